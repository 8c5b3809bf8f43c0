#pragma once
// Light transmittance volumes (shaders/shared/light_volume.h) on the GPU and the CPU twin: one
// RGB volume per light (on the GPU all in one texture, stacked along z) at the render resolution,
// holding exp(−∫κ) from each voxel centre toward the light. The viewing pass reads them instead of
// marching a shadow ray from every sample.
#include <memory>
#include <vector>

#include <glm/vec4.hpp>

#include "core/dense_grid.h"
#include "render/view_params.h"

namespace eikon {

class GpuStageTimer;
class ShaderProgram;
class VolumeTextures;

using LightVolumeCpu = std::vector<glm::vec4>;  // x fastest, like DenseGrid

// CPU twin: every voxel marches in parallel, or, with swept shadows, a directional light sweeps
// slice by slice (each slice in parallel); the result does not depend on the thread count.
std::vector<LightVolumeCpu> computeLightVolumesCpu(const ViewSetup& setup,
                                                   const std::vector<const DenseGrid*>& slotGrids);

class LightVolumesGpu {
public:
    // hardwareTrilinear: let the texture unit filter (see shaders/shared/sampling.h).
    explicit LightVolumesGpu(bool hardwareTrilinear = false);
    ~LightVolumesGpu();
    // Recomputes every light's volume from the field textures (already uploaded).
    void compute(const ViewSetup& setup, VolumeTextures& fields, GpuStageTimer* timer);
    // Binds the stacked light volumes (light l at z offset l·resolution.z) to texture unit
    // EK_UNIT_LIGHT_TRANSMITTANCE (shaders/shared/bindings.h).
    void bind() const;
    // Reads light l's volume back (tests compare it with the CPU twin).
    LightVolumeCpu download(int light) const;

private:
    std::unique_ptr<ShaderProgram> sweep_;
    std::unique_ptr<ShaderProgram> march_;
    void allocate(glm::ivec3 resolution, int lights);

    unsigned texture_ = 0;
    glm::ivec3 resolution_{0};
    int lights_ = 0;
};

}  // namespace eikon
