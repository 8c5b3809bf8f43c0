#include "core/resample.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <openvdb/tools/Interpolation.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "core/error.h"
#include "core/memory_limit.h"
#include "core/transfer_function.h"

namespace eikon {
namespace {

const Field& materialField(const Scene& scene, const FieldRegistry& fields, size_t m) {
    const MaterialSpec& mat = scene.materials[m];
    const std::string where = scene.path + ":/materials/" + std::to_string(m) + "/field";
    if (!fields.has(mat.field))
        throw Error(where, "material '" + mat.name + "' reads field '" + mat.field +
                               "', which no source provides " + fields.presentText());
    const Field& f = fields.get(mat.field);
    if (!f.isScalar())
        throw Error(where, "material '" + mat.name + "' reads field '" + mat.field + "', a " +
                               f.grid->valueType() + " grid; materials read float fields");
    return f;
}

}  // namespace

namespace {

// The widest margin a mesh's blurred index needs around the mesh, in voxels.
int meshMarginVoxels(const Scene& scene) {
    int margin = 0;
    for (const MeshObjectSpec& m : scene.meshes) margin = std::max(margin, m.blurRadiusVoxels + 2);
    return margin;
}

float longestAxis(const Bounds3& b) {
    const glm::vec3 size = b.size();
    return std::max({size.x, size.y, size.z});
}

}  // namespace

RenderVolume chooseRenderVolume(const Scene& scene, const FieldRegistry& fields,
                                const std::vector<Bounds3>& meshBounds) {
    if (scene.materials.empty()) throw Error(scene.path, "the scene has no material");
    if (meshBounds.size() != scene.meshes.size())
        throw Error(scene.path, "the render volume needs the bounds of every mesh (" +
                                    std::to_string(meshBounds.size()) + " of " +
                                    std::to_string(scene.meshes.size()) + " given)");
    std::vector<size_t> fieldMaterials;  // materials reading fields that sources write
    for (size_t m = 0; m < scene.materials.size(); ++m)
        if (meshOfField(scene, scene.materials[m].field) < 0) fieldMaterials.push_back(m);
    Bounds3 meshes;
    for (const Bounds3& b : meshBounds) meshes = meshes.unite(b);
    const float margin = float(meshMarginVoxels(scene));

    RenderVolume v;
    if (scene.volume.autoBounds) {
        // A live simulation starts empty and spreads: its whole domains, so the volume holds still.
        for (const SourceSpec& source : scene.sources)
            if (source.type == SourceType::Simulation)
                for (const SmokeSimulationSpec& simulation : scene.simulations)
                    v.bounds = v.bounds.unite(simulation.domain);
        for (size_t m : fieldMaterials)
            v.bounds = v.bounds.unite(materialField(scene, fields, m).activeWorldBounds());
        if (!v.bounds.valid() && !meshes.valid())
            throw Error(scene.path + ":/volume/bounds",
                        "\"auto\" bounds are empty: the material fields have no active voxels");
    } else {
        v.bounds = scene.volume.bounds;
    }
    if (scene.volume.autoResolution) {
        float voxel = 0.0f;
        if (!fieldMaterials.empty()) {
            const openvdb::Vec3d vs =
                materialField(scene, fields, fieldMaterials[0]).grid->voxelSize();
            voxel = float(std::min({vs.x(), vs.y(), vs.z()}));
        } else {
            // Meshes alone: N voxels along the longest axis, margins included.
            const float n = float(std::min(scene.volume.maxResolution, kMeshVoxelsAcross));
            voxel = scene.volume.autoBounds
                        ? longestAxis(meshes) / std::max(1.0f, n - 2.0f * margin)
                        : longestAxis(v.bounds) / n;
        }
        if (scene.volume.autoBounds && meshes.valid())
            v.bounds = v.bounds.unite({meshes.min - margin * voxel, meshes.max + margin * voxel});
        const glm::vec3 size = v.bounds.size();
        voxel = std::max(voxel, longestAxis(v.bounds) / float(scene.volume.maxResolution));
        v.resolution = glm::max(glm::ivec3(1), glm::ivec3(glm::round(size / voxel)));
        v.resolution = glm::min(v.resolution, glm::ivec3(scene.volume.maxResolution));
    } else {
        v.resolution = scene.volume.resolution;
        if (scene.volume.autoBounds && meshes.valid()) {
            // Grown so that the margin is `margin` voxels of the grown volume:
            // L' = L + 2·margin·L'/N per axis.
            const glm::vec3 n(v.resolution);
            const Bounds3 all = v.bounds.unite(meshes);
            const glm::vec3 grown =
                all.size() / glm::max(glm::vec3(1e-6f), 1.0f - 2.0f * margin / n);
            const glm::vec3 pad = 0.5f * (grown - all.size());
            v.bounds = v.bounds.unite({meshes.min - pad, meshes.max + pad});
        }
    }
    if (scene.volume.autoResolution) {  // a fixed one was checked with the scene
        const glm::ivec3 n = v.resolution;
        checkMemory(scene.path + ":/volume/max_resolution",
                    renderVolumeBytes(double(n.x) * double(n.y) * double(n.z)),
                    "the \"auto\" render volume of " + std::to_string(n.x) + "×" +
                        std::to_string(n.y) + "×" + std::to_string(n.z) + " voxels",
                    "lower volume.max_resolution or set volume.resolution");
    }
    return v;
}

namespace {

using FloatAccessor = openvdb::FloatGrid::ConstAccessor;

// A box [lo, lo + size) of a float grid's voxels held densely, for the box samples of one slab of
// the render volume: BoxSampler::sample looks up its eight values in the tree (eight accessor
// calls a render voxel), where each voxel of the box is looked up once here (the smoke's resample
// stage 127 -> 90 ms on one core). The values are the accessor's, and the interpolation is
// BoxSampler's own, so every sample is BoxSampler::sample's to the bit.
class DenseIndexBox {
public:
    // Copies the voxels of [lo, hi] (inclusive); false, with nothing copied, where that is more
    // than maxVoxels (a render volume coarser than the grid reads far fewer of them).
    bool copy(FloatAccessor& acc, const openvdb::Coord& lo, const openvdb::Coord& hi,
              size_t maxVoxels) {
        const openvdb::Coord size = hi - lo + openvdb::Coord(1);
        if (size.x() <= 0 || size.y() <= 0 || size.z() <= 0) return false;
        const size_t count = size_t(size.x()) * size_t(size.y()) * size_t(size.z());
        if (count > maxVoxels) return false;
        lo_ = lo;
        size_ = size;
        values_.resize(count);
        size_t i = 0;
        for (int z = lo.z(); z <= hi.z(); ++z)
            for (int y = lo.y(); y <= hi.y(); ++y)
                for (int x = lo.x(); x <= hi.x(); ++x)
                    values_[i++] = acc.getValue(openvdb::Coord(x, y, z));
        return true;
    }

    // BoxSampler::sample(acc, ijk): its eight values from the box where they lie in it, else from
    // the accessor.
    float sample(FloatAccessor& acc, const openvdb::Vec3d& ijk) const {
        const openvdb::Vec3i i0 = openvdb::tools::local_util::floorVec3(ijk);
        const openvdb::Vec3d uvw = ijk - i0;
        float data[2][2][2];
        const openvdb::Coord at = openvdb::Coord(i0) - lo_;
        if (!values_.empty() && at.x() >= 0 && at.y() >= 0 && at.z() >= 0 &&
            at.x() + 1 < size_.x() && at.y() + 1 < size_.y() && at.z() + 1 < size_.z()) {
            const size_t row = size_t(size_.x());
            const size_t plane = row * size_t(size_.y());
            const float* v =
                values_.data() + size_t(at.z()) * plane + size_t(at.y()) * row + size_t(at.x());
            for (int dx = 0; dx < 2; ++dx)
                for (int dy = 0; dy < 2; ++dy)
                    for (int dz = 0; dz < 2; ++dz)
                        data[dx][dy][dz] = v[size_t(dz) * plane + size_t(dy) * row + size_t(dx)];
        } else {
            openvdb::tools::BoxSampler::getValues(data, acc, openvdb::Coord(i0));
        }
        return openvdb::tools::BoxSampler::trilinearInterpolation(data, uvw);
    }

private:
    openvdb::Coord lo_, size_;
    std::vector<float> values_;
};

// The box of grid voxels that the samples of render-volume planes [k0, k1) read, for a linear
// transform: the bounds of the index positions of the slab's eight corner voxel centres (an
// affine map's image of a box lies within them), widened by a voxel for rounding and by one more
// at the top for each sample's upper neighbours. Samples outside it still read the accessor.
void slabIndexBox(const openvdb::math::Transform& xform, const RenderVolume& volume, int k0, int k1,
                  openvdb::Coord& lo, openvdb::Coord& hi) {
    const glm::ivec3 res = volume.resolution;
    openvdb::Vec3d mn(std::numeric_limits<double>::max());
    openvdb::Vec3d mx(-std::numeric_limits<double>::max());
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 w = volume.voxelCenter((c & 1) ? res.x - 1 : 0, (c & 2) ? res.y - 1 : 0,
                                               (c & 4) ? k1 - 1 : k0);
        const openvdb::Vec3d ijk = xform.worldToIndex(openvdb::Vec3d(w.x, w.y, w.z));
        mn = openvdb::math::minComponent(mn, ijk);
        mx = openvdb::math::maxComponent(mx, ijk);
    }
    // Clamped so that a far-off transform cannot overflow the coordinates (its box is then too
    // large, and the slab reads the accessor).
    const auto toCoord = [](const openvdb::Vec3d& v, int add) {
        const auto c = [add](double x) {
            return int(std::clamp(std::floor(x), -1.0e9, 1.0e9)) + add;
        };
        return openvdb::Coord(c(v.x()), c(v.y()), c(v.z()));
    };
    lo = toCoord(mn, -1);
    hi = toCoord(mx, 2);
}

}  // namespace

namespace {

// What every slab of one resampling reads and where it writes (resampleToDense).
struct ResampleJob {
    const openvdb::FloatGrid& grid;
    const RenderVolume& volume;
    // Transform::worldToIndex calls its map through a virtual function; a scale-and-translate map
    // (what OpenVDB, Houdini and Blender write) is called directly, the same function inlined.
    const openvdb::math::ScaleTranslateMap* direct;
    // voxelCenter's voxel size and origin, once: the same floats, where the loop would take its
    // divisions for every voxel (the compiler cannot tell that the stores leave `volume` alone).
    glm::vec3 voxel;
    glm::vec3 origin;
    float* values;
};

// Render-volume planes [k0, k1) of the job, with the box of grid voxels they read (a frustum
// transform's slabs read the accessor alone). Returns whether a sample was NaN or infinite.
[[gnu::always_inline]] inline bool resampleSlab(const ResampleJob& job, int k0, int k1) {
    const openvdb::math::Transform& xform = job.grid.transform();
    const glm::ivec3 res = job.volume.resolution;
    auto acc = job.grid.getConstAccessor();
    DenseIndexBox box;
    if (xform.isLinear()) {
        openvdb::Coord lo, hi;
        slabIndexBox(xform, job.volume, k0, k1, lo, hi);
        const size_t slabVoxels = size_t(res.x) * size_t(res.y) * size_t(k1 - k0);
        box.copy(acc, lo, hi, 4 * slabVoxels + 4096);
    }
    bool anyNonFinite = false;
    for (int k = k0; k != k1; ++k)
        for (int j = 0; j < res.y; ++j)
            for (int i = 0; i < res.x; ++i) {
                const glm::vec3 w = job.origin + (glm::vec3(i, j, k) + 0.5f) * job.voxel;
                const openvdb::Vec3d world(w.x, w.y, w.z);
                const openvdb::Vec3d ijk =
                    job.direct
                        ? job.direct->openvdb::math::ScaleTranslateMap::applyInverseMap(world)
                        : xform.worldToIndex(world);
                const float v = box.sample(acc, ijk);
                anyNonFinite = anyNonFinite || !std::isfinite(v);
                job.values[(size_t(k) * size_t(res.y) + size_t(j)) * size_t(res.x) + size_t(i)] = v;
            }
    return anyNonFinite;
}

bool resampleSlabBaseline(const ResampleJob& job, int k0, int k1) {
    return resampleSlab(job, k0, k1);
}

// The same loop compiled for AVX2, as the view's (render/view_pass_cpu.cpp): SSE4.1's roundsd
// takes the floors that baseline x86-64 computes with masks and compares, and VEX's three
// operands save moves. No FMA is enabled, so every operation rounds as in the baseline copy
// (tests/core/test_resample.cpp holds both to BoxSampler::sample by memcmp). The smoke's resample
// stage took 52.6 -> 42.1 ms on two cores (BENCHMARKS.md). Not under the sanitizers, as the view.
#if defined(__x86_64__) && defined(__GNUC__) && defined(__OPTIMIZE__) && \
    !defined(__SANITIZE_ADDRESS__)
#define EK_RESAMPLE_AVX2 1
[[gnu::target("avx2"), gnu::flatten]] bool resampleSlabAvx2(const ResampleJob& job, int k0,
                                                            int k1) {
    return resampleSlab(job, k0, k1);
}
#endif

}  // namespace

bool resampleRunsAvx2() {
#ifdef EK_RESAMPLE_AVX2
    const char* env = std::getenv("EIKON_CPU_AVX2");
    return !(env && std::string(env) == "0") && __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

DenseGrid resampleToDense(const Field& field, const RenderVolume& volume, ResampleCopy copy) {
    if (!field.isScalar())
        throw Error(field.origin, "field '" + field.name + "' is not a float grid");
    const auto grid = openvdb::gridConstPtrCast<openvdb::FloatGrid>(field.grid);
    DenseGrid out;
    out.field = field.name;
    out.version = field.version;
    out.volume = volume;
    out.values.assign(volume.voxelCount(), 0.0f);
    const glm::ivec3 res = volume.resolution;
    std::atomic<bool> nonFinite{false};
    const openvdb::math::Transform& xform = grid->transform();
    auto scaleTranslate = xform.constMap<openvdb::math::ScaleTranslateMap>();
    const auto uniform = xform.constMap<openvdb::math::UniformScaleTranslateMap>();
    const ResampleJob job{*grid,
                          volume,
                          scaleTranslate ? scaleTranslate.get() : uniform.get(),
                          volume.voxelSize(),
                          volume.bounds.min,
                          out.values.data()};
    const bool avx2 = copy == ResampleCopy::Auto && resampleRunsAvx2();
    // In slabs of 4-8 planes, each with the box of grid voxels it reads.
    tbb::parallel_for(
        tbb::blocked_range<int>(0, res.z, 8),
        [&](const tbb::blocked_range<int>& r) {
#ifdef EK_RESAMPLE_AVX2
            if (avx2 ? resampleSlabAvx2(job, r.begin(), r.end())
                     : resampleSlabBaseline(job, r.begin(), r.end()))
                nonFinite = true;
#else
            (void)avx2;
            if (resampleSlabBaseline(job, r.begin(), r.end())) nonFinite = true;
#endif
        },
        tbb::simple_partitioner());
    if (nonFinite) {
        const auto count = std::count_if(out.values.begin(), out.values.end(),
                                         [](float v) { return !std::isfinite(v); });
        throw Error(field.origin, "field '" + field.name + "' has NaN/Inf values (" +
                                      std::to_string(count) + " of the render volume's " +
                                      std::to_string(out.values.size()) + " voxels)");
    }
    return out;
}

namespace {

// Where voxel v of the volume lies, for messages.
std::string voxelPosition(const RenderVolume& volume, size_t v) {
    const glm::ivec3 res = volume.resolution;
    const int i = int(v % size_t(res.x));
    const int j = int((v / size_t(res.x)) % size_t(res.y));
    const int k = int(v / (size_t(res.x) * size_t(res.y)));
    const glm::vec3 p = volume.voxelCenter(i, j, k);
    std::ostringstream out;
    out << std::setprecision(4) << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    return out.str();
}

const DenseGrid& denseFor(const Scene& scene, const std::map<std::string, DenseGrid>& dense,
                          size_t m) {
    auto it = dense.find(materialSlotName(scene.materials[m]));
    if (it == dense.end())
        throw Error(scene.path + ":/materials/" + std::to_string(m) + "/field",
                    "field '" + scene.materials[m].field + "' was not resampled");
    return it->second;
}

// A Gladstone–Dale material's field is a temperature excess over ambient: at or below
// −ambientKelvin it would be at or below absolute zero, where n − 1 ∝ 1/T has no meaning (and
// shaders/shared/material_index.h would divide by zero or flip sign).
void checkAboveAbsoluteZero(const Scene& scene, const FieldRegistry& fields, const DenseGrid& grid,
                            size_t m) {
    const MaterialSpec& mat = scene.materials[m];
    const float floor = -mat.ambientKelvin;
    // The first offending voxel in index order, whatever the thread count.
    const size_t count = grid.values.size();
    const size_t bad = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, count), count,
        [&](const tbb::blocked_range<size_t>& r, size_t first) {
            for (size_t v = r.begin(); v != r.end() && v < first; ++v)
                if (!(grid.values[v] > floor)) return v;
            return first;
        },
        [](size_t a, size_t b) { return std::min(a, b); });
    if (bad == count) return;
    std::ostringstream reason;
    reason << std::setprecision(7);
    reason << "material '" << mat.name << "' (gladstone_dale " << mat.gladstoneDale
           << ", ambient_kelvin " << mat.ambientKelvin << ") reads field '" << mat.field << "'";
    if (fields.has(mat.field)) reason << " (from " << fields.get(mat.field).origin << ")";
    reason << " as a temperature excess in kelvin, which is " << grid.values[bad] << " at "
           << voxelPosition(grid.volume, bad) << ": at or below absolute zero (-"
           << mat.ambientKelvin << "), where Gladstone-Dale has no meaning";
    throw Error(scene.path + ":/materials/" + std::to_string(m) + "/field", reason.str());
}

}  // namespace

void checkRefractiveIndex(const Scene& scene, const FieldRegistry& fields,
                          const std::map<std::string, DenseGrid>& dense) {
    // Gladstone–Dale air is lighter than the ambient air where it is hotter, so its n < 1 is
    // meant (n is relative to the ambient air); its own check is the temperature's. The linear
    // materials together must keep n >= 1.
    std::vector<size_t> refracting;  // linear materials with ior != 1
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        const MaterialSpec& mat = scene.materials[m];
        if (mat.gladstoneDale > 0.0f)
            checkAboveAbsoluteZero(scene, fields, denseFor(scene, dense, m), m);
        else if (mat.ior != 1.0f)
            refracting.push_back(m);
    }
    if (refracting.empty()) return;
    std::vector<const DenseGrid*> grids;
    for (size_t m : refracting) grids.push_back(&denseFor(scene, dense, m));
    auto indexAt = [&](size_t v) {
        float n = 1.0f;  // summed as shaders/shared/refraction.h sums it
        for (size_t r = 0; r < refracting.size(); ++r)
            n += grids[r]->values[v] * (scene.materials[refracting[r]].ior - 1.0f);
        return n;
    };
    // The lowest n (the first such voxel on ties, whatever the thread count), and how many
    // voxels are below 1.
    struct Lowest {
        float n = 1.0f;  // NaN counts as −∞
        size_t voxel = std::numeric_limits<size_t>::max();
        size_t below = 0;
        bool before(float n2, size_t v2) const { return n2 < n || (n2 == n && v2 < voxel); }
    };
    const size_t count = grids[0]->values.size();
    const Lowest lowest = tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, count), Lowest{},
        [&](const tbb::blocked_range<size_t>& r, Lowest acc) {
            for (size_t v = r.begin(); v != r.end(); ++v) {
                float n = indexAt(v);
                if (n >= 1.0f) continue;
                if (std::isnan(n)) n = -std::numeric_limits<float>::infinity();
                ++acc.below;
                if (acc.before(n, v)) acc.n = n, acc.voxel = v;
            }
            return acc;
        },
        [](Lowest a, const Lowest& b) {
            if (a.before(b.n, b.voxel)) a.n = b.n, a.voxel = b.voxel;
            a.below += b.below;
            return a;
        });
    if (lowest.below == 0) return;
    const size_t bad = lowest.voxel;

    // Blame the material whose field pulls n down most there.
    size_t worst = 0;
    for (size_t r = 1; r < refracting.size(); ++r) {
        const auto pull = [&](size_t q) {
            return grids[q]->values[bad] * (scene.materials[refracting[q]].ior - 1.0f);
        };
        if (pull(r) < pull(worst)) worst = r;
    }
    const size_t m = refracting[worst];
    const MaterialSpec& mat = scene.materials[m];
    std::ostringstream reason;
    reason << std::setprecision(7);
    reason << "material '" << mat.name << "' (ior " << mat.ior << ") reads field '" << mat.field
           << "'";
    if (fields.has(mat.field)) reason << " (from " << fields.get(mat.field).origin << ")";
    reason << ", which is " << grids[worst]->values[bad] << " at "
           << voxelPosition(grids[worst]->volume, bad)
           << ": the materials make n = " << indexAt(bad) << " there (the lowest; n < 1 in "
           << lowest.below << " voxels), and n must be >= 1 (a field that a refracting material "
           << "reads must not be negative)";
    throw Error(scene.path + ":/materials/" + std::to_string(m) + "/field", reason.str());
}

}  // namespace eikon
