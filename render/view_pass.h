#pragma once
// The straight-ray viewing pass (emission, absorption, single scattering with shadows) on the GPU
// and its CPU twin. Both run the same shared code (shaders/shared/view_march.h) on the same
// inputs: the packed parameters and one dense grid per field slot.
#include <memory>
#include <vector>

#include "core/dense_grid.h"
#include "render/image.h"
#include "render/light_transport.h"
#include "render/refraction_volume.h"
#include "render/view_params.h"

namespace eikon {

class GpuStageTimer;
class ParamsBuffer;
class VolumeTextures;
class ShaderProgram;

// What the GPU pass needs under dispersion (dispersesView(setup) with curved rays): each
// channel's ∇n volume (red, green, blue; render/refraction_volume.h channelGradientTexture) and
// the params buffer, to which it uploads each channel's params (channelViewParams) in turn and
// setup.params at the end.
struct ViewDispersionGpu {
    unsigned gradientTextures[3] = {0, 0, 0};
    ParamsBuffer* params = nullptr;
};

// CPU twin: 8×8 tiles in parallel (TBB), each pixel independent, so the result does not depend on
// the thread count. `light`: the light-transport method's output (render/light_transport.h), empty
// when the setup reads none. `gradient` is the ∇n volume (render/refraction_volume.h) when
// curvedRays(setup.params) asks for curved rays, else empty. `environment`: the environment image
// when environmentType(params) asks for one. `channelGradients`: under dispersion
// (dispersesView(setup) with curved rays) the red and blue channels' ∇n volumes, `gradient` being
// the green one's; each channel is then traced on its own (three rays a pixel).
// How the CPU twin's view runs; every choice gives the same bytes.
struct ViewCpuOptions {
    // Steps through empty bricks are taken without sampling them (render/empty_bricks.h); false
    // takes every step in full (to measure what skipping gains).
    bool skipEmptySpace = true;
    // The per-pixel code compiled for AVX2 where the processor has it (viewCpuHasAvx2); false
    // runs the baseline x86-64 copy (to measure, and to test that both give the same bytes).
    bool avx2 = true;
    // Where the processor has AVX-512 too (viewCpuHasAvx512), the copy compiled for it, whose 32
    // vector registers hold what the AVX2 copy spills; false runs the AVX2 copy.
    bool avx512 = true;
    // Samples in bricks where their volume holds one value are taken without fetching the
    // corners (render/constant_bricks.h); false fetches every corner.
    bool constantBricks = true;
};

// Whether this build and processor have the view's AVX2 copy (x86-64, optimized, not under the
// sanitizers). Dispersion (three rays a pixel) always runs the baseline copy.
bool viewCpuHasAvx2();
// Whether this build and processor have the view's AVX-512 copy (AVX-512 F and VL, as
// viewCpuHasAvx2 otherwise).
bool viewCpuHasAvx512();

Image renderViewCpu(const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids,
                    const TransportOutputCpu& light, const std::vector<glm::vec4>& gradient = {},
                    const Image* environment = nullptr,
                    const ChannelGradientsCpu* channelGradients = nullptr,
                    const ViewCpuOptions& options = {});

// GPU pass; needs a current GL 4.3 context and the frame's parameters in the ParamsBuffer. Field
// textures come from `textures` in slot order.
class ViewPassGpu {
public:
    // hardwareTrilinear: let the texture unit filter (see shaders/shared/sampling.h).
    explicit ViewPassGpu(bool hardwareTrilinear = false);
    ~ViewPassGpu();
    // light: the light-transport method whose last GPU run the setup reads (null when it reads
    // none); it binds its output to the contract's units. gradientTexture: the ∇n volume for
    // curved rays (0 when the rays are straight). environmentTexture: the environment image
    // (render/environment_map.h) when environmentType(setup.params) asks for one.
    Image render(const ViewSetup& setup, VolumeTextures& textures, const LightTransport* light,
                 unsigned gradientTexture, GpuStageTimer* timer = nullptr,
                 unsigned environmentTexture = 0, const ViewDispersionGpu* dispersion = nullptr);

private:
    // view.comp's variant for one colour channel a dispatch (dispersion) and with the lights'
    // highlights (EK_SPECULAR), made when first needed; [0] the common one.
    ShaderProgram& program(bool perChannel, bool specular);
    std::unique_ptr<ShaderProgram> programs_[4];
    bool hardwareTrilinear_ = false;
    unsigned outputTexture_ = 0;
    int outputWidth_ = 0, outputHeight_ = 0;
};

}  // namespace eikon
