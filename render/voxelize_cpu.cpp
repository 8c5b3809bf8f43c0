// The CPU twin of the blur; the CPU voxelizer itself is core's (core/mesh_voxelize.h), shared
// with the smoke solver's mesh obstacles.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "render/voxelize.h"
#include "shaders/shared/platform.h"

EK_NAMESPACE_BEGIN

struct BlurKernelCpu {
    const float* source;
    ivec3 res;
    float fetchUnblurred(ivec3 v) const {
        return source[(size_t(v.z) * size_t(res.y) + size_t(v.y)) * size_t(res.x) + size_t(v.x)];
    }

#include "shaders/shared/gaussian_blur.h"
};

EK_NAMESPACE_END

namespace eikon {

std::vector<float> blurCoverageCpu(const std::vector<float>& coverage, glm::ivec3 res,
                                   const IndexBlurSettings& settings) {
    if (settings.radiusVoxels <= 0) return coverage;
    std::vector<float> a = coverage, b(coverage.size());
    for (int axis = 0; axis < 3; ++axis) {
        shared::BlurKernelCpu kernel{a.data(), res};
        tbb::parallel_for(tbb::blocked_range<int>(0, res.z), [&](const tbb::blocked_range<int>& r) {
            for (int z = r.begin(); z != r.end(); ++z)
                for (int y = 0; y < res.y; ++y)
                    for (int x = 0; x < res.x; ++x)
                        b[(size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) + size_t(x)] =
                            kernel.gaussianBlurAlongAxis(glm::ivec3(x, y, z), res, axis,
                                                         settings.sigmaVoxels,
                                                         settings.radiusVoxels);
        });
        std::swap(a, b);
    }
    return a;
}

}  // namespace eikon
