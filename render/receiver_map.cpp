#include "render/receiver_map.h"

#include <algorithm>

#include "core/error.h"
#include "render/smoothing.h"
#include "render/volume_kernels_cpu.h"

namespace eikon {

size_t receiverMapTexels(const shared::GpuViewParams& params) {
    size_t texels = 0;
    for (int r = 0; r < shared::receiverCount(params); ++r)
        texels += size_t(shared::receiverMapWidth(params.receivers[r])) *
                  size_t(shared::receiverMapHeight(params.receivers[r]));
    return texels;
}

std::vector<glm::vec4> receiverMapFromFixed(const shared::GpuViewParams& params,
                                            const std::vector<int64_t>& sums, glm::dvec3 scale) {
    const size_t texels = receiverMapTexels(params);
    if (sums.size() != 3 * texels)
        throw Error("receiver map", "expected " + std::to_string(3 * texels) + " sums, got " +
                                        std::to_string(sums.size()));
    shared::VolumeAccessCpu volume{params};  // for the shared receiverTexelArea
    std::vector<glm::vec4> map(texels, glm::vec4(0.0f));
    for (int r = 0; r < shared::receiverCount(params); ++r) {
        const glm::ivec4 t = params.receivers[r].texels;
        const double area = double(volume.receiverTexelArea(r));
        const size_t count = size_t(t.x) * size_t(t.y);
        if (count == 0) continue;  // a voxel receiver: no map
        std::vector<glm::vec4> raw(count, glm::vec4(0.0f));
        for (size_t i = 0; i < count; ++i)
            for (int c = 0; c < 3; ++c) {
                const double sum = double(sums[3 * (size_t(t.z) + i) + c]);
                raw[i][c] = scale[c] > 0.0 ? float(sum / scale[c] / area) : 0.0f;
            }
        // The photon volumes' binomial smoothing, in the plane (a map is a one-texel-thick
        // volume): σ = 1/√2 texel.
        const std::vector<glm::vec4> smoothed = smoothVolumeCpu(raw, glm::ivec3(t.x, t.y, 1));
        std::copy(smoothed.begin(), smoothed.end(), map.begin() + t.z);
    }
    return map;
}

}  // namespace eikon
