#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstdlib>

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

// Four floats in one vector register; aligned as a float, so that a glm::vec4 in memory loads as
// one.
typedef float Lanes4 __attribute__((vector_size(16), aligned(4)));

constexpr int kRun = 4;

// smoothedInteriorVoxel for the kRun voxels from v along x, all of them off the faces: each
// voxel's sum takes its 27 products in smoothedVoxel's order and divides by the same weight sum,
// its four channels in the four lanes of a vector where GLM adds them one by one, and the kRun
// sums are independent chains of adds where one voxel's wait on each other. The same floats
// (tests/render/test_smoothing.cpp holds them to smoothedVoxel by memcmp).
void smoothInteriorRun(const glm::vec4* source, glm::ivec3 res, glm::ivec3 v, glm::vec4* out) {
    Lanes4 sum[kRun] = {};
    float weightSum = 0.0f;
    const size_t row = size_t(res.x);
    const size_t plane = row * size_t(res.y);
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const float w = float((2 - std::abs(dx)) * (2 - std::abs(dy)) * (2 - std::abs(dz)));
                const glm::vec4* tap =
                    source + size_t(v.z + dz) * plane + size_t(v.y + dy) * row + size_t(v.x + dx);
                for (int k = 0; k < kRun; ++k) {
                    Lanes4 value;
                    __builtin_memcpy(&value, tap + k, sizeof(value));
                    sum[k] += w * value;
                }
                weightSum += w;
            }
    for (int k = 0; k < kRun; ++k) {
        const Lanes4 mean = sum[k] / weightSum;
        __builtin_memcpy(out + k, &mean, sizeof(mean));
    }
}

std::vector<glm::vec4> smoothVolume(const std::vector<glm::vec4>& volume, glm::ivec3 res,
                                    bool interiorShortcut) {
    std::vector<glm::vec4> out(volume.size());
    shared::SmoothingKernelCpu kernel{volume.data(), res};
    tbb::parallel_for(tbb::blocked_range<int>(0, res.z), [&](const tbb::blocked_range<int>& r) {
        for (int z = r.begin(); z != r.end(); ++z)
            for (int y = 0; y < res.y; ++y) {
                glm::vec4* target =
                    out.data() + (size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x);
                const bool interiorRow =
                    interiorShortcut && y > 0 && z > 0 && y < res.y - 1 && z < res.z - 1;
                int x = 0;
                if (interiorRow) {
                    target[0] = kernel.smoothedVoxel(glm::ivec3(0, y, z), res);
                    for (x = 1; x + kRun <= res.x - 1; x += kRun)
                        smoothInteriorRun(volume.data(), res, glm::ivec3(x, y, z), target + x);
                    for (; x < res.x - 1; ++x)
                        target[x] = kernel.smoothedInteriorVoxel(glm::ivec3(x, y, z));
                }
                for (; x < res.x; ++x) target[x] = kernel.smoothedVoxel(glm::ivec3(x, y, z), res);
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
