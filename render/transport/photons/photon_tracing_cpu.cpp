#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "render/transport/channel_passes.h"
#include "render/transport/photons/fixed_deposits_cpu.h"
#include "render/transport/photons/lights_missing_volume.h"
#include "render/transport/photons/photon_tracing.h"

namespace eikon {

std::vector<PhotonLightPlan> planLightGrids(const ViewSetup& setup, int side, size_t& particles) {
    // The layouts come from the shared code, run here once: the GPU is told them rather than
    // deciding again, so that a last-bit difference can never change a particle count.
    shared::PhotonKernelCpu kernel{{setup.params}};
    const size_t perGrid = size_t(side) * size_t(side);
    std::vector<PhotonLightPlan> lights;
    particles = 0;
    for (int l = 0; l < shared::lightCount(setup.params); ++l) {
        PhotonLightPlan light;
        light.light = l;
        light.grid = kernel.photonGrid(l);
        light.first = particles;
        light.count = size_t(kernel.photonGridFaces(light.grid)) * perGrid;
        particles += light.count;
        lights.push_back(light);
    }
    return lights;
}

PhotonPlan planPhotons(const ViewSetup& setup, const PhotonSettings& settings) {
    PhotonPlan plan;
    plan.resolution = glm::ivec3(setup.params.resolution);
    const glm::ivec3 res = plan.resolution;
    plan.voxels = size_t(res.x) * size_t(res.y) * size_t(res.z);
    plan.side = std::max(settings.photonsPerSide, 1);
    plan.lights = planLightGrids(setup, plan.side, plan.photons);
    plan.minStep = octreeStepInScene(setup, settings.minStepVoxels);
    // By default a photon may cross the volume 16 times at the minimum step (a trapped path).
    plan.maxSteps = settings.maxSteps > 0 ? settings.maxSteps
                                          : int(std::ceil(16.0f * float(res.x + res.y + res.z) /
                                                          std::max(settings.minStepVoxels, 1e-3f)));
    plan.stepsPerRound = settings.stepsPerRound > 0
                             ? std::min(settings.stepsPerRound, plan.maxSteps)
                             : plan.maxSteps;
    plan.rounds = (plan.maxSteps + plan.stepsPerRound - 1) / plan.stepsPerRound;
    plan.stopFraction = std::max(settings.stopFraction, 0.0f);
    return plan;
}

int photonRoundSteps(const PhotonPlan& plan, int round) {
    return std::min(plan.stepsPerRound, plan.maxSteps - round * plan.stepsPerRound);
}

int64_t photonStopCount(const PhotonPlan& plan, int64_t photonsTraced) {
    return int64_t(std::ceil(double(plan.stopFraction) * double(photonsTraced)));
}

std::vector<shared::GpuPhoton> generatePhotonsCpu(const ViewSetup& setup,
                                                  const RefractionVolumeCpu& gradient,
                                                  const PhotonSettings& settings) {
    shared::PhotonKernelCpu kernel{{setup.params}};
    kernel.gradient = gradient.data();
    const PhotonPlan plan = planPhotons(setup, settings);
    std::vector<shared::GpuPhoton> photons(plan.photons);
    for (const PhotonLightPlan& light : plan.lights) {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, light.count, 256),
                          [&](const tbb::blocked_range<size_t>& r) {
                              for (size_t i = r.begin(); i != r.end(); ++i)
                                  photons[light.first + i] = kernel.generatePhoton(
                                      light.light, light.grid, plan.side, int(i),
                                      glm::uint(settings.seed), glm::uint(settings.frame),
                                      settings.fluxThreshold);
                          });
    }
    return photons;
}

namespace {

// Bits of x spread to every third bit (a 30-bit Morton code from three 10-bit coordinates).
uint32_t spreadBits3(uint32_t x) {
    x &= 0x3FF;
    x = (x | (x << 16)) & 0x030000FF;
    x = (x | (x << 8)) & 0x0300F00F;
    x = (x | (x << 4)) & 0x030C30C3;
    x = (x | (x << 2)) & 0x09249249;
    return x;
}

// The active photons' indices, ordered by the Morton code of the voxel each starts in (ties by
// index). Photons that start near each other walk near each other, so marching them one after
// another finds the voxels they read and deposit into in the cache: at 128³ / 512² photons the
// march took 0.8× the time. Only the order of the march changes: photons are independent and
// their deposits integer sums, so the results do not.
std::vector<uint32_t> activePhotonsInSpaceOrder(shared::PhotonKernelCpu& kernel,
                                                const std::vector<shared::GpuPhoton>& photons) {
    const glm::ivec3 res = kernel.volumeResolution();
    int shift = 0;  // coordinates to 10 bits: past 1024 voxels a side, cells of 2^shift voxels
    while ((std::max({res.x, res.y, res.z}) - 1) >> shift >= 1024) ++shift;
    std::vector<std::pair<uint32_t, uint32_t>> keyed;
    for (size_t i = 0; i < photons.size(); ++i) {
        if (int(photons[i].position.w) != EK_PHOTON_ACTIVE) continue;
        // An active photon starts in the box (or on its faces); the clamp (NaN to 0) keeps any
        // float a voxel.
        const glm::vec3 p = kernel.worldToVolumeIndex(glm::vec3(photons[i].position));
        glm::uvec3 v(0u);
        for (int k = 0; k < 3; ++k)
            if (p[k] >= 0.0f) v[k] = uint32_t(std::min(p[k], float(res[k] - 1))) >> shift;
        keyed.emplace_back(spreadBits3(v.x) | (spreadBits3(v.y) << 1) | (spreadBits3(v.z) << 2),
                           uint32_t(i));
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<uint32_t> order(keyed.size());
    for (size_t i = 0; i < keyed.size(); ++i) order[i] = keyed[i].second;
    return order;
}

// Step 5 for one pass: the march in rounds (PhotonSettings::stepsPerRound), as on the GPU: each
// round marches the active photons by one task per photon, then the ones still active are
// compacted into the next round's list. A photon's extinguished flux is carried over the rounds,
// so that its bookkeeping is the same float sum as in one uninterrupted march. Returns the rounds
// that had photons.
int marchPhotonsCpu(shared::PhotonKernelCpu& kernel, const PhotonPlan& plan, int integrator,
                    int64_t photonsTraced, FixedDepositsCpu& sums,
                    std::vector<shared::GpuPhoton>& photons) {
    std::vector<glm::vec3> extinguished(photons.size(), glm::vec3(0.0f));
    // The flux a photon that has ended leaves: escaped, received or dropped (cut included), in
    // the channels this pass deposits.
    auto finish = [&](const shared::GpuPhoton& p, glm::vec3 lost) {
        const int state = int(p.position.w);
        sums.finish(state, glm::vec3(p.flux) * kernel.photonChannels, lost * kernel.photonChannels);
        sums.addSteps(int64_t(p.direction.w));
        if (state == EK_PHOTON_CUT) sums.addCut();
    };
    std::vector<uint32_t> active = activePhotonsInSpaceOrder(kernel, photons);
    const int64_t stopCount = photonStopCount(plan, photonsTraced);
    bool stop = false;  // the stop rule fired: this round cuts instead of marching
    int rounds = 0;
    for (int round = 0; round < plan.rounds && !active.empty(); ++round) {
        const int steps = photonRoundSteps(plan, round);
        const bool last = round == plan.rounds - 1;
        tbb::parallel_for(tbb::blocked_range<size_t>(0, active.size(), 16),
                          [&](const tbb::blocked_range<size_t>& r) {
                              for (size_t k = r.begin(); k != r.end(); ++k) {
                                  const uint32_t i = active[k];
                                  shared::GpuPhoton& p = photons[i];
                                  if (!stop)
                                      kernel.marchPhoton(p, plan.minStep, integrator, steps,
                                                         extinguished[i]);
                                  const bool still = int(p.position.w) == EK_PHOTON_ACTIVE;
                                  if (still && !stop && !last) continue;
                                  if (still) p.position.w = float(EK_PHOTON_CUT);
                                  finish(p, extinguished[i]);
                              }
                          });
        ++rounds;
        if (stop) break;
        // Compaction; in the march's order here, in any order on the GPU (photons are independent).
        active.erase(std::remove_if(active.begin(), active.end(),
                                    [&](uint32_t i) {
                                        return int(photons[i].position.w) != EK_PHOTON_ACTIVE;
                                    }),
                     active.end());
        stop = int64_t(active.size()) < stopCount;
    }
    return rounds;
}

}  // namespace

PhotonResultCpu traceLightPhotonsCpu(const ViewSetup& setup,
                                     const std::vector<const DenseGrid*>& slotGrids,
                                     const RefractionVolumeCpu& gradient,
                                     const RefractionVolumeCpu& octree,
                                     const PhotonSettings& settings,
                                     const ChannelGradientsCpu* channelGradients) {
    shared::PhotonKernelCpu kernel{{setup.params}};
    for (size_t s = 0; s < slotGrids.size(); ++s) kernel.fields[s] = slotGrids[s]->values.data();
    kernel.octree = octree.data();
    const std::vector<const RefractionVolumeCpu*> gradients =
        channelPassGradientsCpu(setup, gradient, channelGradients, "photons");
    const int passes = int(gradients.size());

    PhotonResultCpu result;
    const PhotonPlan plan = planPhotons(setup, settings);
    result.resolution = plan.resolution;
    const int integrator = static_cast<int>(settings.integrator);

    // Step 4: generate every light's photons; the emitted power, summed in index order, sets the
    // fixed-point scales before anything is deposited. A photon's flux and whether it enters the
    // box do not depend on n, so every pass emits these photons' power, one channel each.
    std::vector<shared::GpuPhoton> photons = generatePhotonsCpu(setup, gradient, settings);
    warnLightsMissingVolume(setup, plan.lights, [&](size_t i) {
        return int(photons[i].position.w) == EK_PHOTON_ACTIVE;
    });
    int64_t tracedPerPass = 0;
    for (const shared::GpuPhoton& p : photons) {
        if (int(p.position.w) != EK_PHOTON_ACTIVE) continue;
        result.totals.emitted += glm::dvec3(glm::vec3(p.flux));
        ++tracedPerPass;
    }

    FixedDepositsCpu sums(setup, result.totals.emitted);
    sums.attach(kernel);
    result.fixedPointScale = sums.scale();

    for (int pass = 0; pass < passes; ++pass) {
        kernel.gradient = gradients[pass]->data();
        // The fields and this pass's ∇n where they hold one value (render/constant_bricks.h):
        // a step's samples there fetch no corners.
        std::optional<ConstantBricks> constant;
        if (constantBricksEnabled()) {
            constant.emplace(glm::ivec3(setup.params.resolution));
            for (size_t s = 0; s < slotGrids.size(); ++s)
                constant->addField(int(s), kernel.fields[s]);
            constant->addVolume(EK_GRADIENT_SLOT, kernel.gradient);
        }
        kernel.constantBricks = constant ? &*constant : nullptr;
        kernel.photonChannels = channelPassMask(pass, passes);
        // Each channel's photons start with its own n (v = n·d).
        if (pass > 0 || gradients[pass] != &gradient)
            photons = generatePhotonsCpu(setup, *gradients[pass], settings);
        result.rounds += marchPhotonsCpu(kernel, plan, integrator, tracedPerPass, sums, photons);
        result.photons.insert(result.photons.end(), photons.begin(), photons.end());
        kernel.constantBricks = nullptr;
    }
    result.photonsTraced = tracedPerPass * passes;

    sums.readTotals(result.totals);
    result.steps = sums.steps();
    result.photonsCut = sums.cut();
    result.receiverMap = sums.receiverMap(setup);
    sums.readVolumes(result.radiance, result.direction);
    return result;
}

}  // namespace eikon
