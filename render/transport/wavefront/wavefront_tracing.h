#pragma once
// Eikonal wavefront tracing (Ihrke et al. 2007; docs: shaders/shared/wavefront.h): the CPU
// twin, in the GPU's rounds (shaders/shared/wavefront_rounds.h): each round's list of patches in
// parallel with TBB, the next list made by the same prefix sums, so that both backends trace the
// same patches and refuse the same splits. Memory: the lists, at most max_patches entries.
//
// Output (x fastest, like DenseGrid), the photons' units (render/transport/photons/
// photon_tracing.h): radiance rgb = Σ power·length per voxel, direction xyz = Σ luminance of that
// × the chord's unit direction; summed in fixed point (the photons' rule), so any thread count
// and any order of patches give the same bits. Every (patch, step) is computed the same whatever
// the order, which a breadth-first GPU list of patches can reproduce.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/dense_grid.h"
#include "render/refraction_volume.h"
#include "render/transport/photons/photon_tracing.h"
#include "render/view_params.h"
#include "shaders/shared/material_index.h"  // at file scope: fresnel.h calls it

EK_NAMESPACE_BEGIN
#define EK_WAVEFRONT_TYPES_ONLY
#include "shaders/shared/wavefront.h"
#undef EK_WAVEFRONT_TYPES_ONLY
EK_NAMESPACE_END

namespace eikon {

enum class WavefrontIntegrator : int { Euler = 0, Midpoint = 1, Rk4 = 2 };

// Every member is 4 bytes: the cache key takes the struct's bytes.
struct WavefrontSettings {
    int patchesPerSide = 64;   // N: N×N starting patches per light-space grid (as photons)
    float stepVoxels = 1.0f;   // Δt, in optical voxel lengths of the smallest edge
    float splitVoxels = 1.0f;  // split a patch spanning more voxels than this along an axis
    int maxLevel = 8;  // split levels; a patch still too wide there has torn (EK_PATCH_TORN)
    // Patches of a frame, at most (starting patches and 4 per split; under dispersion per colour
    // channel), shared equally among the starting patches: each one's splits are granted in the
    // rounds' list order while its share allows (so the cap does not depend on thread timing);
    // the patches refused go on unsplit.
    int maxPatches = 1 << 22;
    float fluxThreshold = 1e-4f;  // drop a patch below this fraction of its initial power
    int maxSteps = 0;             // per patch; 0: 16 crossings of the volume at Δt
    int atCaustic = 0;            // EK_WAVEFRONT_KEEP or EK_WAVEFRONT_REMOVE
    // Chords per side a patch's step is deposited along (depositPatchStep); 1: the paper's
    // midpoint.
    int depositSamples = 2;
    WavefrontIntegrator integrator = WavefrontIntegrator::Rk4;
    // Fresnel at the surfaces of materials marked `fresnel`: a step along which their index
    // changes by more than this per voxel is crossing a surface (shaders/shared/fresnel.h). 0: no
    // Fresnel. 0.01 finds 98 % of the jump of a mesh's edge blurred by σ = 1.5 voxels (its slope
    // peaks at 0.13 per voxel for glass).
    float surfaceSlope = 0.01f;
};

struct WavefrontResultCpu {
    glm::ivec3 resolution{0};
    std::vector<glm::vec4> radiance;     // rgb: Σ power·length; w: 0
    std::vector<glm::vec4> direction;    // xyz: Σ luminance(power·length) × unit direction
    std::vector<glm::vec4> receiverMap;  // irradiance per receiver texel (render/receiver_map.h)
    PhotonTotals totals;  // removed (also in totals.removed), torn and cut patches' power: dropped
    glm::dvec4 fixedPointScale{0.0};
    int64_t steps = 0;             // patch steps, all patches
    int64_t startingPatches = 0;   // active starting patches (their rays reach the box)
    int64_t patchesTraced = 0;     // starting patches and every child made by a split
    int64_t patchesSplit = 0;      // splits done
    int64_t splitsRefused = 0;     // patches refused a split by the patch budget (go on unsplit)
    int64_t patchesTorn = 0;       // ended at the level cap still too wide (EK_PATCH_TORN)
    int64_t patchesRemoved = 0;    // removed at a caustic (atCaustic = remove)
    int64_t causticCrossings = 0;  // orientation flips seen (kept or removed)
    int64_t patchesCut = 0;        // still active at maxSteps; power counts as dropped
    int maxLevelReached = 0;
    int rounds = 0;           // rounds traced, all passes (shared/wavefront_rounds.h)
    int64_t largestList = 0;  // the most patches a round's list held
    // Every patch's final state in the order it ended on its starting patch's thread: for
    // tests that follow the wavefront (empty unless keepPatches).
    std::vector<shared::GpuWavefrontPatch> patches;
};

struct WavefrontPlan {
    glm::ivec3 resolution{0};
    int side = 1;
    std::vector<PhotonLightPlan> lights;  // photons' layouts: the same grids, patches for cells
    size_t patches = 0;                   // starting patches, all lights
    float dt = 0.0f;                      // the optical time step, in scene units
    int maxSteps = 0;
};
WavefrontPlan planWavefronts(const ViewSetup& setup, const WavefrontSettings& settings);

// What every patch's rounds read (shared/wavefront.h patchRound), derived from the settings
// once, the same for both backends.
struct WavefrontRoundSettings {
    int maxSteps = 0;
    float splitVoxels = 1.0f;
    int maxLevel = 0;
    float dt = 0.0f;
    int integrator = EK_WAVEFRONT_RK4;
    int atCaustic = EK_WAVEFRONT_KEEP;
    int samples = 1;
    float surfaceSlope = 0.0f;  // 0: no Fresnel (also where no material has a sharp surface)
};
WavefrontRoundSettings wavefrontRoundSettings(const ViewSetup& setup,
                                              const WavefrontSettings& settings,
                                              const WavefrontPlan& plan);

// The patches each of a pass's `startingPatches` may make, itself included
// (shared/wavefront_rounds.h): max_patches shared equally, at least 1.
int64_t wavefrontRootBudget(const WavefrontSettings& settings, int64_t startingPatches);

// The Fresnel surface criterion the trace uses: settings.surfaceSlope where some material of
// setup has sharp surfaces (fresnel.h anySurfaces), else 0 (none).
float wavefrontSurfaceSlope(const ViewSetup& setup, const WavefrontSettings& settings);

// The params of colour channel `channel`'s wavefronts under dispersion: that channel's n
// (channelViewParams) and the lights' power in that channel alone.
shared::GpuViewParams wavefrontChannelParams(const ViewSetup& setup, int channel);

// The starting patches of every light, light after light in index order (inactive ones too).
// slotGrids: the field volumes (a patch's walk across surfaces starts with their index there).
std::vector<shared::GpuWavefrontPatch> generatePatchesCpu(
    const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids,
    const RefractionVolumeCpu& gradient, const WavefrontSettings& settings = {});

// Traces every light's wavefront through the media (slotGrids: the field volumes; gradient: the
// ∇n volume). keepPatches: also return every final patch (tests). channelGradients: under
// dispersion (dispersesView(setup)) the red and blue channels' ∇n volumes, `gradient` being the
// green one's: each light then sends one wavefront per channel, carrying that channel's power
// and bending with that channel's n, all three into the same sums.
WavefrontResultCpu traceWavefrontsCpu(const ViewSetup& setup,
                                      const std::vector<const DenseGrid*>& slotGrids,
                                      const RefractionVolumeCpu& gradient,
                                      const WavefrontSettings& settings = {},
                                      bool keepPatches = false,
                                      const ChannelGradientsCpu* channelGradients = nullptr);

}  // namespace eikon
