#include "render/transport/light_volumes/light_volume_transport.h"

namespace eikon {
namespace {

int shadowModeCode(ShadowMode mode) {
    switch (mode) {
        case ShadowMode::Marched:
            return EK_SHADOWS_MARCHED;
        case ShadowMode::Swept:
            return EK_SHADOWS_SWEPT;
        case ShadowMode::Volume:
            break;
    }
    return EK_SHADOWS_VOLUME;
}

}  // namespace

LightVolumeSettings readLightVolumeSettings(const json::Value* section) {
    LightVolumeSettings s;
    if (!section) return s;
    json::Object object(*section, "the light volume settings");
    if (auto shadows = object.optional("shadows")) {
        const std::string mode = shadows->choice({"volume", "swept", "marched"});
        s.shadows = mode == "volume"  ? ShadowMode::Volume
                    : mode == "swept" ? ShadowMode::Swept
                                      : ShadowMode::Marched;
    }
    if (auto step = object.optional("shadow_step_voxels"))
        s.shadowStepVoxels = step->floatNumber(json::Range::greaterThan(0.0));
    object.finish();
    return s;
}

LightVolumeTransport::LightVolumeTransport(LightVolumeSettings settings, TransportDevice device)
    : settings_(settings), device_(device) {}

LightVolumeTransport::~LightVolumeTransport() = default;

void LightVolumeTransport::configure(const Scene&, ViewSetup& setup) {
    shared::GpuViewParams& p = setup.params;
    shared::setShadowMode(p, shadowModeCode(settings_.shadows));
    shared::setShadowStep(p, settings_.shadowStepVoxels * smallestVoxelEdge(p));
}

std::vector<unsigned char> LightVolumeTransport::cacheKey(
    const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids) const {
    if (!viewReadsLightTransmittance(setup)) return {};
    return transportInputsKey(setup, slotGrids);
}

void LightVolumeTransport::runCpu(const TransportInputsCpu& in) {
    StageScope stage(in.timer, "light");
    cpu_ = computeLightVolumesCpu(in.setup, in.slotGrids);
}

void LightVolumeTransport::runGpu(const TransportInputsGpu& in) {
    if (!gpu_) gpu_ = std::make_unique<LightVolumesGpu>(device_.hardwareTrilinear);
    gpu_->compute(in.setup, in.fields, in.timer);
}

TransportOutputCpu LightVolumeTransport::outputCpu() const {
    TransportOutputCpu out;
    for (const LightVolumeCpu& v : cpu_) out.lightTransmittance.push_back(v.data());
    return out;
}

void LightVolumeTransport::bindGpu() const {
    if (gpu_) gpu_->bind();
}

LightVolumeCpu LightVolumeTransport::downloadGpu(int light) const {
    return gpu_ ? gpu_->download(light) : LightVolumeCpu{};
}

}  // namespace eikon
