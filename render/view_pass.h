#pragma once
// The straight-ray viewing pass (emission, absorption, single scattering with shadows) on the GPU
// and its CPU twin. Both run the same shared code (shaders/shared/view_march.h) on the same
// inputs: the packed parameters and one dense grid per field slot.
#include <memory>
#include <vector>

#include "core/dense_grid.h"
#include "render/image.h"
#include "render/light_volume.h"
#include "render/view_params.h"

namespace eikon {

class GpuStageTimer;
class LightVolumesGpu;
class PhotonRadianceGpu;
struct PhotonRadianceCpu;
class VolumeTextures;
class ShaderProgram;

// CPU twin: rows in parallel (TBB), each pixel independent, so the result does not depend on the
// thread count. `lightVolumes` may be empty when viewNeedsLightVolumes(setup) is false.
// `gradient` is the ∇n volume (render/refraction_volume.h) when setup.params.pipeline.x asks for
// curved rays, else empty. `photons`: the smoothed photon volumes when pipeline.y asks for them.
// `environment`: the environment image when params.environment.x asks for one.
Image renderViewCpu(const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids,
                    const std::vector<LightVolumeCpu>& lightVolumes,
                    const std::vector<glm::vec4>& gradient = {},
                    const PhotonRadianceCpu* photons = nullptr, const Image* environment = nullptr);

// GPU pass; needs a current GL 4.3 context and the frame's parameters in the ParamsBuffer. Field
// textures come from `textures` in slot order.
class ViewPassGpu {
public:
    // hardwareTrilinear: let the texture unit filter (see shaders/shared/sampling.h).
    explicit ViewPassGpu(bool hardwareTrilinear = false);
    ~ViewPassGpu();
    // gradientTexture: the ∇n volume for curved rays (0 when the rays are straight). photons:
    // the smoothed photon volumes when setup.params.pipeline.y asks for them.
    // environmentTexture: the environment image (render/environment_map.h) when
    // setup.params.environment.x asks for one.
    Image render(const ViewSetup& setup, VolumeTextures& textures, const LightVolumesGpu& lights,
                 unsigned gradientTexture, const PhotonRadianceGpu* photons = nullptr,
                 GpuStageTimer* timer = nullptr, unsigned environmentTexture = 0);

private:
    std::unique_ptr<ShaderProgram> program_;
    unsigned outputTexture_ = 0;
    int outputWidth_ = 0, outputHeight_ = 0;
};

}  // namespace eikon
