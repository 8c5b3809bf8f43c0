#include "render/transport/plane_sweep/plane_sweep_transport.h"

#include "core/error.h"
#include "core/memory_limit.h"
#include "render/input_key.h"
#include "render/transport/plane_sweep/plane_sweep_view.h"

namespace eikon {
namespace {

using json::Object;
using json::Range;

// Past 16 planes a voxel the trilinear fields change too little between planes to matter.
constexpr std::int64_t kMaxPlanesPerVoxel = 16;
// Each refinement costs a bilinear fetch and a ∇n sample; two already reach the float's digits.
constexpr std::int64_t kMaxRefinements = 4;

// A texel is the sweep's particle: it takes a step a plane.
TransportStats sweepStats(const PlaneSweepResultCpu& result) {
    TransportStats stats;
    stats.steps = result.texelSteps;
    stats.particlesTraced = result.texels;
    stats.particlesCut = result.texelsLost;
    return stats;
}

}  // namespace

PlaneSweepTransportSettings readPlaneSweepTransportSettings(const json::Value* section) {
    PlaneSweepTransportSettings s;
    if (!section) return s;
    Object object(*section, "the plane sweep settings");
    s.where = section->where();
    if (auto planes = object.optional("planes_per_voxel"))
        s.sweep.planesPerVoxel = static_cast<int>(planes->integer(1, kMaxPlanesPerVoxel));
    if (auto refinements = object.optional("back_trace_refinements"))
        s.sweep.backTraceRefinements = static_cast<int>(refinements->integer(0, kMaxRefinements));
    if (auto correction = object.optional("intensity_correction"))
        s.sweep.intensityCorrection = correction->boolean() ? 1 : 0;
    if (auto cosine = object.optional("min_cosine"))
        s.sweep.minCosine = cosine->floatNumber(Range::closedOpen(0.01, 1.0));
    if (auto view = object.optional("view"))
        s.sweep.interleavedView = view->choice({"volume", "interleaved"}) == "interleaved" ? 1 : 0;
    object.finish();
    return s;
}

PlaneSweepTransport::PlaneSweepTransport(PlaneSweepTransportSettings settings,
                                         TransportDevice device)
    : settings_(std::move(settings)), device_(device) {}

PlaneSweepTransport::~PlaneSweepTransport() = default;

TransportNeeds PlaneSweepTransport::needs() const {
    TransportNeeds n;
    // Light bends by Δs ∇n between planes; under dispersion one sweep per channel
    // (render/transport/channel_passes.h).
    n.gradient = true;
    return n;
}

void PlaneSweepTransport::configure(const Scene& scene, ViewSetup& setup) {
    const std::string where =
        settings_.where.empty() ? scene.path + ":/render/light_transport" : settings_.where;
    interleaved_ = false;
    if (!lightAllThroughFluence(scene, setup)) return;
    if (settings_.sweep.interleavedView) {
        const std::string at = where + "/view";
        checkInterleavedView(setup, settings_.sweep, at);
        interleaved_ = true;
        checkMemory(at, double(interleavedViewBytes(setup)),
                    "the interleaved view's rays and planes", "lower the image size");
        return;
    }
    for (int l = 0; l < shared::lightCount(setup.params); ++l)
        planPlaneSweep(setup, l, settings_.sweep);  // a light it cannot sweep fails here
    // The output volumes (the buffers are a few planes).
    const glm::ivec3 res(setup.params.resolution);
    const double voxels = double(res.x) * double(res.y) * double(res.z);
    checkMemory(where, 2.0 * voxels * double(sizeof(glm::vec4)),
                "the plane sweep's fluence and direction volumes", "lower the render resolution");
}

std::vector<unsigned char> PlaneSweepTransport::cacheKey(
    const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids) const {
    if (!shared::readsFluence(setup.params)) return {};
    std::vector<unsigned char> key = transportInputsKey(setup, slotGrids);
    appendReceiverMapsKey(setup, key);  // receivers stop the light and fill their maps
    static_assert(sizeof(PlaneSweepSettings) == 5 * 4, "PlaneSweepSettings gained padding");
    appendBytes(key, &settings_.sweep, sizeof(settings_.sweep));
    // Each channel's light bends with its own n under dispersion.
    for (const glm::vec3& slopes : setup.channelIndexSlopes)
        appendBytes(key, &slopes, sizeof(slopes));
    return key;
}

void PlaneSweepTransport::runCpu(const TransportInputsCpu& in) {
    StageScope stage(in.timer, "plane_sweep");
    result_ = sweepLightsCpu(in.setup, in.slotGrids, in.gradient, settings_.sweep, {},
                             in.channelGradients);
    stats_ = sweepStats(result_);
}

Image PlaneSweepTransport::runWithViewCpu(const TransportInputsCpu& in, const Image* environment) {
    InterleavedViewCpu frame =
        renderInterleavedCpu(in.setup, in.slotGrids, in.gradient, settings_.sweep, environment,
                             in.channelGradients, in.timer);
    result_ = std::move(frame.sweep);
    result_.memory.viewBytes = frame.windowBytes + frame.rayBytes;
    stats_ = sweepStats(result_);
    stats_.viewSteps = frame.viewSteps;
    stats_.viewSamplesBehind = frame.samplesBehind;
    return std::move(frame.image);
}

Image PlaneSweepTransport::runWithViewGpu(const TransportInputsGpu& in,
                                          unsigned environmentTexture) {
    if (!interleavedGpu_) interleavedGpu_ = std::make_unique<InterleavedViewGpu>(device_.exactMath);
    Image image = interleavedGpu_->render(in.setup, in.fields, in.refraction, settings_.sweep,
                                          environmentTexture, in.timer);
    const PlaneSweepGpu& sweep = interleavedGpu_->sweep();
    interleavedGpuMemory_ = sweep.memory();
    interleavedGpuMemory_.viewBytes = interleavedGpu_->windowBytes() + interleavedGpu_->rayBytes();
    stats_ = TransportStats{};
    stats_.steps = sweep.texelSteps();
    stats_.particlesTraced = sweep.texels();
    stats_.particlesCut = sweep.texelsLost();
    stats_.viewSteps = interleavedGpu_->viewSteps();
    stats_.viewSamplesBehind = interleavedGpu_->samplesBehind();
    return image;
}

void PlaneSweepTransport::runGpu(const TransportInputsGpu& in) {
    if (!gpu_) gpu_ = std::make_unique<PlaneSweepGpu>(device_.exactMath);
    gpu_->compute(in.setup, in.fields, in.refraction, settings_.sweep, in.timer, in.dispersion);
    stats_ = TransportStats{};
    stats_.steps = gpu_->texelSteps();
    stats_.particlesTraced = gpu_->texels();
    stats_.particlesCut = gpu_->texelsLost();
}

void PlaneSweepTransport::bindGpu() const {
    if (gpu_) gpu_->bind();
}

const PlaneSweepMemory& PlaneSweepTransport::memory() const {
    if (device_.gpu && interleaved_) return interleavedGpuMemory_;
    return device_.gpu && gpu_ ? gpu_->memory() : result_.memory;
}

PlaneSweepResultCpu PlaneSweepTransport::downloadGpu() const {
    return gpu_ ? gpu_->download() : PlaneSweepResultCpu{};
}

TransportOutputCpu PlaneSweepTransport::outputCpu() const {
    return fluenceOutputOf(result_.fluence, result_.direction, result_.receiverMap);
}

}  // namespace eikon
