#pragma once
// A field resampled onto the dense render volume: what the GPU upload and the CPU twins read.
// Voxel (i, j, k) spans [i, i+1) × [j, j+1) × [k, k+1) in volume index space; its value is the
// field at the voxel's centre.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/bounds.h"

namespace eikon {

// The box the pipeline works in and its resolution.
struct RenderVolume {
    Bounds3 bounds;
    glm::ivec3 resolution{0};

    glm::vec3 voxelSize() const { return bounds.size() / glm::vec3(resolution); }
    std::size_t voxelCount() const {
        return std::size_t(resolution.x) * std::size_t(resolution.y) * std::size_t(resolution.z);
    }
    glm::vec3 voxelCenter(int i, int j, int k) const {
        return bounds.min + (glm::vec3(i, j, k) + 0.5f) * voxelSize();
    }
    bool operator==(const RenderVolume& o) const {
        return bounds.min == o.bounds.min && bounds.max == o.bounds.max &&
               resolution == o.resolution;
    }
    bool operator!=(const RenderVolume& o) const { return !(*this == o); }
};

struct DenseGrid {
    std::string field;
    std::uint64_t version = 0;  // the field's version it was made from (upload skips equal ones)
    RenderVolume volume;
    std::vector<float> values;  // x fastest, then y, then z

    std::size_t index(int i, int j, int k) const {
        return (std::size_t(k) * std::size_t(volume.resolution.y) + std::size_t(j)) *
                   std::size_t(volume.resolution.x) +
               std::size_t(i);
    }
    float at(int i, int j, int k) const { return values[index(i, j, k)]; }
};

}  // namespace eikon
