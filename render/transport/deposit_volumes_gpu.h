#pragma once
// The output contract's fluence from a particle trace's fixed-point deposits on the GPU (photons,
// wavefront): resolved into float volumes (shaders/photon_resolve.comp, the CPU twin's
// conversion), both smoothed (render/smoothing.h), and the receiver map uploaded. What the CPU
// twins do with smoothVolumeCpu after readVolumes.
#include <memory>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shaders/shared/gpu_types.h"

namespace eikon {

// Reads back a trace's fixed-point deposits (6 int64 per voxel of resolution `res` as (low, high)
// words, shaders/particle_deposits.glsl) and converts them as the CPU twin does (FixedDepositsCpu
// readVolumes): radiance rgb and the weighted direction xyz per voxel.
void readFixedDeposits(unsigned buffer, glm::ivec3 res, const glm::dvec4& scale,
                       std::vector<glm::vec4>& radiance, std::vector<glm::vec4>& direction);
// Reads back a trace's receiver map sums (3 int64 per texel) and converts them as the twin does
// (render/receiver_map.h), at the totals' scales of the `emitted` power.
std::vector<glm::vec4> readFixedReceiverMap(unsigned buffer, const shared::GpuViewParams& params,
                                            const glm::dvec3& emitted);

class GpuStageTimer;
class ShaderProgram;
class VolumeSmootherGpu;

class DepositVolumesGpu {
public:
    DepositVolumesGpu();
    ~DepositVolumesGpu();
    DepositVolumesGpu(const DepositVolumesGpu&) = delete;
    DepositVolumesGpu& operator=(const DepositVolumesGpu&) = delete;

    // depositBuffer: 6 int64 sums per voxel as (low, high) words (shaders/particle_deposits.glsl)
    // at the fixed-point `scale`; receiverMap: the irradiance per receiver map texel, converted
    // on the host. Timer stage: "smooth".
    void compute(glm::ivec3 resolution, unsigned depositBuffer, const glm::dvec4& scale,
                 const std::vector<glm::vec4>& receiverMap, GpuStageTimer* timer);
    // Binds the smoothed radiance and direction volumes to texture units EK_UNIT_FLUENCE and
    // EK_UNIT_FLUENCE_DIRECTION, and the receiver map to EK_SSBO_RECEIVER_MAP.
    void bind() const;
    // The smoothed radiance and direction volumes (tests).
    std::vector<glm::vec4> radiance() const;
    std::vector<glm::vec4> direction() const;

private:
    void allocate(glm::ivec3 resolution);

    std::unique_ptr<VolumeSmootherGpu> smoother_;
    std::unique_ptr<ShaderProgram> resolve_;
    unsigned raw_[2] = {0, 0};       // radiance, direction before smoothing
    unsigned smoothed_[2] = {0, 0};  // after
    unsigned receiverMap_ = 0;       // SSBO: vec4 irradiance per receiver map texel
    glm::ivec3 resolution_{0};
};

}  // namespace eikon
