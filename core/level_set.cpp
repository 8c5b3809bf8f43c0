#include "core/level_set.h"

#include <algorithm>
#include <cmath>

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/error.h"
#include "core/file_kind.h"
#include "core/nanovdb_reader.h"
#include "core/printable.h"
#include "core/vdb_import.h"
#include "core/vdb_reader.h"
#include "core/world_box.h"

namespace eikon {

struct LevelSet::Impl {
    openvdb::FloatGrid::Ptr grid;
    std::string label;
    Bounds3 bounds;
    float voxel = 0.0f;  // the grid's smallest voxel edge, in its world units
};

namespace {

// One grid of the file as the choice sees it: its name, class and value type, and the grid
// itself when it is a float or double one (null otherwise).
struct Candidate {
    std::string name;
    std::string gridClass;  // "level set", "fog volume", "staggered", "unknown"
    std::string valueType;
    openvdb::GridBase::Ptr grid;
};

std::string labelOf(const std::vector<Candidate>& all, size_t i) {
    return all[i].name.empty()
               ? "unnamed grid " + std::to_string(i)
               : "'" + printable(all[i].name) + "' (grid " + std::to_string(i) + ")";
}

std::string listOf(const std::vector<Candidate>& all) {
    std::string out;
    for (size_t i = 0; i < all.size(); ++i)
        out += (i ? "; " : "") + labelOf(all, i) + ": " + all[i].gridClass + " " + all[i].valueType;
    return out;
}

bool isScalar(const openvdb::GridBase::Ptr& g) {
    return g && (g->isType<openvdb::FloatGrid>() || g->isType<openvdb::DoubleGrid>());
}

std::vector<Candidate> readCandidates(const std::string& path) {
    ensureOpenVdbInitialized();
    std::vector<Candidate> out;
    if (sniffFileKind(path) == FileKind::NanoVdb) {
        for (const NanoVdbGrid& g : readNanoVdb(path)) {
            Candidate c{g.name, "unknown", g.type, nullptr};
            if (g.grid) c.gridClass = openvdb::GridBase::gridClassToString(g.grid->getGridClass());
            if (isScalar(g.grid)) c.grid = g.grid;
            out.push_back(std::move(c));
        }
        return out;
    }
    VdbReader reader(path);
    for (size_t i = 0; i < reader.entries().size(); ++i) {
        const VdbReader::Entry& e = reader.entries()[i];
        Candidate c{e.name, "unknown", e.type, nullptr};
        if (e.registered) {
            c.valueType = openvdb::GridBase::createGrid(e.type)->valueType();
            if (c.valueType == "float" || c.valueType == "double") {
                try {
                    c.grid = reader.readGrid(i);
                    c.gridClass = openvdb::GridBase::gridClassToString(c.grid->getGridClass());
                } catch (const UnsupportedGridError&) {
                    c.grid = nullptr;
                }
            }
        }
        out.push_back(std::move(c));
    }
    return out;
}

const std::string kHowToChoose = "\"grid\" in a scene's mesh, --grid on the command line";

size_t choose(const std::string& path, const std::vector<Candidate>& all,
              const GridChoice& choice) {
    if (all.empty()) throw Error(path, "holds no grids");
    if (choice.index >= 0) {
        if (size_t(choice.index) >= all.size())
            throw Error(path, "has " + std::to_string(all.size()) + " grid" +
                                  (all.size() == 1 ? "" : "s") + " (index 0-" +
                                  std::to_string(all.size() - 1) + "), no grid " +
                                  std::to_string(choice.index) + " (grids: " + listOf(all) + ")");
        return size_t(choice.index);
    }
    if (!choice.name.empty()) {
        for (size_t i = 0; i < all.size(); ++i)
            if (all[i].name == choice.name) return i;
        throw Error(path,
                    "no grid named '" + printable(choice.name) + "' (grids: " + listOf(all) + ")");
    }
    std::vector<size_t> levelSets;
    for (size_t i = 0; i < all.size(); ++i)
        if (all[i].gridClass == "level set") levelSets.push_back(i);
    if (levelSets.size() == 1) return levelSets.front();
    if (levelSets.empty())
        throw Error(path, "holds no level set (grids: " + listOf(all) +
                              "); choose a signed-distance grid by its name or index (" +
                              kHowToChoose + ")");
    throw Error(path, "holds " + std::to_string(levelSets.size()) +
                          " level sets (grids: " + listOf(all) +
                          "); choose one by its name or index (" + kHowToChoose + ")");
}

openvdb::FloatGrid::Ptr asFloat(const openvdb::GridBase::Ptr& g) {
    if (auto f = openvdb::gridPtrCast<openvdb::FloatGrid>(g)) return f->deepCopy();
    const auto d = openvdb::gridPtrCast<openvdb::DoubleGrid>(g);
    // Tree's converting copy: the same topology and tiles, each value cast.
    auto tree = std::make_shared<openvdb::FloatTree>(d->tree());
    auto out = openvdb::FloatGrid::create(tree);
    out->setTransform(d->transform().copy());
    out->setGridClass(d->getGridClass());
    return out;
}

// The box around the voxels below zero, one voxel wider: the zero crossing of the trilinear
// field lies within a voxel of them. Inactive interior tiles lie within the band around them.
bool insideBox(const openvdb::FloatGrid& grid, openvdb::CoordBBox& box) {
    bool any = false;
    for (auto it = grid.cbeginValueOn(); it; ++it)
        if (*it < 0.0f) {
            box.expand(it.getBoundingBox());
            any = true;
        }
    box.expand(1);
    return any;
}

glm::vec3 toGlm(const openvdb::Vec3d& v) {
    return {float(v.x()), float(v.y()), float(v.z())};
}

// The signed distance at world points of a placed level set: one per thread (the accessor
// caches nodes and is not shared).
class PlacedSampler {
public:
    PlacedSampler(const openvdb::FloatGrid& grid, const MeshObjectSpec& placement)
        : accessor_(grid.getConstAccessor()),
          sampler_(accessor_, grid.transform()),
          placement_(placement),
          inverse_(glm::conjugate(placement.rotation)) {}

    float operator()(glm::vec3 world) const {
        const glm::vec3 p = (inverse_ * (world - placement_.translation)) / placement_.scale;
        return sampler_.wsSample(openvdb::Vec3d(p.x, p.y, p.z));
    }

private:
    openvdb::FloatGrid::ConstAccessor accessor_;
    openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler>
        sampler_;
    const MeshObjectSpec& placement_;
    glm::quat inverse_;
};

// The fraction of the unit cube where m·u < alpha, for m ≥ 0 (Scardovelli & Zaleski 2000: the
// corner tetrahedron less the parts past each face): exact for a plane. Each m is kept at least
// 1e-4 of their sum so that the division by their product stays well conditioned in double.
double cubeFractionBelow(glm::dvec3 m, double alphaAtCentre) {  // m·u < m·½ + alphaAtCentre
    const double floor = 1e-4 * (m.x + m.y + m.z);
    m = glm::max(m, glm::dvec3(floor));
    const double sum = m.x + m.y + m.z;
    double alpha = 0.5 * sum + alphaAtCentre;
    if (alpha <= 0.0) return 0.0;
    if (alpha >= sum) return 1.0;
    // The fraction is symmetric about the centre; the smaller side has fewer cancelling terms.
    const bool mirrored = alpha > 0.5 * sum;
    if (mirrored) alpha = sum - alpha;
    auto cube = [](double x) { return x > 0.0 ? x * x * x : 0.0; };
    const double v = (cube(alpha) - cube(alpha - m.x) - cube(alpha - m.y) - cube(alpha - m.z) +
                      cube(alpha - m.x - m.y) + cube(alpha - m.y - m.z) + cube(alpha - m.x - m.z)) /
                     (6.0 * m.x * m.y * m.z);
    return mirrored ? 1.0 - v : v;
}

// The fraction of the box of size `size` centred on `centre` below the zero crossing, taken as
// the plane at distance φ/|∇φ| along ∇φ/|∇φ| (the gradient by central differences across the
// box). `margin`: the world distance beyond which the box is wholly in or out.
float boxCoverage(const PlacedSampler& phi, glm::vec3 centre, glm::vec3 size, float minScale,
                  float margin) {
    const float f = phi(centre);
    if (std::abs(f) * minScale >= margin) return f < 0.0f ? 1.0f : 0.0f;
    glm::dvec3 g;
    for (int a = 0; a < 3; ++a) {
        glm::vec3 step(0.0f);
        step[a] = 0.5f * size[a];
        g[a] = double(phi(centre + step) - phi(centre - step)) / double(size[a]);
    }
    const double length = glm::length(g);
    if (!(length > 0.0)) return f < 0.0f ? 1.0f : 0.0f;  // a flat field: past the band
    // Inside where n·(x − centre) < −d; in the box's unit coordinates, with each axis turned so
    // that its component is positive: m·u < ½Σm − d.
    const glm::dvec3 m = glm::abs(g / length) * glm::dvec3(size);
    return float(cubeFractionBelow(m, -double(f) / length));
}

}  // namespace

LevelSet LevelSet::read(const std::string& path, const GridChoice& choice) {
    const std::vector<Candidate> all = readCandidates(path);
    const size_t i = choose(path, all, choice);
    const std::string label = labelOf(all, i);
    if (!all[i].grid)
        throw Error(path, label + " is " + all[i].valueType +
                              ", not a signed distance (a float or double grid)");
    auto impl = std::make_shared<Impl>();
    impl->label = label;
    impl->grid = asFloat(all[i].grid);
    openvdb::FloatGrid& grid = *impl->grid;
    std::size_t nonFinite = 0;
    for (auto it = grid.cbeginValueOn(); it; ++it)
        if (!std::isfinite(*it)) ++nonFinite;
    if (nonFinite > 0 || !std::isfinite(grid.background()))
        throw Error(path,
                    label + " has " + std::to_string(nonFinite) + " NaN/Inf values" +
                        (std::isfinite(grid.background()) ? "" : " and a NaN/Inf background"));
    // The band's inside tiles negative, as OpenVDB's tools leave them; a writer that did not flood
    // its SDF would otherwise leave the solid hollow.
    openvdb::tools::signedFloodFill(grid.tree());
    openvdb::CoordBBox box;
    if (!insideBox(grid, box))
        throw Error(path, label + " has no value below zero: nothing is inside it" +
                              (all[i].gridClass == "level set"
                                   ? std::string("")
                                   : " (a " + all[i].gridClass + ", not a signed distance)"));
    const openvdb::BBoxd world = worldBoxOf(grid.transform(), box);
    impl->bounds = Bounds3{toGlm(world.min()), toGlm(world.max())};
    const openvdb::Vec3d vs = grid.voxelSize();
    impl->voxel = float(std::min({vs.x(), vs.y(), vs.z()}));
    if (!(impl->voxel > 0.0f) || !impl->bounds.valid())
        throw Error(path, label + " has a degenerate transform (voxel size " +
                              std::to_string(impl->voxel) + ")");
    LevelSet out;
    out.impl_ = std::move(impl);
    return out;
}

const std::string& LevelSet::label() const {
    return impl_->label;
}

Bounds3 LevelSet::bounds() const {
    return impl_->bounds;
}

std::vector<float> LevelSet::coverage(const RenderVolume& volume,
                                      const MeshObjectSpec& placement) const {
    std::vector<float> out(volume.voxelCount(), 0.0f);
    const glm::vec3 h = volume.voxelSize();
    const glm::vec3 s = placement.scale;
    const float minScale = std::min({s.x, s.y, s.z});
    const float gridVoxel = impl_->voxel * minScale;  // in the world
    // Sub-boxes no wider than the level set's voxels, at most 4 per axis.
    const float widest = std::max({h.x, h.y, h.z});
    const int sub = std::clamp(int(std::ceil(widest / gridVoxel)), 1, 4);
    const glm::vec3 subSize = h / float(sub);
    // Past half its diagonal (and one voxel of the level set, for the trilinear field's own
    // slope) a box is wholly on one side.
    const float margin = 0.5f * glm::length(h) + gridVoxel;
    const float subMargin = 0.5f * glm::length(subSize) + gridVoxel;
    const glm::ivec3 r = volume.resolution;
    tbb::parallel_for(tbb::blocked_range<int>(0, r.z), [&](const tbb::blocked_range<int>& range) {
        const PlacedSampler phi(*impl_->grid, placement);
        for (int k = range.begin(); k < range.end(); ++k)
            for (int j = 0; j < r.y; ++j)
                for (int i = 0; i < r.x; ++i) {
                    const glm::vec3 c = volume.voxelCenter(i, j, k);
                    const float f = phi(c);
                    float value;
                    if (std::abs(f) * minScale >= margin) {
                        value = f < 0.0f ? 1.0f : 0.0f;
                    } else {
                        float sum = 0.0f;
                        for (int c3 = 0; c3 < sub; ++c3)
                            for (int c2 = 0; c2 < sub; ++c2)
                                for (int c1 = 0; c1 < sub; ++c1) {
                                    const glm::vec3 offset =
                                        (glm::vec3(c1, c2, c3) + 0.5f) / float(sub) - 0.5f;
                                    sum += boxCoverage(phi, c + offset * h, subSize, minScale,
                                                       subMargin);
                                }
                        value = sum / float(sub * sub * sub);
                    }
                    out[(size_t(k) * size_t(r.y) + size_t(j)) * size_t(r.x) + size_t(i)] = value;
                }
    });
    return out;
}

InsideBits LevelSet::inside(glm::vec3 gridMin, glm::vec3 cellSize, glm::ivec3 resolution,
                            const MeshObjectSpec& placement) const {
    InsideBits bits;
    bits.resolution = resolution;
    bits.wordsPerColumn = (resolution.z + 31) / 32;
    bits.words.assign(size_t(resolution.x) * size_t(resolution.y) * size_t(bits.wordsPerColumn),
                      0u);
    tbb::parallel_for(
        tbb::blocked_range<int>(0, resolution.y), [&](const tbb::blocked_range<int>& range) {
            const PlacedSampler phi(*impl_->grid, placement);
            for (int j = range.begin(); j < range.end(); ++j)
                for (int i = 0; i < resolution.x; ++i) {
                    const size_t column = size_t(j) * size_t(resolution.x) + size_t(i);
                    for (int k = 0; k < resolution.z; ++k) {
                        const glm::vec3 centre = gridMin + (glm::vec3(i, j, k) + 0.5f) * cellSize;
                        if (phi(centre) < 0.0f)
                            bits.words[column * size_t(bits.wordsPerColumn) + size_t(k / 32)] |=
                                1u << (k % 32);
                    }
                }
        });
    return bits;
}

}  // namespace eikon
