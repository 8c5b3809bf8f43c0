#pragma once
// Photon tracing, steps 4 and 5 of Sun et al. 2008 (docs: shaders/shared/photons.h): the CPU twin,
// parallel over photons with TBB; the GPU port runs the same shared functions.
//
// Every light is traced: directional lights of irradiance E (power per area) send photons of
// flux E × cell area, point and spot lights of intensity I (power per steradian) photons of flux
// I × the cell's solid angle (× the spot falloff); see the units in shaders/shared/photons.h.
//
// Radiance volume (x fastest, like DenseGrid): rgb = Σ flux·length per voxel, in power × scene
// units (divide by the voxel's volume for the fluence rate, power per area: I/r² from a point
// light in a clear medium); direction volume: xyz = Σ luminance of that flux·length × the
// segment's unit direction.
//
// Determinism: deposits are summed as 64-bit integers, so the order of additions does not matter
// and any thread count gives the same bits. A deposit q becomes llround(q · scale) with, per
// channel, scale = 2^40 / (Φ_c · h): Φ_c the power emitted in that channel this frame (all
// lights), h the smallest voxel edge. One quantum is Φ·h·2^-40 (~1e-12 of a photon budget
// crossing one voxel), and a voxel overflows only if more than 2^23 voxel lengths' worth of the
// whole emitted power pass through it. The direction volume uses the same rule with the emitted
// power's luminance. Totals (escaped, extinguished, dropped) are integer sums too, per photon,
// at 2^40 / Φ_c.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/dense_grid.h"
#include "core/ray_integrator.h"
#include "render/refraction_volume.h"
#include "render/view_params.h"

EK_NAMESPACE_BEGIN
#define EK_PHOTON_TYPES_ONLY
#include "shaders/shared/photons.h"
#undef EK_PHOTON_TYPES_ONLY
EK_NAMESPACE_END

namespace eikon {

struct PhotonSettings {
    int photonsPerSide = 128;    // N: N×N photons per light-space grid (PhotonLightPlan)
    float minStepVoxels = 1.0f;  // Δs_min, in voxels of the smallest edge
    // How a photon steps through the ray equation (shaders/shared/ray_equation.h).
    RayIntegrator integrator = RayIntegrator::Rk4;
    float fluxThreshold = 1e-4f;  // drop a photon below this fraction of its initial flux
    int maxSteps = 0;             // per photon; 0: 16 crossings of the volume at Δs_min
    // The march runs in rounds of this many steps of every active photon; after each round the
    // photons still active are compacted into a list (on the GPU, without a read-back) and only
    // they are marched on. Without the stop rule the results do not depend on it; with it, the
    // rule is checked once per round. 0: one round of maxSteps.
    int stepsPerRound = 32;
    // After a round, when fewer than this fraction of the traced photons are still active, they
    // are cut (EK_PHOTON_CUT, their flux counted as dropped): a few trapped photons no longer
    // keep the whole march going. 0: never; the step cap still applies.
    float stopFraction = 1e-3f;
    uint32_t seed = 0;
    int frame = 0;
};

// Per colour channel, in power (irradiance × area, or intensity × solid angle).
struct PhotonTotals {
    glm::dvec3 emitted{0.0};       // Σ initial flux of the photons that entered the box
    glm::dvec3 escaped{0.0};       // flux carried out through the box's faces
    glm::dvec3 extinguished{0.0};  // lost to e^(−κΔ): absorbed or scattered out
    glm::dvec3 dropped{0.0};       // left in photons removed below the threshold or cut
    glm::dvec3 received{0.0};      // carried onto a receiver (front or back face)
    glm::dvec3 removed{0.0};       // of dropped: wavefront patches removed at caustics
    glm::dvec3 reflected{0.0};     // reflected at surfaces (Fresnel) and not followed
};

struct PhotonResultCpu {
    glm::ivec3 resolution{0};
    std::vector<glm::vec4> radiance;   // rgb: Σ flux·length; w: 0
    std::vector<glm::vec4> direction;  // xyz: Σ luminance(flux·length) × unit direction; w: 0
    // Irradiance (rgb) per texel of the receivers' front faces (render/receiver_map.h).
    std::vector<glm::vec4> receiverMap;
    PhotonTotals totals;
    glm::dvec4 fixedPointScale{0.0};  // rgb: radiance channels; w: direction (see above)
    int64_t steps = 0;                // photon steps taken, all photons
    int64_t photonsTraced = 0;        // photons that entered the box, all passes
    // Still active at maxSteps, or when the stop rule ended the march (PhotonSettings::
    // stopFraction); their flux counts as dropped.
    int64_t photonsCut = 0;
    int rounds = 0;  // rounds of the march that had photons to march (PhotonSettings)
    // Every photon's final state, light after light, index order: for escaped photons the exit
    // point and the direction v they leave with (shared::GpuPhoton, EK_PHOTON_* in position.w).
    // Under dispersion the passes' photons one after the other: red's, green's, blue's.
    std::vector<shared::GpuPhoton> photons;
};

// One light's photons: photons[first .. first + count) of the photon list, in the layout
// `grid` (EK_PHOTON_GRID_*: one N×N grid, six for a light in or beside the box, none for a spot
// whose cone misses the box).
struct PhotonLightPlan {
    int light = 0;  // index in ViewParams.lights
    int grid = EK_PHOTON_GRID_NONE;
    size_t first = 0;
    size_t count = 0;  // photonGridFaces(grid) · side²
};

// What the settings mean for a given volume, derived once for both backends.
struct PhotonPlan {
    glm::ivec3 resolution{0};
    size_t voxels = 0;
    int side = 1;                         // photons per side of a light-space grid
    std::vector<PhotonLightPlan> lights;  // every light, in order
    size_t photons = 0;                   // all lights' photons
    float minStep = 0.0f;                 // Δs_min in scene units
    int maxSteps = 0;                     // per photon
    int stepsPerRound = 0;                // in [1, maxSteps]
    int rounds = 0;                       // enough rounds to reach maxSteps
    float stopFraction = 0.0f;
};
PhotonPlan planPhotons(const ViewSetup& setup, const PhotonSettings& settings);

// Every light's layout of N×N grids (side N), decided by the shared photonGrid once on the host,
// with each light's particles numbered on from the last's; `particles` gets the total. Shared by
// the photon and wavefront plans (one patch per cell).
std::vector<PhotonLightPlan> planLightGrids(const ViewSetup& setup, int side, size_t& particles);

// Dispersion (a dispersive material seen along curved rays: dispersesView): every photon is
// traced once per colour channel, each pass bending through that channel's ∇n volume (its n at
// every point, the entry's v = n·d included) and depositing that channel alone; the photons
// carry all three channels' flux in every pass, so each pass drops and cuts them exactly as a
// trace of that channel's n would, and channel c of the deposits is, bit for bit, what a glass
// without dispersion of index n_c gives. The three passes share one set of fixed-point sums and
// scales (those of one pass carrying all three), so with equal n in every channel they deposit
// the plain trace's power·length bytes; the luminance-weighted direction, summed per channel,
// rounds differently (within a quantum per pass). Three times the steps and the time. The passes
// and their masks: render/transport/channel_passes.h.

// Steps every active photon takes in round `round` (from 0) of plan: stepsPerRound, less in a
// last round that reaches maxSteps. Every photon still active after a round has taken all of its
// steps, so all of them have taken the same number and the step cap is one count for all.
int photonRoundSteps(const PhotonPlan& plan, int round);

// The stop rule: the march ends once fewer than this many photons are active after a round
// (stopFraction × traced, rounded up, so that "fewer than" compares integers exactly); 0: never.
int64_t photonStopCount(const PhotonPlan& plan, int64_t photonsTraced);

// Every photon of the plan in its starting state (step 4), light after light in index order: what
// traceLightPhotonsCpu marches, for tests and benches that compare paths with exact ones. A
// photon starts with v = n·d, n read from `gradient` (the ∇n volume) where it enters.
std::vector<shared::GpuPhoton> generatePhotonsCpu(const ViewSetup& setup,
                                                  const RefractionVolumeCpu& gradient,
                                                  const PhotonSettings& settings = {});

// Traces the photons of every light of setup (PhotonPlan) through the media: slotGrids are the
// field volumes (as for computeIndexGradientCpu), gradient and octree the refraction volumes.
// With channelGradients (the red and blue ∇n volumes, `gradient` the green one's) and a setup
// that disperses (dispersesView), one pass per colour channel (channelPassCount).
PhotonResultCpu traceLightPhotonsCpu(const ViewSetup& setup,
                                     const std::vector<const DenseGrid*>& slotGrids,
                                     const RefractionVolumeCpu& gradient,
                                     const RefractionVolumeCpu& octree,
                                     const PhotonSettings& settings = {},
                                     const ChannelGradientsCpu* channelGradients = nullptr);

}  // namespace eikon
