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
#include <cstddef>
#include <cstdint>
#include <functional>
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

// The sweep of light l. Throws eikon::Error where a point or spot light is not outside the face
// its sweep enters through (the sweep needs every ray to cross the planes forward).
PlaneSweepPlan planPlaneSweep(const ViewSetup& setup, int light, const PlaneSweepSettings& s);

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
