#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "render/transport/channel_passes.h"
#include "render/transport/photons/fixed_deposits_cpu.h"
#include "render/transport/photons/lights_missing_volume.h"
#include "render/transport/wavefront/wavefront_tracing.h"
#include "shaders/shared/wavefront_rounds.h"

EK_NAMESPACE_BEGIN

// The wavefront shaders' world: the photons' (deposits, receivers, extinction) and the wavefront
// functions on top.
struct WavefrontKernelCpu : PhotonKernelCpu {
    // clang-format off
#include "shaders/shared/wavefront.h"
    // clang-format on
};

EK_NAMESPACE_END

namespace eikon {

static_assert(int(WavefrontIntegrator::Euler) == EK_WAVEFRONT_EULER &&
                  int(WavefrontIntegrator::Midpoint) == EK_WAVEFRONT_MIDPOINT &&
                  int(WavefrontIntegrator::Rk4) == EK_WAVEFRONT_RK4,
              "WavefrontIntegrator and shaders/shared/wavefront.h disagree");

namespace {

// What the tracer counts besides the photons' totals.
struct WavefrontCounters {
    std::atomic<int64_t> traced{0};
    std::atomic<int64_t> split{0};
    std::atomic<int64_t> refused{0};
    std::atomic<int64_t> removed{0};
    std::atomic<int64_t> torn{0};
    std::atomic<int64_t> crossings{0};
    std::atomic<int> maxLevel{0};
};

}  // namespace

WavefrontPlan planWavefronts(const ViewSetup& setup, const WavefrontSettings& settings) {
    WavefrontPlan plan;
    plan.resolution = glm::ivec3(setup.params.resolution);
    const glm::ivec3 res = plan.resolution;
    plan.side = std::max(settings.patchesPerSide, 1);
    // The photons' layouts, one patch per cell.
    plan.lights = planLightGrids(setup, plan.side, plan.patches);
    shared::WavefrontKernelCpu kernel{{{setup.params}}};
    const glm::vec3 h = kernel.volumeVoxelSize();
    const float stepVoxels = std::max(settings.stepVoxels, 1e-3f);
    plan.dt = stepVoxels * std::min({h.x, h.y, h.z});
    // By default a patch may cross the volume 16 times (a trapped path; outside the box, the
    // approach from the light's plane is at most one more crossing).
    plan.maxSteps = settings.maxSteps > 0
                        ? settings.maxSteps
                        : int(std::ceil(16.0f * float(res.x + res.y + res.z) / stepVoxels));
    return plan;
}

std::vector<shared::GpuWavefrontPatch> generatePatchesCpu(
    const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids,
    const RefractionVolumeCpu& gradient, const WavefrontSettings& settings) {
    shared::WavefrontKernelCpu kernel{{{setup.params}}};
    for (size_t s = 0; s < slotGrids.size(); ++s) kernel.fields[s] = slotGrids[s]->values.data();
    kernel.gradient = gradient.data();
    const WavefrontPlan plan = planWavefronts(setup, settings);
    std::vector<shared::GpuWavefrontPatch> patches(plan.patches);
    for (const PhotonLightPlan& light : plan.lights)
        tbb::parallel_for(tbb::blocked_range<size_t>(0, light.count, 256),
                          [&](const tbb::blocked_range<size_t>& r) {
                              for (size_t i = r.begin(); i != r.end(); ++i)
                                  patches[light.first + i] =
                                      kernel.generatePatch(light.light, light.grid, plan.side,
                                                           int(i), settings.fluxThreshold);
                          });
    return patches;
}

int64_t wavefrontRootBudget(const WavefrontSettings& settings, int64_t startingPatches) {
    return std::max<int64_t>(
        1, int64_t(std::max(settings.maxPatches, 1)) / std::max<int64_t>(startingPatches, 1));
}

WavefrontRoundSettings wavefrontRoundSettings(const ViewSetup& setup,
                                              const WavefrontSettings& settings,
                                              const WavefrontPlan& plan) {
    WavefrontRoundSettings r;
    r.maxSteps = plan.maxSteps;
    r.splitVoxels = std::max(settings.splitVoxels, 1e-3f);
    r.maxLevel = std::max(settings.maxLevel, 0);
    r.dt = plan.dt;
    r.integrator = static_cast<int>(settings.integrator);
    r.atCaustic = settings.atCaustic;
    r.samples = std::max(settings.depositSamples, 1);
    r.surfaceSlope = wavefrontSurfaceSlope(setup, settings);
    return r;
}

float wavefrontSurfaceSlope(const ViewSetup& setup, const WavefrontSettings& settings) {
    shared::WavefrontKernelCpu kernel{{{setup.params}}};
    return kernel.anySurfaces() ? std::max(settings.surfaceSlope, 0.0f) : 0.0f;
}

shared::GpuViewParams wavefrontChannelParams(const ViewSetup& setup, int channel) {
    shared::GpuViewParams params = channelViewParams(setup, channel);
    for (int l = 0; l < shared::lightCount(params); ++l)
        for (int k = 0; k < 3; ++k)
            if (k != channel) params.lights[l].radiance[k] = 0.0f;
    return params;
}

namespace {

// One wavefront per light, or under dispersion one per light and colour channel: the params its
// kernel reads (the channel's n, the lights' power in that channel alone) and its ∇n volume.
struct WavefrontPass {
    shared::GpuViewParams params;
    const RefractionVolumeCpu* gradient = nullptr;
};

std::vector<WavefrontPass> wavefrontPasses(const ViewSetup& setup,
                                           const RefractionVolumeCpu& gradient,
                                           const ChannelGradientsCpu* channelGradients) {
    const std::vector<const RefractionVolumeCpu*> gradients =
        channelPassGradientsCpu(setup, gradient, channelGradients, "wavefront");
    if (gradients.size() == 1) return {{setup.params, &gradient}};
    std::vector<WavefrontPass> passes;
    for (int c = 0; c < 3; ++c) passes.push_back({wavefrontChannelParams(setup, c), gradients[c]});
    return passes;
}

// One round of one patch (patchRound), adding its steps and orientation flips.
int tracePatchRound(shared::WavefrontKernelCpu& kernel, const WavefrontRoundSettings& r,
                    shared::GpuWavefrontPatch& p, shared::GpuWavefrontTally& tally, int64_t& steps,
                    int64_t& crossings) {
    int roundSteps = 0, roundCrossings = 0;
    const int state = kernel.patchRound(p, tally, EK_WAVE_ROUND_STEPS, r.maxSteps, r.splitVoxels,
                                        r.maxLevel, r.dt, r.integrator, r.atCaustic, r.samples,
                                        r.surfaceSlope, roundSteps, roundCrossings);
    steps += roundSteps;
    crossings += roundCrossings;
    return state;
}

// Whether a round's outcome ends the patch (not a step cap, not a split request).
bool endedInRound(int state) {
    return state != EK_PHOTON_ACTIVE && state != EK_PATCH_WANTS_SPLIT;
}
}  // namespace

WavefrontResultCpu traceWavefrontsCpu(const ViewSetup& setup,
                                      const std::vector<const DenseGrid*>& slotGrids,
                                      const RefractionVolumeCpu& gradient,
                                      const WavefrontSettings& settings, bool keepPatches,
                                      const ChannelGradientsCpu* channelGradients) {
    const std::vector<WavefrontPass> passes = wavefrontPasses(setup, gradient, channelGradients);
    // One kernel per pass (a deque: the kernels hold their params by reference and must not move).
    std::deque<shared::WavefrontKernelCpu> kernels;
    for (const WavefrontPass& pass : passes) {
        shared::WavefrontKernelCpu& kernel =
            kernels.emplace_back(shared::WavefrontKernelCpu{{{pass.params}}});
        for (size_t s = 0; s < slotGrids.size(); ++s)
            kernel.fields[s] = slotGrids[s]->values.data();
        kernel.gradient = pass.gradient->data();
    }

    WavefrontResultCpu result;
    const WavefrontPlan plan = planWavefronts(setup, settings);
    result.resolution = plan.resolution;

    // The starting patches, pass after pass; the emitted power, summed in index order, sets the
    // fixed-point scales before anything is deposited (as for photons). Under dispersion each
    // pass emits one channel, so the sums and scales are those of one pass carrying all three.
    std::vector<shared::GpuWavefrontPatch> roots;
    std::vector<uint8_t> rootPass;
    for (size_t k = 0; k < passes.size(); ++k) {
        ViewSetup passSetup = setup;
        passSetup.params = passes[k].params;
        const std::vector<shared::GpuWavefrontPatch> generated =
            generatePatchesCpu(passSetup, slotGrids, *passes[k].gradient, settings);
        if (k == 0)
            warnLightsMissingVolume(setup, plan.lights, [&](size_t i) {
                return int(generated[i].state.x) == EK_PHOTON_ACTIVE;
            });
        roots.insert(roots.end(), generated.begin(), generated.end());
        rootPass.insert(rootPass.end(), generated.size(), uint8_t(k));
    }
    std::vector<uint32_t> active;
    for (size_t i = 0; i < roots.size(); ++i) {
        if (int(roots[i].state.x) != EK_PHOTON_ACTIVE) continue;
        const glm::vec3 power(roots[i].power);
        if (passes.size() > 1 && power == glm::vec3(0.0f)) continue;  // a channel the light lacks
        result.totals.emitted += glm::dvec3(power);
        active.push_back(uint32_t(i));
    }
    result.startingPatches = int64_t(active.size());

    FixedDepositsCpu sums(setup, result.totals.emitted);
    for (shared::WavefrontKernelCpu& kernel : kernels) sums.attach(kernel);
    result.fixedPointScale = sums.scale();

    WavefrontCounters counters;
    // The power a patch that has ended leaves: escaped, received or dropped (cut, removed and
    // torn included); a split patch leaves only what it extinguished and reflected, its power
    // going on in its children.
    auto finish = [&](const shared::GpuWavefrontPatch& p, int state,
                      const shared::GpuWavefrontTally& tally) {
        sums.finish(state, glm::vec3(p.power), glm::vec3(tally.lost), state == EK_PATCH_SPLIT);
        sums.addReflected(glm::vec3(tally.reflected));
        if (state == EK_PHOTON_CUT) sums.addCut();
        if (state == EK_PATCH_REMOVED) {
            counters.removed.fetch_add(1, std::memory_order_relaxed);
            sums.addRemoved(glm::vec3(p.power));
        }
        if (state == EK_PATCH_TORN) counters.torn.fetch_add(1, std::memory_order_relaxed);
    };

    const WavefrontRoundSettings round = wavefrontRoundSettings(setup, settings, plan);

    // Pass after pass, its patches in rounds (shared/wavefront_rounds.h), as the GPU traces them.
    std::vector<shared::GpuWavefrontPatch> list, next;
    std::vector<shared::GpuWavefrontTally> tallies, nextTallies;
    std::vector<int> outcome;
    std::vector<int64_t> entry;
    for (size_t pass = 0; pass < passes.size(); ++pass) {
        shared::WavefrontKernelCpu& kernel = kernels[pass];
        list.clear();
        for (uint32_t i : active)
            if (rootPass[i] == pass) list.push_back(roots[i]);
        tallies.assign(list.size(), shared::GpuWavefrontTally{});
        for (size_t r = 0; r < list.size(); ++r) tallies[r].root.x = int(r);
        // Each starting patch's share of the budget, counting itself. Under dispersion each
        // channel's wavefront has the whole budget, so that it is the wavefront a glass of that
        // channel's n makes, whatever the budget.
        const int64_t budget = wavefrontRootBudget(settings, int64_t(list.size()));
        std::vector<int64_t> made(list.size(), 1);
        counters.traced.fetch_add(int64_t(list.size()), std::memory_order_relaxed);
        while (!list.empty()) {
            ++result.rounds;
            result.largestList = std::max(result.largestList, int64_t(list.size()));
            outcome.assign(list.size(), EK_PHOTON_ACTIVE);
            tbb::parallel_for(
                tbb::blocked_range<size_t>(0, list.size(), 16),
                [&](const tbb::blocked_range<size_t>& r) {
                    int64_t steps = 0, crossings = 0;
                    for (size_t i = r.begin(); i != r.end(); ++i) {
                        const int state =
                            tracePatchRound(kernel, round, list[i], tallies[i], steps, crossings);
                        outcome[i] = state;
                        if (!endedInRound(state)) continue;
                        list[i].state.x = float(state);
                        finish(list[i], state, tallies[i]);
                    }
                    sums.addSteps(steps);
                    counters.crossings.fetch_add(crossings, std::memory_order_relaxed);
                });
            // The grants (each starting patch's first requests in list order while its share
            // allows) and the prefix sums: where each patch's entries start in the next list.
            int64_t requests = 0, granted = 0;
            entry.resize(list.size() + 1);
            entry[0] = 0;
            for (size_t i = 0; i < list.size(); ++i) {
                int64_t count = endedInRound(outcome[i]) ? 0 : 1;
                if (outcome[i] == EK_PATCH_WANTS_SPLIT) {
                    ++requests;
                    int64_t& rootMade = made[size_t(tallies[i].root.x)];
                    if (rootMade + 4 <= budget) {
                        rootMade += 4;
                        count = 4;
                        ++granted;
                    }
                }
                entry[i + 1] = entry[i] + count;
            }
            if (keepPatches)  // the ended patches in list order, round after round
                for (size_t i = 0; i < list.size(); ++i)
                    if (endedInRound(outcome[i])) result.patches.push_back(list[i]);
            next.resize(size_t(entry.back()));
            nextTallies.assign(next.size(), shared::GpuWavefrontTally{});
            tbb::parallel_for(
                tbb::blocked_range<size_t>(0, list.size(), 64),
                [&](const tbb::blocked_range<size_t>& r) {
                    for (size_t i = r.begin(); i != r.end(); ++i) {
                        const size_t at = size_t(entry[i]);
                        if (entry[i + 1] - entry[i] == 4) {
                            for (int c = 0; c < 4; ++c) {
                                next[at + c] = kernel.patchChild(list[i], c);
                                nextTallies[at + c].root = tallies[i].root;
                            }
                            finish(list[i], EK_PATCH_SPLIT, tallies[i]);
                            const int level = int(list[i].state.z) + 1;
                            int seen = counters.maxLevel.load(std::memory_order_relaxed);
                            while (level > seen &&
                                   !counters.maxLevel.compare_exchange_weak(seen, level)) {
                            }
                        } else if (entry[i + 1] - entry[i] == 1) {
                            next[at] = list[i];
                            nextTallies[at] = tallies[i];
                            // Refused a split: it goes on unsplit for good.
                            if (outcome[i] == EK_PATCH_WANTS_SPLIT) nextTallies[at].lost.w = 1.0f;
                        }
                    }
                });
            counters.split.fetch_add(granted, std::memory_order_relaxed);
            counters.refused.fetch_add(requests - granted, std::memory_order_relaxed);
            counters.traced.fetch_add(4 * granted, std::memory_order_relaxed);
            list.swap(next);
            tallies.swap(nextTallies);
        }
    }

    sums.readTotals(result.totals);
    result.steps = sums.steps();
    result.patchesCut = sums.cut();
    result.patchesTraced = counters.traced.load();
    result.patchesSplit = counters.split.load();
    result.splitsRefused = counters.refused.load();
    result.patchesRemoved = counters.removed.load();
    result.patchesTorn = counters.torn.load();
    result.causticCrossings = counters.crossings.load();
    result.maxLevelReached = counters.maxLevel.load();

    result.receiverMap = sums.receiverMap(setup);
    sums.readVolumes(result.radiance, result.direction);
    return result;
}

}  // namespace eikon
