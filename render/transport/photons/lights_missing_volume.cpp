#include "render/transport/photons/lights_missing_volume.h"

#include <string>

#include "core/log.h"

namespace eikon {

int warnLightsMissingVolume(const ViewSetup& setup, const std::vector<PhotonLightPlan>& lights,
                            const std::function<bool(size_t)>& entered) {
    int named = 0;
    for (const PhotonLightPlan& light : lights) {
        const glm::vec4 radiance = setup.params.lights[light.light].radiance;
        if (radiance.x <= 0.0f && radiance.y <= 0.0f && radiance.z <= 0.0f) continue;
        bool any = false;
        for (size_t i = light.first; i < light.first + light.count && !any; ++i) any = entered(i);
        if (any) continue;
        logWarning("lights[" + std::to_string(light.light) +
                   "]: none of its light reaches the volume (it faces away or its cone misses "
                   "the box): it lights nothing there");
        ++named;
    }
    return named;
}

}  // namespace eikon
