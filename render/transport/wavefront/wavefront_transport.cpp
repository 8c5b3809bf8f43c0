#include "render/transport/wavefront/wavefront_transport.h"

#include <algorithm>
#include <cstdio>

#include "core/error.h"
#include "core/memory_limit.h"
#include "render/input_key.h"
#include "render/smoothing.h"
#include "render/transport/deposit_volumes_gpu.h"
#include "render/transport/wavefront/wavefront_tracing_gpu.h"

namespace eikon {
namespace {

using json::Object;
using json::Range;

// Beyond this a light's starting patches alone would take minutes on a CPU.
constexpr std::int64_t kMaxPatchesPerSide = 4096;
// 4^12 descendants per starting patch is far past any volume this runs on.
constexpr std::int64_t kMaxLevel = 12;
// Chords per side of a patch's deposit: 8 × 8 already resolves a patch of several voxels.
constexpr std::int64_t kMaxDepositSamples = 8;
// The patch budget's ceiling: 2^30 patches of a frame.
constexpr std::int64_t kMaxPatchBudget = std::int64_t(1) << 30;

}  // namespace

const std::vector<std::string>& wavefrontIntegratorNames() {
    static const std::vector<std::string> names = {"euler", "midpoint", "rk4"};
    return names;
}

WavefrontTransportSettings readWavefrontTransportSettings(const json::Value* section) {
    WavefrontTransportSettings s;
    if (!section) return s;
    Object object(*section, "the wavefront settings");
    s.where = section->where();
    if (auto side = object.optional("per_side"))
        s.trace.patchesPerSide = static_cast<int>(side->integer(1, kMaxPatchesPerSide));
    if (auto step = object.optional("step_voxels"))
        s.trace.stepVoxels = step->floatNumber(Range::greaterThan(0.0));
    if (auto split = object.optional("split_voxels"))
        s.trace.splitVoxels = split->floatNumber(Range::greaterThan(0.0));
    if (auto level = object.optional("max_level"))
        s.trace.maxLevel = static_cast<int>(level->integer(0, kMaxLevel));
    if (auto budget = object.optional("max_patches"))
        s.trace.maxPatches = static_cast<int>(budget->integer(1, kMaxPatchBudget));
    if (auto threshold = object.optional("flux_threshold"))
        s.trace.fluxThreshold = threshold->floatNumber(Range::closedOpen(0.0, 1.0));
    if (auto caustic = object.optional("at_caustic"))
        s.trace.atCaustic =
            caustic->choice({"keep", "remove"}) == "keep" ? EK_WAVEFRONT_KEEP : EK_WAVEFRONT_REMOVE;
    if (auto samples = object.optional("deposit_samples"))
        s.trace.depositSamples = static_cast<int>(samples->integer(1, kMaxDepositSamples));
    if (auto fresnel = object.optional("fresnel"))
        if (!fresnel->boolean()) s.trace.surfaceSlope = 0.0f;
    if (auto slope = object.optional("surface_slope")) {
        if (s.trace.surfaceSlope == 0.0f) slope->fail("\"surface_slope\" needs \"fresnel\": true");
        s.trace.surfaceSlope = slope->floatNumber(Range::greaterThan(0.0));
    }
    if (auto integrator = object.optional("integrator")) {
        const std::string name = integrator->choice(wavefrontIntegratorNames());
        s.trace.integrator = name == "euler"      ? WavefrontIntegrator::Euler
                             : name == "midpoint" ? WavefrontIntegrator::Midpoint
                                                  : WavefrontIntegrator::Rk4;
    }
    object.finish();
    return s;
}

WavefrontTransport::WavefrontTransport(WavefrontTransportSettings settings, TransportDevice device)
    : settings_(std::move(settings)), device_(device) {}

WavefrontTransport::~WavefrontTransport() = default;

TransportNeeds WavefrontTransport::needs() const {
    // Particles advance by a fixed optical time: no octree, only ∇n.
    TransportNeeds n;
    n.gradient = true;
    n.octree = false;
    return n;
}

void WavefrontTransport::configure(const Scene& scene, ViewSetup& setup) {
    if (!lightAllThroughFluence(scene, setup)) return;
    // The starting patches, and the two lists of a pass's rounds: at most the budget's patches
    // live at once (each was made, and a pass makes at most the budget, or one per starting
    // patch where there are more), each with its tally (shared/wavefront_rounds.h).
    const WavefrontPlan plan = planWavefronts(setup, settings_.trace);
    const double live = std::max(double(settings_.trace.maxPatches), double(plan.patches));
    const std::string where =
        settings_.where.empty() ? scene.path + ":/render/light_transport" : settings_.where;
    checkMemory(where,
                double(plan.patches) * double(sizeof(shared::GpuWavefrontEntry)) +
                    2.0 * live * double(sizeof(shared::GpuWavefrontEntry)),
                std::to_string(plan.patches) + " starting patches (" +
                    std::to_string(settings_.trace.patchesPerSide) + " per side) and lists of " +
                    std::to_string(settings_.trace.maxPatches) + " patches (max_patches)",
                "lower per_side or max_patches");
}

std::vector<unsigned char> WavefrontTransport::cacheKey(
    const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids) const {
    if (!shared::readsFluence(setup.params)) return {};
    std::vector<unsigned char> key = transportInputsKey(setup, slotGrids);
    appendReceiverMapsKey(setup, key);  // patches stop on receivers and fill their maps
    // Every member is 4 bytes: the struct has no padding to carry stale bytes into the key.
    static_assert(sizeof(WavefrontSettings) == 11 * 4,
                  "WavefrontSettings gained padding or a member");
    appendBytes(key, &settings_.trace, sizeof(settings_.trace));
    // Each channel's wavefront bends with its own n under dispersion.
    for (const glm::vec3& slopes : setup.channelIndexSlopes)
        appendBytes(key, &slopes, sizeof(slopes));
    return key;
}

void WavefrontTransport::runCpu(const TransportInputsCpu& in) {
    StageScope stage(in.timer, "wavefront");
    WavefrontResultCpu traced = traceWavefrontsCpu(in.setup, in.slotGrids, in.gradient,
                                                   settings_.trace, false, in.channelGradients);
    cpu_ = PhotonVolumes{};
    cpu_.radiance = smoothVolumeCpu(traced.radiance, traced.resolution);
    cpu_.direction = smoothVolumeCpu(traced.direction, traced.resolution);
    cpu_.receiverMap = std::move(traced.receiverMap);
    setResult(traced);
}

void WavefrontTransport::runGpu(const TransportInputsGpu& in) {
    if (!gpu_) {
        gpu_ = std::make_unique<WavefrontTracerGpu>(device_.exactMath);
        volumesGpu_ = std::make_unique<DepositVolumesGpu>();
    }
    gpu_->trace(in.setup, in.fields, in.refraction, settings_.trace, in.timer, in.dispersion);
    const shared::GpuViewParams& p = in.setup.params;
    volumesGpu_->compute(glm::ivec3(p.resolution.x, p.resolution.y, p.resolution.z),
                         gpu_->depositBuffer(), gpu_->fixedPointScale(), gpu_->receiverMap(),
                         in.timer);
    // The counts and the energy account: 192 bytes read back, for --stats and the benches.
    setResult(gpu_->counts());
}

void WavefrontTransport::bindGpu() const {
    if (volumesGpu_) volumesGpu_->bind();
}

void WavefrontTransport::setResult(const WavefrontResultCpu& traced) {
    cpu_.totals = traced.totals;
    cpu_.steps = traced.steps;
    cpu_.photonsTraced = traced.patchesTraced;
    cpu_.photonsCut = traced.patchesCut;
    cpu_.rounds = traced.rounds;
    stats_ = TransportStats{};
    stats_.steps = traced.steps;
    stats_.particlesTraced = traced.patchesTraced;
    stats_.particlesCut = traced.patchesCut;
    stats_.particlesSplit = traced.patchesSplit;
    stats_.splitsRefused = traced.splitsRefused;
    stats_.particlesTorn = traced.patchesTorn;
    stats_.particlesRemoved = traced.patchesRemoved;
    stats_.rounds = traced.rounds;
}

PhotonVolumes WavefrontTransport::volumes() const {
    if (!device_.gpu || !volumesGpu_) return cpu_;
    PhotonVolumes v = cpu_;
    v.radiance = volumesGpu_->radiance();
    v.direction = volumesGpu_->direction();
    v.receiverMap = gpu_->receiverMap();
    return v;
}

TransportOutputCpu WavefrontTransport::outputCpu() const {
    return transportOutputOf(cpu_);
}

std::optional<EnergyBalance> WavefrontTransport::energy() const {
    const PhotonTotals& t = cpu_.totals;
    return EnergyBalance{t.emitted,  t.extinguished, t.escaped,  t.dropped,
                         t.received, t.removed,      t.reflected};
}

std::string WavefrontTransport::previewPatch() const {
    char patch[64];
    std::snprintf(patch, sizeof(patch), R"({"wavefront": {"split_voxels": %.9g}})",
                  double(settings_.trace.splitVoxels) * 2.0);
    return patch;
}

}  // namespace eikon
