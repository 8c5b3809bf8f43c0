// The CPU twin of the blur; the CPU voxelizer itself is core's (core/mesh_voxelize.h), shared
// with the smoke solver's mesh obstacles.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "render/voxelize.h"
#include "shaders/shared/platform.h"

EK_NAMESPACE_BEGIN

// gaussian_blur.h's tap weights come from blurWeights (blurTapWeight).
#define EK_BLUR_WEIGHT_TABLE

struct BlurKernelCpu {
    const float* source;
    ivec3 res;
    // gaussianBlurWeight(d, sigma) at blurWeights[d], d in [−radius, radius].
    const float* blurWeights = nullptr;
    float fetchUnblurred(ivec3 v) const {
        return source[(size_t(v.z) * size_t(res.y) + size_t(v.y)) * size_t(res.x) + size_t(v.x)];
    }

#include "shaders/shared/gaussian_blur.h"
};

EK_NAMESPACE_END

namespace eikon {
namespace {

// One pass of the blur along `axis`, from kernel.source into `out`. The voxels whose window lies
// inside the volume along the axis take their taps a row at a time, sums[x] += w[d] · tap[x] for
// d = −radius … radius: each voxel's sum is gaussianBlurAlongAxis's, the same products added in
// the same order, and so is the weight sum it divides by, so the floats are the same
// (tests/render/test_voxelize.cpp holds them to an exp a tap by memcmp). With the weight table,
// the mesh blur at 128³ went from 110-115 to 7.8 ms (BENCHMARKS.md, "The mesh blur 14×"). The
// voxels within a radius of a face call the shared function, which leaves out the missing taps.
void blurPass(shared::BlurKernelCpu& kernel, float* out, int axis,
              const IndexBlurSettings& settings) {
    const glm::ivec3 res = kernel.res;
    const int radius = settings.radiusVoxels;
    const float* weights = kernel.blurWeights;  // weights[d], d in [−radius, radius]
    float fullWeightSum = 0.0f;
    for (int d = -radius; d <= radius; ++d) fullWeightSum += weights[d];
    const size_t row = size_t(res.x);
    const size_t plane = row * size_t(res.y);
    const ptrdiff_t tapStride = ptrdiff_t(axis == 0 ? 1 : axis == 1 ? row : plane);
    tbb::parallel_for(tbb::blocked_range<int>(0, res.z), [&](const tbb::blocked_range<int>& r) {
        std::vector<float> sums(row);
        for (int z = r.begin(); z != r.end(); ++z)
            for (int y = 0; y < res.y; ++y) {
                const float* source = kernel.source + size_t(z) * plane + size_t(y) * row;
                float* target = out + size_t(z) * plane + size_t(y) * row;
                // [x0, x1): the voxels of this row with their whole window inside the volume.
                int x0 = axis == 0 ? radius : 0;
                int x1 = axis == 0 ? res.x - radius : res.x;
                const int along = axis == 1 ? y : z;
                if (axis != 0 && (along < radius || along >= res[axis] - radius)) x1 = x0;
                if (x1 <= x0) x0 = x1 = 0;
                if (x1 > x0) {
                    std::fill(sums.begin() + x0, sums.begin() + x1, 0.0f);
                    for (int d = -radius; d <= radius; ++d) {
                        const float w = weights[d];
                        const float* tap = source + ptrdiff_t(d) * tapStride;
                        for (int x = x0; x < x1; ++x) sums[size_t(x)] += w * tap[x];
                    }
                    for (int x = x0; x < x1; ++x) target[x] = sums[size_t(x)] / fullWeightSum;
                }
                for (int x = 0; x < res.x; ++x)
                    if (x < x0 || x >= x1)
                        target[x] = kernel.gaussianBlurAlongAxis(glm::ivec3(x, y, z), res, axis,
                                                                 settings.sigmaVoxels, radius);
            }
    });
}

}  // namespace

std::vector<float> blurCoverageCpu(const std::vector<float>& coverage, glm::ivec3 res,
                                   const IndexBlurSettings& settings) {
    if (settings.radiusVoxels <= 0) return coverage;
    std::vector<float> weights;
    for (int d = -settings.radiusVoxels; d <= settings.radiusVoxels; ++d)
        weights.push_back(shared::BlurKernelCpu{}.gaussianBlurWeight(d, settings.sigmaVoxels));
    std::vector<float> a = coverage, b(coverage.size());
    for (int axis = 0; axis < 3; ++axis) {
        shared::BlurKernelCpu kernel{a.data(), res, weights.data() + settings.radiusVoxels};
        blurPass(kernel, b.data(), axis, settings);
        std::swap(a, b);
    }
    return a;
}

}  // namespace eikon
