#include "core/resample.h"

#include <algorithm>
#include <cmath>

#include <openvdb/tools/Interpolation.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.h"

namespace eikon {
namespace {

const Field& materialField(const Scene& scene, const FieldRegistry& fields, size_t m) {
    const MaterialSpec& mat = scene.materials[m];
    const std::string where = scene.path + ":/materials/" + std::to_string(m) + "/field";
    if (!fields.has(mat.field)) {
        std::string have;
        for (const auto& n : fields.names()) have += (have.empty() ? "" : ", ") + n;
        throw Error(where, "material '" + mat.name + "' reads field '" + mat.field +
                               "', which no source provides (fields present: " +
                               (have.empty() ? "none" : have) + ")");
    }
    const Field& f = fields.get(mat.field);
    if (!f.isScalar())
        throw Error(where, "material '" + mat.name + "' reads field '" + mat.field + "', a " +
                               f.grid->valueType() + " grid; materials read float fields");
    return f;
}

}  // namespace

RenderVolume chooseRenderVolume(const Scene& scene, const FieldRegistry& fields) {
    if (scene.materials.empty()) throw Error(scene.path, "the scene has no material");
    RenderVolume v;
    if (scene.volume.autoBounds) {
        for (size_t m = 0; m < scene.materials.size(); ++m)
            v.bounds = v.bounds.unite(materialField(scene, fields, m).activeWorldBounds());
        if (!v.bounds.valid())
            throw Error(scene.path + ":/volume/bounds",
                        "\"auto\" bounds are empty: the material fields have no active voxels");
    } else {
        v.bounds = scene.volume.bounds;
    }
    if (scene.volume.autoResolution) {
        const Field& first = materialField(scene, fields, 0);
        const openvdb::Vec3d vs = first.grid->voxelSize();
        float voxel = float(std::min({vs.x(), vs.y(), vs.z()}));
        const glm::vec3 size = v.bounds.size();
        const float longest = std::max({size.x, size.y, size.z});
        voxel = std::max(voxel, longest / float(scene.volume.maxResolution));
        v.resolution = glm::max(glm::ivec3(1), glm::ivec3(glm::round(size / voxel)));
        v.resolution = glm::min(v.resolution, glm::ivec3(scene.volume.maxResolution));
    } else {
        v.resolution = scene.volume.resolution;
    }
    return v;
}

DenseGrid resampleToDense(const Field& field, const RenderVolume& volume) {
    if (!field.isScalar())
        throw Error(field.origin, "field '" + field.name + "' is not a float grid");
    const auto grid = openvdb::gridConstPtrCast<openvdb::FloatGrid>(field.grid);
    DenseGrid out;
    out.field = field.name;
    out.version = field.version;
    out.volume = volume;
    out.values.assign(volume.voxelCount(), 0.0f);
    const glm::ivec3 res = volume.resolution;

    tbb::parallel_for(tbb::blocked_range<int>(0, res.z), [&](const tbb::blocked_range<int>& r) {
        auto acc = grid->getConstAccessor();
        const openvdb::math::Transform& xform = grid->transform();
        for (int k = r.begin(); k != r.end(); ++k)
            for (int j = 0; j < res.y; ++j)
                for (int i = 0; i < res.x; ++i) {
                    const glm::vec3 w = volume.voxelCenter(i, j, k);
                    const openvdb::Vec3d ijk = xform.worldToIndex(openvdb::Vec3d(w.x, w.y, w.z));
                    out.values[out.index(i, j, k)] = openvdb::tools::BoxSampler::sample(acc, ijk);
                }
    });
    return out;
}

}  // namespace eikon
