#pragma once
// Shorthands for a test scene's render.light_transport section (render/light_transport_registry.h
// reads it; scenes written in code set it through the same JSON a scene file holds).
#include <cstdio>
#include <string>

#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/light_transport_registry.h"
#include "render/transport/light_volumes/light_volume_transport.h"
#include "render/transport/photons/photon_transport.h"

namespace eikon::test {

// "auto", "photons" or "light_volumes".
inline void setTransportMethod(Scene& scene, const std::string& method) {
    patchLightTransport(scene, "{\"method\": \"" + method + "\"}");
}

// One number of a method's settings section, e.g. ("photons", "per_side", 64).
inline void setTransportSetting(Scene& scene, const std::string& method, const std::string& key,
                                double value) {
    char number[40];
    std::snprintf(number, sizeof(number), "%.17g", value);
    patchLightTransport(scene, "{\"" + method + "\": {\"" + key + "\": " + number + "}}");
}

inline void setPhotonSetting(Scene& scene, const std::string& key, double value) {
    setTransportSetting(scene, "photons", key, value);
}

// "volume", "swept" or "marched" (render.light_transport.light_volumes.shadows).
inline void setShadows(Scene& scene, const std::string& mode) {
    patchLightTransport(scene, "{\"light_volumes\": {\"shadows\": \"" + mode + "\"}}");
}

inline const char* shadowName(ShadowMode m) {
    return m == ShadowMode::Volume ? "volume" : m == ShadowMode::Swept ? "swept" : "marched";
}

// The smoothed photon volumes of the renderer's last photon run (the GPU's read back).
inline PhotonVolumes photonVolumesOf(const FrameRenderer& renderer) {
    const auto* photons = dynamic_cast<const PhotonTransport*>(&renderer.lightTransport());
    return photons ? photons->volumes() : PhotonVolumes{};
}

}  // namespace eikon::test
