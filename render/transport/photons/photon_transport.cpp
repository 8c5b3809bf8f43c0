#include "render/transport/photons/photon_transport.h"

#include <algorithm>
#include <string>

#include <glm/vector_relational.hpp>

#include "core/memory_limit.h"
#include "render/input_key.h"
#include "render/receiver_map.h"
#include "render/transport/channel_passes.h"

namespace eikon {
namespace {

using json::Object;
using json::Range;

// Photons per side beyond this would take minutes per light on a CPU and overflow int indices.
constexpr std::int64_t kMaxPhotonsPerSide = 8192;
// More steps per round than any step cap (16 crossings of an 8192-voxel box): one round.
constexpr std::int64_t kMaxStepsPerRound = 1 << 20;

}  // namespace

PhotonTransportSettings readPhotonTransportSettings(const json::Value* section) {
    PhotonTransportSettings s;
    if (!section) return s;
    Object object(*section, "the photon settings");
    s.where = section->where();
    if (auto side = object.optional("per_side"))
        s.trace.photonsPerSide = static_cast<int>(side->integer(1, kMaxPhotonsPerSide));
    if (auto step = object.optional("min_step_voxels"))
        s.trace.minStepVoxels = step->floatNumber(Range::greaterThan(0.0));
    if (auto integrator = object.optional("integrator"))
        s.trace.integrator = rayIntegratorNamed(integrator->choice(rayIntegratorNames()));
    if (auto threshold = object.optional("flux_threshold"))
        s.trace.fluxThreshold = threshold->floatNumber(Range::closedOpen(0.0, 1.0));
    if (auto fraction = object.optional("stop_fraction"))
        s.trace.stopFraction = fraction->floatNumber(Range::closedOpen(0.0, 1.0));
    if (auto steps = object.optional("steps_per_round"))
        s.trace.stepsPerRound = static_cast<int>(steps->integer(1, kMaxStepsPerRound));
    if (auto step = object.optional("max_step_voxels"))
        s.maxStepVoxels = step->floatNumber(Range::greaterThan(0.0));
    if (auto kappa = object.optional("kappa_tolerance"))
        s.kappaTolerance = kappa->floatNumber(Range::atLeast(0.0));
    object.finish();
    return s;
}

PhotonTransport::PhotonTransport(PhotonTransportSettings settings, TransportDevice device)
    : settings_(settings), device_(device) {}

PhotonTransport::~PhotonTransport() = default;

TransportNeeds PhotonTransport::needs() const {
    // Photons march through the ∇n and octree volumes even where n ≡ 1 (their steps then grow
    // to the octree's limit).
    TransportNeeds n;
    n.gradient = true;
    n.octree = true;
    n.octreeSettings.kappaTolerance = settings_.kappaTolerance;
    // Near strong variation of n the octree caps steps at the photons' own minimum step, so that
    // min_step_voxels sets the step there (with a cap of 1 voxel, a smaller minimum step could
    // only shorten steps the octree already cut at a node's face).
    n.octreeSettings.minStepVoxels = settings_.trace.minStepVoxels;
    n.octreeSettings.stepLimitVoxels = settings_.maxStepVoxels;
    return n;
}

void PhotonTransport::configure(const Scene& scene, ViewSetup& setup) {
    seed_ = scene.render.seed;
    // Photons matter where something scatters them toward the camera, or a receiver shows them;
    // every light type emits photons (shaders/shared/photons.h).
    if (!lightAllThroughFluence(scene, setup)) return;
    // Every photon of every light is in memory at once (GPU records and their read-back), under
    // dispersion once per colour channel (channelPassCount).
    const PhotonPlan plan = planPhotons(setup, traceSettings());
    const double passes =
        channelPassCount(shared::curvedRays(setup.params) && dispersesView(setup));
    checkMemory(settings_.where.empty() ? scene.path + ":/render/light_transport" : settings_.where,
                double(plan.photons) * passes * kPhotonBytes,
                std::to_string(plan.photons) + " photons (" +
                    std::to_string(settings_.trace.photonsPerSide) + " per side)" +
                    (passes > 1 ? " in each of 3 colour channels" : ""),
                "lower per_side");
}

PhotonSettings PhotonTransport::traceSettings() const {
    PhotonSettings s = settings_.trace;
    s.seed = seed_;
    s.frame = 0;  // the same jitter every frame
    return s;
}

std::vector<unsigned char> PhotonTransport::cacheKey(
    const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids) const {
    const shared::GpuViewParams& p = setup.params;
    if (!shared::readsFluence(p)) return {};
    std::vector<unsigned char> key = transportInputsKey(setup, slotGrids);
    appendReceiverMapsKey(setup, key);  // photons stop on receivers and fill their maps
    // Every member is 4 bytes: the struct has no padding to carry stale bytes into the key.
    static_assert(sizeof(PhotonSettings) == 9 * 4, "PhotonSettings gained padding or a member");
    const PhotonSettings trace = traceSettings();
    appendBytes(key, &trace, sizeof(trace));
    appendBytes(key, &settings_.kappaTolerance, sizeof(settings_.kappaTolerance));
    appendBytes(key, &settings_.maxStepVoxels, sizeof(settings_.maxStepVoxels));
    // Each channel's photons bend with its own n under dispersion.
    for (const glm::vec3& slopes : setup.channelIndexSlopes)
        appendBytes(key, &slopes, sizeof(slopes));
    return key;
}

void PhotonTransport::runCpu(const TransportInputsCpu& in) {
    StageScope stage(in.timer, "photons");
    cpu_ = computePhotonRadianceCpu(in.setup, in.slotGrids, in.gradient, in.octree, traceSettings(),
                                    in.channelGradients);
}

void PhotonTransport::runGpu(const TransportInputsGpu& in) {
    if (!gpu_) gpu_ = std::make_unique<PhotonRadianceGpu>(device_.exactMath);
    gpu_->compute(in.setup, in.fields, in.refraction, traceSettings(), in.timer, in.dispersion);
}

TransportOutputCpu PhotonTransport::outputCpu() const {
    return transportOutputOf(cpu_);
}

void PhotonTransport::bindGpu() const {
    if (gpu_) gpu_->bind();
}

TransportStats PhotonTransport::stats() const {
    TransportStats s;
    if (device_.gpu) {
        if (!gpu_) return s;
        s.steps = gpu_->lastSteps();
        s.particlesTraced = gpu_->lastPhotonsTraced();
        s.particlesCut = gpu_->lastPhotonsCut();
        s.rounds = gpu_->lastRounds();
        return s;
    }
    s.steps = cpu_.steps;
    s.particlesTraced = cpu_.photonsTraced;
    s.particlesCut = cpu_.photonsCut;
    s.rounds = cpu_.rounds;
    return s;
}

std::optional<EnergyBalance> PhotonTransport::energy() const {
    const PhotonTotals t = volumes().totals;  // a GPU run's: read back (benches and tests only)
    return EnergyBalance{t.emitted, t.extinguished, t.escaped, t.dropped, t.received};
}

std::string PhotonTransport::previewPatch() const {
    const int side = std::max(settings_.trace.photonsPerSide / 2, 16);
    if (side >= settings_.trace.photonsPerSide) return {};
    return R"({"photons": {"per_side": )" + std::to_string(side) + "}}";
}

PhotonVolumes PhotonTransport::volumes() const {
    if (device_.gpu) return gpu_ ? gpu_->download() : PhotonVolumes{};
    return cpu_;
}

}  // namespace eikon
