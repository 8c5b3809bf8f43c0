#pragma once
// Plane-by-plane semi-Lagrangian light propagation (Magnus's thesis, ch. 4.2; the per-texel
// step is shaders/shared/plane_sweep.h): the CPU twin. Each light's 2D buffer advances slice by
// slice along the volume axis its light travels most along, `planesPerVoxel` planes a voxel;
// what the buffer holds at every voxel-centre plane becomes that slice of the output contract's
// fluence and mean-direction volumes (render/light_transport.h), so every view pass and bench
// reads it as it reads the photons'. The buffers themselves hold three planes of texels whatever
// the volume's depth (PlaneSweepMemory reports both).
//
// Deterministic: every texel of a plane is computed from the previous plane alone, in any
// order; the receivers' sums are fixed point, so their order does not matter either: the same
// bits for any thread count, and on the GPU (plane_sweep_gpu.h).
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/dense_grid.h"
#include "render/refraction_volume.h"
#include "render/view_params.h"

EK_NAMESPACE_BEGIN
#define EK_PLANE_SWEEP_TYPES_ONLY
#include "shaders/shared/plane_sweep.h"
#undef EK_PLANE_SWEEP_TYPES_ONLY
EK_NAMESPACE_END

namespace eikon {

// Every member is 4 bytes: the cache key takes the struct's bytes.
struct PlaneSweepSettings {
    int planesPerVoxel = 1;        // planes between two voxel centres along the sweep axis
    int backTraceRefinements = 1;  // fixed-point refinements of each texel's back-trace
    int intensityCorrection = 1;   // the intensity law (S_{i−1}/S_i); 0: light is only moved
    // Light whose direction comes within this cosine of the planes is lost (a sweep cannot
    // carry light that does not cross its planes).
    float minCosine = 0.2f;
    // 1: the view rays advance with the planes and no fluence volume is kept (plane_sweep_view.h);
    // 0: the planes are written into the fluence volumes the view pass reads.
    int interleavedView = 0;
};

// How one light is swept: along `axis` (u, w the plane's axes), toward +axis when order is +1.
struct PlaneSweepPlan {
    int axis = 2, u = 0, w = 1, order = 1;
    glm::ivec2 size{0};  // texels of a plane (the volume's resolution along u and w)
    int planes = 0;      // planes swept, the first on the first voxel-centre slice
    int depth = 0;       // voxels along the axis
    int perVoxel = 1;    // planes between two voxel centres
    int light = 0;
    // A light with a disc: the radii of its kernel along u and w, texels (softLightRadius in
    // plane_sweep_cpu.cpp); (0, 0) without one.
    glm::dvec2 softRadius{0.0};
};

// A family of planes: the slices across `axis`, swept toward +axis when order is +1.
struct SweepAxis {
    int axis = 2;
    int order = 1;
};
// The axis a direction travels most along, and its sense.
SweepAxis dominantAxis(glm::vec3 direction);

// The sweep of light l: across the axis its light travels most along, or across `forced`. Throws
// eikon::Error where a point or spot light is not outside the face its sweep enters through (the
// sweep needs every ray to cross the planes forward).
PlaneSweepPlan planPlaneSweep(const ViewSetup& setup, int light, const PlaneSweepSettings& s,
                              const SweepAxis* forced = nullptr);

// Plane j (0 ≤ j < plan.planes) of a light's sweep: the shared step's parameters, the same for
// the CPU twin and the GPU dispatch.
shared::GpuPlaneSweep planeSweepStep(const ViewSetup& setup, const PlaneSweepPlan& plan,
                                     const PlaneSweepSettings& settings, int j);
// The volume slice plane j lies on (the output contract's), or −1 between voxel centres.
int planeSweepSlice(const PlaneSweepPlan& plan, int j);

// The fixed-point scale of the receivers' sums (render/transport/fixed_point.h): 2^40 quanta
// for the most power the lights in the fluence could bring into the volume.
double planeSweepReceiverScale(const ViewSetup& setup, const PlaneSweepSettings& settings);
// Irradiance (rgb) per receiver map texel from the sums (3 per texel) of the power it gathered.
std::vector<glm::vec4> planeSweepReceiverMap(const ViewSetup& setup, const int64_t* sums,
                                             double scale);

// What a run allocates, in bytes.
struct PlaneSweepMemory {
    size_t bufferBytes = 0;  // the light buffers: two planes of light and direction, one of traces
    size_t outputBytes = 0;  // the fluence and mean-direction volumes written for the view
    // The interleaved view's (plane_sweep_view.h): the slices of fluence and direction it
    // holds and the view rays' states; 0 otherwise.
    size_t viewBytes = 0;
};

struct PlaneSweepResultCpu {
    // x fastest, the photons' units: rgb Σ flux·length per voxel (fluence rate × voxel volume);
    // xyz Σ its luminance × the light's unit direction.
    std::vector<glm::vec4> fluence;
    std::vector<glm::vec4> direction;
    // Irradiance (rgb) per receiver map texel (render/receiver_map.h): the light the receivers
    // stopped, gathered on their front faces.
    std::vector<glm::vec4> receiverMap;
    int64_t texels = 0;      // texels of a plane, summed over the lights (and channels) swept
    int64_t texelSteps = 0;  // texel updates, all planes and lights
    int64_t texelsLost = 0;  // of them, where the light turned within minCosine of the planes
    PlaneSweepMemory memory;
};

// The receivers' sums of the power the sweeps stop (3 fixed-point int64 per map texel, any
// order of additions giving the same sums) and the map they make.
struct SweepReceiversCpu {
    SweepReceiversCpu(const ViewSetup& setup, const PlaneSweepSettings& settings);
    std::vector<glm::vec4> map(const ViewSetup& setup) const;
    size_t count;
    std::unique_ptr<std::atomic<int64_t>[]> sums;
    double scale;
};

// One sweep: a light, and under dispersion one colour channel of it, through that channel's ∇n.
struct LightSweepSpec {
    PlaneSweepPlan plan;
    const RefractionVolumeCpu* gradient;
    glm::vec3 channels;  // the channels its sources send (render/transport/channel_passes.h)
};
// Every light that comes through the fluence, each channel's sweep under dispersion (with
// channelGradients and a setup that disperses), in the order their deposits add up. Across
// `forced` planes when given.
std::vector<LightSweepSpec> lightSweepSpecs(const ViewSetup& setup,
                                            const RefractionVolumeCpu& gradient,
                                            const PlaneSweepSettings& settings,
                                            const ChannelGradientsCpu* channelGradients,
                                            const SweepAxis* forced = nullptr);

// One sweep's buffers, advanced plane by plane: sweepLightsCpu runs the sweeps one after the
// other; the interleaved view (plane_sweep_view.h) all of them together, plane by plane, beside
// the view rays.
class LightSweepCpu {
public:
    LightSweepCpu(const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids,
                  const LightSweepSpec& spec, const PlaneSweepSettings& settings,
                  SweepReceiversCpu& receivers);
    ~LightSweepCpu();
    LightSweepCpu(const LightSweepCpu&) = delete;
    LightSweepCpu& operator=(const LightSweepCpu&) = delete;

    const PlaneSweepPlan& plan() const;
    // Advances the buffers to plane j: 0, 1, ... plan().planes − 1 in turn.
    void advance(int j);
    // Adds the light on the plane just reached (a voxel-centre plane: planeSweepSlice ≥ 0) to a
    // slice of the fluence and mean-direction volumes: texel (a, b) to element
    // a·strideU + b·strideW (sweepDepositTexel).
    void deposit(glm::vec4* fluence, glm::vec4* direction, size_t strideU, size_t strideW) const;
    // The plane just reached (rgb: irradiance; direction xyz: v, w: 1 where lit), u fastest.
    const std::vector<glm::vec4>& light() const;
    const std::vector<glm::vec4>& direction() const;
    int64_t texelsLost() const;  // so far
    size_t bufferBytes() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};
// Adds a finished sweep's texels, steps and losses to out's counters.
void countSweep(const LightSweepCpu& sweep, PlaneSweepResultCpu& out);

// Sees each light's buffer at every voxel-centre plane: the light, the slice index along the
// plan's axis, and the plane's light (rgb: irradiance on the plane) and direction (xyz: v =
// n dx/ds; w: 1 where lit), u fastest.
using PlaneSweepObserver = std::function<void(int lightIndex, const PlaneSweepPlan& plan, int slice,
                                              const std::vector<glm::vec4>& planeLight,
                                              const std::vector<glm::vec4>& planeDirection)>;

// Sweeps every light that comes through the fluence (lightInFluence). `gradient` is the ∇n
// volume (xyz: ∇n, w: n). Receivers stop the light that crosses them (their maps gather it).
// With channelGradients (the red and blue ∇n volumes) and a setup that disperses, each light is
// swept once per colour channel, through that channel's volume, its sources sending that channel
// alone (render/transport/channel_passes.h): three times the texel steps, and the observer sees
// each pass.
PlaneSweepResultCpu sweepLightsCpu(const ViewSetup& setup,
                                   const std::vector<const DenseGrid*>& slotGrids,
                                   const RefractionVolumeCpu& gradient,
                                   const PlaneSweepSettings& settings,
                                   const PlaneSweepObserver& observer = {},
                                   const ChannelGradientsCpu* channelGradients = nullptr);

}  // namespace eikon
