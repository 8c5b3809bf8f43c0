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
    for (int c = 0; c < 3; ++c) {
        WavefrontPass pass{channelViewParams(setup, c), gradients[c]};
        for (int l = 0; l < shared::lightCount(pass.params); ++l)
            for (int k = 0; k < 3; ++k)
                if (k != c) pass.params.lights[l].radiance[k] = 0.0f;
        passes.push_back(pass);
    }
    return passes;
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
    // torn included); a split patch leaves only what it extinguished, its power going to its
    // children.
    auto finish = [&](const shared::GpuWavefrontPatch& p, int state, glm::vec3 lost,
                      glm::vec3 reflected) {
        sums.finish(state, glm::vec3(p.power), lost, state == EK_PATCH_SPLIT);
        sums.addReflected(reflected);
        if (state == EK_PHOTON_CUT) sums.addCut();
        if (state == EK_PATCH_REMOVED) {
            counters.removed.fetch_add(1, std::memory_order_relaxed);
            sums.addRemoved(glm::vec3(p.power));
        }
        if (state == EK_PATCH_TORN) counters.torn.fetch_add(1, std::memory_order_relaxed);
    };

    const int integrator = static_cast<int>(settings.integrator);
    const float splitVoxels = std::max(settings.splitVoxels, 1e-3f);
    const int maxLevel = std::max(settings.maxLevel, 0);
    const int samples = std::max(settings.depositSamples, 1);
    const float surfaceSlope =
        kernels.front().anySurfaces() ? std::max(settings.surfaceSlope, 0.0f) : 0.0f;
    // Each starting patch's share of the patch budget, counting itself. Under dispersion each
    // channel's wavefront has the whole budget, so that it is the wavefront a glass of that
    // channel's n makes, whatever the budget.
    std::vector<int64_t> activeInPass(passes.size(), 0);
    for (uint32_t i : active) ++activeInPass[rootPass[i]];
    std::vector<int64_t> budgets;
    for (int64_t count : activeInPass)
        budgets.push_back(std::max<int64_t>(
            1, int64_t(std::max(settings.maxPatches, 1)) / std::max<int64_t>(count, 1)));
    std::vector<std::vector<shared::GpuWavefrontPatch>> kept(keepPatches ? active.size() : 0);

    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, active.size(), 4), [&](const tbb::blocked_range<size_t>& r) {
            std::vector<shared::GpuWavefrontPatch> stack;
            for (size_t k = r.begin(); k != r.end(); ++k) {
                int64_t made = 1, steps = 0, splits = 0, refused = 0, crossings = 0;
                int deepest = 0;
                shared::WavefrontKernelCpu& kernel = kernels[rootPass[active[k]]];
                const int64_t budget = budgets[rootPass[active[k]]];
                stack.assign(1, roots[active[k]]);
                while (!stack.empty()) {
                    shared::GpuWavefrontPatch p = stack.back();
                    stack.pop_back();
                    glm::vec3 lost(0.0f);
                    glm::vec3 reflected(0.0f);
                    int state = EK_PHOTON_ACTIVE;
                    bool wasRefused = false;  // counted once per patch, not per step
                    while (state == EK_PHOTON_ACTIVE) {
                        if (int(p.state.y) >= plan.maxSteps) {
                            state = EK_PHOTON_CUT;
                            break;
                        }
                        if (kernel.patchNeedsSplit(p, splitVoxels)) {
                            if (int(p.state.z) >= maxLevel) {
                                state = EK_PATCH_TORN;
                                break;
                            }
                            if (made + 4 <= budget) {
                                // Children pushed last to first, so child 0 is traced next.
                                for (int c = 3; c >= 0; --c)
                                    stack.push_back(kernel.patchChild(p, c));
                                made += 4;
                                ++splits;
                                deepest = std::max(deepest, int(p.state.z) + 1);
                                state = EK_PATCH_SPLIT;
                                break;
                            }
                            refused += wasRefused ? 0 : 1;
                            wasRefused = true;
                        }
                        const float sign = p.state.w;
                        state = kernel.patchStep(p, plan.dt, integrator, settings.atCaustic,
                                                 samples, surfaceSlope, lost, reflected);
                        ++steps;
                        if (p.state.w != sign || state == EK_PATCH_REMOVED) ++crossings;
                    }
                    p.state.x = float(state);
                    finish(p, state, lost, reflected);
                    if (keepPatches && state != EK_PATCH_SPLIT) kept[k].push_back(p);
                }
                sums.addSteps(steps);
                counters.traced.fetch_add(made, std::memory_order_relaxed);
                counters.split.fetch_add(splits, std::memory_order_relaxed);
                counters.refused.fetch_add(refused, std::memory_order_relaxed);
                counters.crossings.fetch_add(crossings, std::memory_order_relaxed);
                int seen = counters.maxLevel.load(std::memory_order_relaxed);
                while (deepest > seen && !counters.maxLevel.compare_exchange_weak(seen, deepest)) {
                }
            }
        });

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
    for (auto& patches : kept)
        result.patches.insert(result.patches.end(), patches.begin(), patches.end());

    result.receiverMap = sums.receiverMap(setup);
    sums.readVolumes(result.radiance, result.direction);
    return result;
}

}  // namespace eikon
