#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "render/receiver_map.h"
#include "render/transport/photons/photon_tracing.h"
#include "render/volume_kernels_cpu.h"

EK_NAMESPACE_BEGIN

// What the photon shaders will see: the field and ∇n volumes, the octree volume, and the
// radiance volume as integer accumulators (kDepositChannels per voxel: r, g, b, then the
// weighted direction x, y, z).
struct PhotonKernelCpu : VolumeAccessCpu {
    static constexpr int kDepositChannels = 6;
    const vec4* octree = nullptr;
    std::atomic<int64_t>* deposits = nullptr;
    dvec4 scale = dvec4(0.0);                          // rgb: flux·length channels; w: direction
    std::atomic<int64_t>* receiverDeposits = nullptr;  // 3 per receiver map texel: r, g, b
    dvec3 receiverScale = dvec3(0.0);                  // the totals' per-channel scales

    vec4 fetchOctree(ivec3 v) const { return octree[voxelIndex(v)]; }

    static int64_t toFixed(double value, double scale) {
        // Clamped so that no input can make the conversion undefined; at the documented scale a
        // single deposit never comes near this.
        const double limit = 4.0e18;
        return int64_t(std::llround(std::clamp(value * scale, -limit, limit)));
    }

    void depositVoxel(ivec3 v, vec3 fluxLength, vec3 weightedDir) const {
        std::atomic<int64_t>* cell = deposits + voxelIndex(v) * kDepositChannels;
        // Integer addition commutes exactly: the sum is the same in any order, on any thread.
        for (int c = 0; c < 3; ++c) {
            cell[c].fetch_add(toFixed(fluxLength[c], scale[c]), std::memory_order_relaxed);
            cell[3 + c].fetch_add(toFixed(weightedDir[c], scale.w), std::memory_order_relaxed);
        }
    }

    void depositReceiverTexel(int index, vec3 flux) const {
        std::atomic<int64_t>* texel = receiverDeposits + size_t(index) * 3;
        for (int c = 0; c < 3; ++c)
            texel[c].fetch_add(toFixed(flux[c], receiverScale[c]), std::memory_order_relaxed);
    }

    // clang-format off
#include "shaders/shared/photons.h"
    // clang-format on
};

EK_NAMESPACE_END

namespace eikon {

namespace {

constexpr double kFixedPointRange =
    1099511627776.0;  // 2^40, see render/transport/photons/photon_tracing.h

double luminance(glm::dvec3 c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// Order-independent totals: per-photon values in fixed point, summed as integers.
struct FixedTotals {
    std::atomic<int64_t> escaped[3] = {};
    std::atomic<int64_t> extinguished[3] = {};
    std::atomic<int64_t> dropped[3] = {};
    std::atomic<int64_t> received[3] = {};
    std::atomic<int64_t> steps{0};
    std::atomic<int64_t> cut{0};
};

}  // namespace

PhotonPlan planPhotons(const ViewSetup& setup, const PhotonSettings& settings) {
    PhotonPlan plan;
    plan.resolution = glm::ivec3(setup.params.resolution);
    const glm::ivec3 res = plan.resolution;
    plan.voxels = size_t(res.x) * size_t(res.y) * size_t(res.z);
    plan.side = std::max(settings.photonsPerSide, 1);
    // The layouts come from the shared code, run here once: the GPU is told them rather than
    // deciding again, so that a last-bit difference can never change a photon count.
    shared::PhotonKernelCpu kernel{{setup.params}};
    const size_t perGrid = size_t(plan.side) * size_t(plan.side);
    for (int l = 0; l < shared::lightCount(setup.params); ++l) {
        PhotonLightPlan light;
        light.light = l;
        light.grid = kernel.photonGrid(l);
        light.first = plan.photons;
        light.count = size_t(kernel.photonGridFaces(light.grid)) * perGrid;
        plan.photons += light.count;
        plan.lights.push_back(light);
    }
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

PhotonResultCpu traceLightPhotonsCpu(const ViewSetup& setup,
                                     const std::vector<const DenseGrid*>& slotGrids,
                                     const RefractionVolumeCpu& gradient,
                                     const RefractionVolumeCpu& octree,
                                     const PhotonSettings& settings) {
    shared::PhotonKernelCpu kernel{{setup.params}};
    for (size_t s = 0; s < slotGrids.size(); ++s) kernel.fields[s] = slotGrids[s]->values.data();
    kernel.gradient = gradient.data();
    kernel.octree = octree.data();

    PhotonResultCpu result;
    const PhotonPlan plan = planPhotons(setup, settings);
    result.resolution = plan.resolution;
    const size_t voxels = plan.voxels;
    const float minStep = plan.minStep;
    const int integrator = static_cast<int>(settings.integrator);

    // Step 4: generate every light's photons; the emitted power, summed in index order, sets the
    // fixed-point scales before anything is deposited.
    result.photons = generatePhotonsCpu(setup, gradient, settings);
    for (const shared::GpuPhoton& p : result.photons) {
        if (int(p.position.w) != EK_PHOTON_ACTIVE) continue;
        result.totals.emitted += glm::dvec3(glm::vec3(p.flux));
        ++result.photonsTraced;
    }

    const glm::vec3 h = kernel.volumeVoxelSize();
    const double smallestVoxel = double(std::min({h.x, h.y, h.z}));
    const glm::dvec3& emitted = result.totals.emitted;
    auto scaleFor = [](double power, double length) {
        return power > 0.0 ? kFixedPointRange / (power * length) : 0.0;
    };
    kernel.scale =
        glm::dvec4(scaleFor(emitted.x, smallestVoxel), scaleFor(emitted.y, smallestVoxel),
                   scaleFor(emitted.z, smallestVoxel), scaleFor(luminance(emitted), smallestVoxel));
    result.fixedPointScale = kernel.scale;
    const glm::dvec3 totalScale(scaleFor(emitted.x, 1.0), scaleFor(emitted.y, 1.0),
                                scaleFor(emitted.z, 1.0));

    // std::atomic's default constructor leaves the value unset before C++20: zero explicitly.
    const size_t depositCount = voxels * size_t(shared::PhotonKernelCpu::kDepositChannels);
    std::unique_ptr<std::atomic<int64_t>[]> deposits(new std::atomic<int64_t>[depositCount]);
    for (size_t i = 0; i < depositCount; ++i) deposits[i].store(0, std::memory_order_relaxed);
    kernel.deposits = deposits.get();
    const size_t receiverSums = 3 * receiverMapTexels(setup.params);
    std::unique_ptr<std::atomic<int64_t>[]> receiverDeposits(
        new std::atomic<int64_t>[std::max<size_t>(receiverSums, 1)]);
    for (size_t i = 0; i < receiverSums; ++i)
        receiverDeposits[i].store(0, std::memory_order_relaxed);
    kernel.receiverDeposits = receiverDeposits.get();
    kernel.receiverScale = totalScale;

    // Step 5: the march in rounds (PhotonSettings::stepsPerRound), as on the GPU: each round
    // marches the active photons by one task per photon, then the ones still active are
    // compacted into the next round's list. A photon's extinguished flux is carried over the
    // rounds, so that its bookkeeping is the same float sum as in one uninterrupted march.
    FixedTotals totals;
    std::vector<glm::vec3> extinguished(result.photons.size(), glm::vec3(0.0f));
    // The flux a photon that has ended leaves: escaped, received or dropped (cut included).
    auto finish = [&](const shared::GpuPhoton& p, glm::vec3 lost) {
        const int state = int(p.position.w);
        const glm::vec3 left(p.flux);
        for (int c = 0; c < 3; ++c) {
            totals.extinguished[c].fetch_add(
                shared::PhotonKernelCpu::toFixed(lost[c], totalScale[c]),
                std::memory_order_relaxed);
            std::atomic<int64_t>& bin = state == EK_PHOTON_ESCAPED    ? totals.escaped[c]
                                        : state == EK_PHOTON_RECEIVED ? totals.received[c]
                                                                      : totals.dropped[c];
            bin.fetch_add(shared::PhotonKernelCpu::toFixed(left[c], totalScale[c]),
                          std::memory_order_relaxed);
        }
        totals.steps.fetch_add(int64_t(p.direction.w), std::memory_order_relaxed);
        if (state == EK_PHOTON_CUT) totals.cut.fetch_add(1, std::memory_order_relaxed);
    };
    std::vector<uint32_t> active;
    for (size_t i = 0; i < result.photons.size(); ++i)
        if (int(result.photons[i].position.w) == EK_PHOTON_ACTIVE) active.push_back(uint32_t(i));
    const int64_t stopCount = photonStopCount(plan, result.photonsTraced);
    bool stop = false;  // the stop rule fired: this round cuts instead of marching
    for (int round = 0; round < plan.rounds && !active.empty(); ++round) {
        const int steps = photonRoundSteps(plan, round);
        const bool last = round == plan.rounds - 1;
        tbb::parallel_for(tbb::blocked_range<size_t>(0, active.size(), 16),
                          [&](const tbb::blocked_range<size_t>& r) {
                              for (size_t k = r.begin(); k != r.end(); ++k) {
                                  const uint32_t i = active[k];
                                  shared::GpuPhoton& p = result.photons[i];
                                  if (!stop)
                                      kernel.marchPhoton(p, minStep, integrator, steps,
                                                         extinguished[i]);
                                  const bool still = int(p.position.w) == EK_PHOTON_ACTIVE;
                                  if (still && !stop && !last) continue;
                                  if (still) p.position.w = float(EK_PHOTON_CUT);
                                  finish(p, extinguished[i]);
                              }
                          });
        ++result.rounds;
        if (stop) break;
        // Compaction; in index order here, in any order on the GPU (photons are independent).
        active.erase(
            std::remove_if(
                active.begin(), active.end(),
                [&](uint32_t i) { return int(result.photons[i].position.w) != EK_PHOTON_ACTIVE; }),
            active.end());
        stop = int64_t(active.size()) < stopCount;
    }

    auto fromFixed = [](int64_t q, double scale) { return scale > 0.0 ? double(q) / scale : 0.0; };
    for (int c = 0; c < 3; ++c) {
        result.totals.escaped[c] = fromFixed(totals.escaped[c].load(), totalScale[c]);
        result.totals.extinguished[c] = fromFixed(totals.extinguished[c].load(), totalScale[c]);
        result.totals.dropped[c] = fromFixed(totals.dropped[c].load(), totalScale[c]);
        result.totals.received[c] = fromFixed(totals.received[c].load(), totalScale[c]);
    }
    result.steps = totals.steps.load();
    result.photonsCut = totals.cut.load();

    std::vector<int64_t> sums(receiverSums);
    for (size_t i = 0; i < receiverSums; ++i) sums[i] = receiverDeposits[i].load();
    result.receiverMap = receiverMapFromFixed(setup.params, sums, totalScale);

    result.radiance.resize(voxels);
    result.direction.resize(voxels);
    const glm::dvec4 scale = kernel.scale;
    for (size_t i = 0; i < voxels; ++i) {
        const std::atomic<int64_t>* cell = &deposits[i * shared::PhotonKernelCpu::kDepositChannels];
        for (int c = 0; c < 3; ++c) {
            result.radiance[i][c] = float(fromFixed(cell[c].load(), scale[c]));
            result.direction[i][c] = float(fromFixed(cell[3 + c].load(), scale.w));
        }
    }
    return result;
}

}  // namespace eikon
