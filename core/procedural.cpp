#include "core/procedural.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace eikon {
namespace {

openvdb::math::Transform::Ptr cellAlignedTransform(float h) {
    auto xform = openvdb::math::Transform::createLinearTransform(double(h));
    xform->postTranslate(openvdb::Vec3d(0.5 * h));
    return xform;
}

// Fills the voxels whose centres lie within `reach` of the shape with value·ramp(distance).
template <typename SignedDistance>
openvdb::FloatGrid::Ptr rasterize(glm::vec3 lo, glm::vec3 hi, float value, float falloff, float h,
                                  SignedDistance distance) {
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setTransform(cellAlignedTransform(h));
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    auto acc = grid->getAccessor();
    const glm::ivec3 i0 = glm::ivec3(glm::floor((lo - falloff) / h)) - 1;
    const glm::ivec3 i1 = glm::ivec3(glm::ceil((hi + falloff) / h)) + 1;
    for (int k = i0.z; k <= i1.z; ++k)
        for (int j = i0.y; j <= i1.y; ++j)
            for (int i = i0.x; i <= i1.x; ++i) {
                const glm::vec3 p = (glm::vec3(i, j, k) + 0.5f) * h;
                const float d = distance(p);
                float v = 0.0f;
                if (d <= 0.0f)
                    v = value;
                else if (d < falloff)
                    v = value * (1.0f - d / falloff);
                if (v != 0.0f) acc.setValue(openvdb::Coord(i, j, k), v);
            }
    return grid;
}

}  // namespace

openvdb::FloatGrid::Ptr makeSphereField(glm::vec3 center, float radius, float value, float falloff,
                                        float voxelSize) {
    return rasterize(center - radius, center + radius, value, falloff, voxelSize,
                     [&](glm::vec3 p) { return glm::length(p - center) - radius; });
}

openvdb::FloatGrid::Ptr makeBoxField(glm::vec3 boxMin, glm::vec3 boxMax, float value, float falloff,
                                     float voxelSize) {
    const glm::vec3 c = 0.5f * (boxMin + boxMax);
    const glm::vec3 halfSize = 0.5f * (boxMax - boxMin);
    return rasterize(boxMin, boxMax, value, falloff, voxelSize, [&](glm::vec3 p) {
        const glm::vec3 q = glm::abs(p - c) - halfSize;
        return glm::length(glm::max(q, 0.0f)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
    });
}

}  // namespace eikon
