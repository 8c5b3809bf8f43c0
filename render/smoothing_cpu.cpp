#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "render/smoothing.h"
#include "shaders/shared/platform.h"

EK_NAMESPACE_BEGIN

// The shared smoothing code with its one hook: a read of the unsmoothed volume.
struct SmoothingKernelCpu {
    const vec4* source;
    ivec3 res;
    vec4 fetchUnsmoothed(ivec3 v) const {
        return source[(size_t(v.z) * size_t(res.y) + size_t(v.y)) * size_t(res.x) + size_t(v.x)];
    }

#include "shaders/shared/smoothing.h"
};

EK_NAMESPACE_END

namespace eikon {

namespace {

std::vector<glm::vec4> smoothVolume(const std::vector<glm::vec4>& volume, glm::ivec3 res,
                                    bool interiorShortcut) {
    std::vector<glm::vec4> out(volume.size());
    shared::SmoothingKernelCpu kernel{volume.data(), res};
    tbb::parallel_for(tbb::blocked_range<int>(0, res.z), [&](const tbb::blocked_range<int>& r) {
        for (int z = r.begin(); z != r.end(); ++z)
            for (int y = 0; y < res.y; ++y)
                for (int x = 0; x < res.x; ++x) {
                    const glm::ivec3 v(x, y, z);
                    const bool interior = interiorShortcut && x > 0 && y > 0 && z > 0 &&
                                          x < res.x - 1 && y < res.y - 1 && z < res.z - 1;
                    out[(size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) + size_t(x)] =
                        interior ? kernel.smoothedInteriorVoxel(v) : kernel.smoothedVoxel(v, res);
                }
    });
    return out;
}

}  // namespace

std::vector<glm::vec4> smoothVolumeCpu(const std::vector<glm::vec4>& volume, glm::ivec3 res) {
    return smoothVolume(volume, res, true);
}

std::vector<glm::vec4> smoothVolumePerVoxelCpu(const std::vector<glm::vec4>& volume,
                                               glm::ivec3 res) {
    return smoothVolume(volume, res, false);
}

}  // namespace eikon
