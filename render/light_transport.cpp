#include "render/light_transport.h"

#include <cstring>

#include "render/gpu_timer.h"
#include "render/input_key.h"

namespace eikon {

StageScope::StageScope(GpuStageTimer* timer, const char* stage) : timer_(timer) {
    if (timer_) timer_->begin(stage);
}

StageScope::~StageScope() {
    if (timer_) timer_->end();
}

bool viewReadsLightTransmittance(const ViewSetup& setup) {
    const shared::GpuViewParams& p = setup.params;
    if (shared::lightCount(p) == 0 || shared::shadowMode(p) == EK_SHADOWS_MARCHED) return false;
    if (shared::allLightsInFluence(p)) return false;
    if (shared::receiverCount(p) > 0) return true;  // receivers are lit through them
    for (int m = 0; m < shared::materialCount(p); ++m) {
        const glm::vec4& s = p.materials[m].scattering;
        if (s.x > 0.0f || s.y > 0.0f || s.z > 0.0f) return true;
    }
    return false;
}

std::vector<unsigned char> transportInputsKey(const ViewSetup& setup,
                                              const std::vector<const DenseGrid*>& slotGrids) {
    shared::GpuViewParams p = setup.params;
    p.cameraOrigin = p.cameraRight = p.cameraUp = p.cameraForward = glm::vec4(0.0f);
    p.image.x = p.image.y = 0;
    p.background = glm::vec4(0.0f);
    p.environment = glm::ivec4(0);
    p.environmentSky = p.environmentHorizon = p.environmentGround = glm::vec4(0.0f);
    // Receivers stop photons but not straight light; their albedo only shades the view. A
    // method whose output depends on them appends them itself.
    shared::setReceiverCount(p, 0);
    for (shared::GpuReceiver& r : p.receivers) r = shared::GpuReceiver{};
    // Sized first and copied into, not appended to an empty vector: GCC 12 warns (a false
    // -Wstringop-overflow) on insert() into an empty vector at this size.
    std::vector<unsigned char> key(sizeof(p));
    std::memcpy(key.data(), &p, sizeof(p));
    for (const DenseGrid* g : slotGrids) appendBytes(key, &g->version, sizeof(g->version));
    return key;
}

}  // namespace eikon
