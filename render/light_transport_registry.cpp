#include "render/light_transport_registry.h"

#include <glm/vector_relational.hpp>

#include "render/transport/light_volumes/light_volume_transport.h"
#include "render/transport/photons/photon_transport.h"
#include "render/transport/plane_sweep/plane_sweep_transport.h"
#include "render/transport/wavefront/wavefront_transport.h"

namespace eikon {
namespace {

constexpr const char* kPointer = "/render/light_transport";

template <class Method, class Settings>
std::unique_ptr<LightTransport> make(Settings settings, const TransportDevice& device) {
    return std::make_unique<Method>(settings, device);
}

// "auto": photons when light can bend on its way (some material has ior ≠ 1) and something
// shows it (a material scatters it toward the camera, or a receiver); straight light volumes
// otherwise, where they are exact and cheaper.
std::string automaticMethod(const Scene& scene) {
    bool refracts = false, scatters = false;
    for (const MaterialSpec& mat : scene.materials) {
        refracts = refracts || mat.ior != 1.0f;
        scatters = scatters || glm::any(glm::greaterThan(mat.scattering, glm::vec3(0.0f)));
    }
    return refracts && (scatters || !scene.receivers.empty()) ? "photons" : "light_volumes";
}

json::Json parseSection(const Scene& scene) {
    // Core wrote the section as compact JSON (core/scene.h), so it always parses.
    return json::Json::parse(scene.render.lightTransport);
}

// Reads the section, checks every method's settings, and returns the chosen one.
std::unique_ptr<LightTransport> readSection(const Scene& scene, const TransportDevice& device,
                                            std::string* chosenName) {
    const json::Json doc = parseSection(scene);
    json::Object object(json::Value(doc, scene.path, kPointer), "the light transport settings");
    std::vector<std::string> names = {"auto"};
    for (const LightTransportMethod& m : lightTransportMethods()) names.push_back(m.name);
    std::string method = "auto";
    if (auto m = object.optional("method")) method = m->choice(names);
    if (method == "auto") method = automaticMethod(scene);
    std::unique_ptr<LightTransport> chosen;
    for (const LightTransportMethod& m : lightTransportMethods()) {
        const std::optional<json::Value> section = object.optional(m.name);
        std::unique_ptr<LightTransport> made = m.make(section ? &*section : nullptr, device);
        if (m.name == method) chosen = std::move(made);
    }
    object.finish();
    if (!chosen->drawsLightDiscs()) requireLightsWithoutDisc(scene, method);
    if (chosenName) *chosenName = method;
    return chosen;
}

// The photons' settings in `eikon bench methods`: the photon count (coarse, default, fine), and
// the integrators other than the default (RK4) at the default steps (`eikon bench integrators`
// measures them photon by photon at three steps).
std::vector<std::pair<std::string, std::string>> photonBenchSettings() {
    std::vector<std::pair<std::string, std::string>> settings = {
        {"coarse", R"({"per_side": 64})"},
        {"default", "{}"},
        {"fine", R"({"per_side": 256, "min_step_voxels": 0.5})"}};
    for (const std::string& integrator : rayIntegratorNames())
        if (integrator != rayIntegratorName(PhotonSettings{}.integrator))
            settings.push_back({integrator, R"({"integrator": ")" + integrator + R"("})"});
    return settings;
}

}  // namespace

const std::vector<LightTransportMethod>& lightTransportMethods() {
    static const std::vector<LightTransportMethod> methods = {
        {"photons",
         "Sun et al. 2008: photons march the ray equation through the octree and deposit "
         "fluence (curved light, volume and surface caustics)",
         [](const json::Value* s, const TransportDevice& d) {
             return make<PhotonTransport>(readPhotonTransportSettings(s), d);
         },
         photonBenchSettings()},
        {"light_volumes",
         "single scattering of straight light: a transmittance volume per light, swept or "
         "marched, or marched at every view sample",
         [](const json::Value* s, const TransportDevice& d) {
             return make<LightVolumeTransport>(readLightVolumeSettings(s), d);
         },
         {{"coarse", R"({"shadows": "volume", "shadow_step_voxels": 6})"},
          {"default", "{}"},
          {"fine", R"({"shadows": "volume", "shadow_step_voxels": 1})"}}},
        {"wavefront",
         "Ihrke et al. 2007: wavefront patches advance in equal optical time steps, split past a "
         "voxel and carry power (curved light, caustics by the intensity law, no noise); CPU twin "
         "only so far",
         [](const json::Value* s, const TransportDevice& d) {
             return make<WavefrontTransport>(readWavefrontTransportSettings(s), d);
         },
         {{"coarse", R"({"split_voxels": 2})"},
          {"default", "{}"},
          {"fine", R"({"step_voxels": 0.5})"},
          {"paper", R"({"at_caustic": "remove", "deposit_samples": 1})"},
          {"midpoint", R"({"integrator": "midpoint"})"},
          {"euler", R"({"integrator": "euler"})"}}},
        {"plane_sweep",
         "Magnus's thesis: each light's 2D buffer advances plane by plane, looking back along its "
         "direction, bending by the ∇n step and correcting intensity by footprint areas (curved "
         "light, caustics, no noise)",
         [](const json::Value* s, const TransportDevice& d) {
             return make<PlaneSweepTransport>(readPlaneSweepTransportSettings(s), d);
         },
         {{"coarse", R"({"back_trace_refinements": 0})"},
          {"default", "{}"},
          {"fine", R"({"planes_per_voxel": 4})"},
          {"uncorrected", R"({"intensity_correction": false})"}}},
    };
    return methods;
}

std::unique_ptr<LightTransport> makeLightTransport(const Scene& scene,
                                                   const TransportDevice& device) {
    return readSection(scene, device, nullptr);
}

void checkLightTransport(const Scene& scene) {
    readSection(scene, TransportDevice{}, nullptr);
}

std::string lightTransportName(const Scene& scene) {
    std::string name;
    readSection(scene, TransportDevice{}, &name);
    return name;
}

ViewSetup makeConfiguredViewSetup(const Scene& scene, const RenderVolume& volume,
                                  const CameraFrame& camera, glm::ivec2 environmentSize) {
    ViewSetup setup = makeViewSetup(scene, volume, camera, environmentSize);
    makeLightTransport(scene, TransportDevice{})->configure(scene, setup);
    return setup;
}

void patchLightTransport(Scene& scene, const std::string& jsonPatch) {
    json::Json section = parseSection(scene);
    section.merge_patch(json::Json::parse(jsonPatch));
    scene.render.lightTransport = section.dump();
}

}  // namespace eikon
