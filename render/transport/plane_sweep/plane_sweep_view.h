#pragma once
// The plane sweep's interleaved view (Magnus's thesis, ch. 5.2, Algorithm 1): the view rays
// advance through the volume with the light planes, each shading its samples from the last few
// slices swept (eight), so no fluence volume is stored: what the light needs grows with the image
// and the plane, not with the volume, and a light move costs a sweep and a view like a camera move.
//
// The planes are the volume's slices across the axis the camera looks most along (from the
// camera to the volume's centre), the thesis's planes perpendicular to the view, kept to the
// volume's axes as the light sweep is. Every view ray crosses them front to back, and every
// light must cross them forward too (light from the camera's side, as in the thesis).
//
// Each view ray is the view pass's own (shaders/shared/view_march.h: curvedRayAdvance,
// straightRayAdvance), stopped where its next sample would read a slice not swept yet
// (viewSampleReady) and taken on when it is. Its samples read the slices held exactly as
// they would read the whole volume, so where the sweeps cross the same planes the image is the
// volume path's to the bit; what differs: reflections at sharp surfaces are seen in the
// environment (the view pass traces two through the volume, back toward the camera, against
// the sweep). A ray that meets a receiver keeps the hit (receiverDeferred) and is shaded once
// the receiver's light is complete: a voxel receiver's when the slices in front of it are held,
// a plane receiver's map after the last plane (it fills as the planes pass it).
//
// On the GPU (InterleavedViewGpu: shaders/view_interleaved.comp beside plane_sweep.comp) the ray
// states stay in buffers between dispatches; the CPU twin is renderInterleavedCpu.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "render/image.h"
#include "render/transport/plane_sweep/plane_sweep_cpu.h"
#include "render/transport/plane_sweep/plane_sweep_gpu.h"

namespace eikon {

class GpuStageTimer;
class ParamsBuffer;
class RefractionVolumesGpu;
class ShaderProgram;
class VolumeTextures;

// The planes the interleaved view sweeps: across the axis the camera looks most along.
SweepAxis interleavedSweepAxis(const ViewSetup& setup);

// Throws eikon::Error (at `where`, the settings' JSON pointer) for what the interleaved view
// cannot do: a camera inside the slab of planes or beside it (its rays must cross them front to
// back), a light that does not cross them forward with at least min_cosine.
void checkInterleavedView(const ViewSetup& setup, const PlaneSweepSettings& settings,
                          const std::string& where);

// What the view rays and the slices held take for this setup, in bytes (the sweeps' own
// buffers aside).
size_t interleavedViewBytes(const ViewSetup& setup);

struct InterleavedViewCpu {
    Image image;
    // The sweeps' counters and memory; no fluence or direction volume, outputBytes 0.
    PlaneSweepResultCpu sweep;
    size_t windowBytes = 0;  // the slices of fluence and direction held
    size_t rayBytes = 0;     // the view rays' states
    // Samples of view rays that turned back against the sweep: read from the nearer slice held
    // instead of the one dropped.
    int64_t samplesBehind = 0;
    int64_t viewSteps = 0;  // view ray steps, all pixels
};

// Sweeps every light of the fluence beside the view rays and returns the frame.
// `gradient`: the ∇n volume; `environment`: as renderViewCpu's. Under dispersion
// (dispersesView, curved rays) `channelGradients` holds the red and blue channels' ∇n volumes:
// each light is swept once a channel and each pixel has a ray a channel, as the volume path has.
// The timer (null: none) gets the sweeps' share as stage "plane_sweep" and the rays' as "view".
InterleavedViewCpu renderInterleavedCpu(const ViewSetup& setup,
                                        const std::vector<const DenseGrid*>& slotGrids,
                                        const RefractionVolumeCpu& gradient,
                                        const PlaneSweepSettings& settings,
                                        const Image* environment,
                                        const ChannelGradientsCpu* channelGradients = nullptr,
                                        GpuStageTimer* timer = nullptr);

// The GPU port (needs a current GL 4.3 context): the same sweeps in lockstep
// (PlaneSweepGpu::sweepWindowed), the window as two RGBA32F volumes of res[u] × res[w] × 8 slices,
// and one dispatch of view_interleaved.comp over the pixels at each turn; each pixel's ray state
// (the shared CurvedRay or StraightRay, laid out by the driver) stays in a buffer between them.
// Receivers and dispersion as on the twin.
class InterleavedViewGpu {
public:
    // exactMath: the sweep's (PlaneSweepGpu).
    explicit InterleavedViewGpu(bool exactMath);
    ~InterleavedViewGpu();
    InterleavedViewGpu(const InterleavedViewGpu&) = delete;
    InterleavedViewGpu& operator=(const InterleavedViewGpu&) = delete;

    // The frame, as renderInterleavedCpu's: the fields uploaded and the params bound
    // (TransportInputsGpu), `refraction` holding ∇n; `environmentTexture` as the view pass's.
    Image render(const ViewSetup& setup, VolumeTextures& fields,
                 const RefractionVolumesGpu& refraction, const PlaneSweepSettings& settings,
                 unsigned environmentTexture, GpuStageTimer* timer = nullptr);

    // The last frame's sweeps (counters, memory, receiver map).
    const PlaneSweepGpu& sweep() const { return sweep_; }
    int64_t viewSteps() const { return viewSteps_; }
    int64_t samplesBehind() const { return samplesBehind_; }
    size_t windowBytes() const { return windowBytes_; }
    size_t rayBytes() const { return rayBytes_; }  // rays, flags and receiver hits

private:
    // view_interleaved.comp's variant: curved or straight rays, with the lights' highlights or
    // not; made when first needed.
    ShaderProgram& program(bool curved, bool specular);
    void allocate(const shared::GpuViewParams& p, const SweepAxis& axis, size_t rayStride,
                  int channels);

    PlaneSweepGpu sweep_;
    std::unique_ptr<ShaderProgram> programs_[4];
    // Under dispersion: red, green and blue's params (channelViewParams), then the scene's.
    std::unique_ptr<ParamsBuffer> params_[4];
    unsigned window_[2] = {0, 0};  // fluence, mean direction
    glm::ivec3 windowSize_{0};
    unsigned output_ = 0;
    int outputWidth_ = 0, outputHeight_ = 0;
    unsigned rays_ = 0, flags_ = 0, hits_ = 0, counters_ = 0;
    int64_t viewSteps_ = 0, samplesBehind_ = 0;
    size_t windowBytes_ = 0, rayBytes_ = 0;
};

}  // namespace eikon
