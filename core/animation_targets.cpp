#include "core/animation_targets.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include <glm/geometric.hpp>

namespace eikon {

namespace {

std::vector<std::string> splitPointer(const std::string& pointer) {
    std::vector<std::string> parts;
    if (pointer.empty() || pointer[0] != '/') return parts;
    std::stringstream in(pointer.substr(1));
    std::string part;
    while (std::getline(in, part, '/')) parts.push_back(part);
    return parts;
}

// A non-negative decimal index without leading zeros, or −1.
int parseIndex(const std::string& text) {
    if (text.empty() || text.size() > 6 || (text.size() > 1 && text[0] == '0')) return -1;
    for (char c : text)
        if (c < '0' || c > '9') return -1;
    return std::stoi(text);
}

AnimationTarget make(TargetKind kind, int index, int width, double lo = -1e30, double hi = 1e30) {
    AnimationTarget t;
    t.kind = kind;
    t.index = index;
    t.width = width;
    t.lo = lo;
    t.hi = hi;
    return t;
}

int materialNamed(const Scene& scene, const std::string& name) {
    for (size_t m = 0; m < scene.materials.size(); ++m)
        if (scene.materials[m].name == name) return int(m);
    return -1;
}

std::optional<AnimationTarget> meshTarget(const Scene& scene, int i, const std::string& key,
                                          std::string& why) {
    const MeshObjectSpec& mesh = scene.meshes[size_t(i)];
    const bool simulated = mesh.jelly.has_value() || mesh.shape == MeshShapeType::Water;
    if (simulated && (key == "translate" || key == "scale" || key == "rotation")) {
        why = "mesh '" + mesh.name + "' moves by its own simulation (" +
              (mesh.jelly ? "jelly" : "water") +
              "); its placement only sets where it starts and cannot be animated";
        return std::nullopt;
    }
    if (mesh.shape == MeshShapeType::Liquid &&
        (key == "translate" || key == "scale" || key == "rotation")) {
        why = "mesh '" + mesh.name + "' is a liquid and moves with its container '" +
              scene.meshes[size_t(mesh.container)].name + "'; animate the container";
        return std::nullopt;
    }
    if (key == "translate") return make(TargetKind::MeshTranslate, i, 3);
    if (key == "scale") return make(TargetKind::MeshScale, i, 3, 1e-6, 1e30);
    if (key == "rotation") {
        AnimationTarget t = make(TargetKind::MeshRotation, i, 4, -1.0, 1.0);
        t.rotation = true;
        return t;
    }
    // A mesh's optics live in the materials the parser made for it (core/scene_meshes.h).
    const std::string& name = scene.meshes[size_t(i)].name;
    if (key == "ior") {
        const int m = materialNamed(scene, name + ".n");
        if (m < 0) why = "mesh '" + name + "' has no index to animate (give it an \"ior\" > 1)";
        if (m < 0) return std::nullopt;
        return make(TargetKind::MaterialIor, m, 1, 1.0, 1e30);
    }
    const TargetKind kinds[] = {TargetKind::MaterialAbsorption, TargetKind::MaterialScattering,
                                TargetKind::MaterialEmission};
    const char* keys[] = {"absorption", "scattering", "emission"};
    for (int k = 0; k < 3; ++k) {
        if (key != keys[k]) continue;
        const int m = materialNamed(scene, name);
        if (m < 0)
            why = "mesh '" + name +
                  "' has no absorption, scattering or emission to animate (give "
                  "it a non-zero value to start from)";
        if (m < 0) return std::nullopt;
        return make(kinds[k], m, 3, 0.0, 1e30);
    }
    why =
        "a mesh animates translate, rotation, scale, ior, absorption, scattering or emission, "
        "not '" +
        key + "'";
    return std::nullopt;
}

// /meshes/<i>/deformer/handles/<j>/<key>, split.
std::optional<AnimationTarget> handleTarget(const Scene& scene, int i,
                                            const std::vector<std::string>& p, std::string& why) {
    const MeshObjectSpec& mesh = scene.meshes[size_t(i)];
    if (!mesh.arap) {
        why = "mesh '" + mesh.name + "' has no ARAP deformer, so no handles to move";
        return std::nullopt;
    }
    const int j = parseIndex(p[4]);
    if (j < 0 || size_t(j) >= mesh.arap->handles.size()) {
        why = "mesh '" + mesh.name + "' has no handle " + p[4] + " (its deformer has " +
              std::to_string(mesh.arap->handles.size()) + ")";
        return std::nullopt;
    }
    std::optional<AnimationTarget> t;
    if (p[5] == "translate") t = make(TargetKind::HandleTranslate, i, 3);
    if (p[5] == "rotation") {
        t = make(TargetKind::HandleRotation, i, 4, -1.0, 1.0);
        t->rotation = true;
    }
    if (!t) why = "a handle animates translate or rotation, not '" + p[5] + "'";
    if (t) t->handle = j;
    return t;
}

std::optional<AnimationTarget> lightTarget(const Scene& scene, int i, const std::string& key,
                                           std::string& why) {
    const LightSpec& light = scene.lights[size_t(i)];
    const bool positioned = light.type != LightType::Directional;
    const bool directed = light.type != LightType::Point;
    if (key == "position" && positioned) return make(TargetKind::LightPosition, i, 3);
    if (key == "direction" && directed) return make(TargetKind::LightDirection, i, 3);
    if (key == "color") return make(TargetKind::LightColor, i, 3, 0.0, 1e30);
    if (key == "intensity") return make(TargetKind::LightIntensity, i, 1, 0.0, 1e30);
    if (light.type == LightType::Spot && key == "cone_angle_deg")
        return make(TargetKind::LightCone, i, 1, 1e-3, 90.0);
    if (light.type == LightType::Spot && key == "cone_softness_deg")
        return make(TargetKind::LightSoftness, i, 1, 0.0, 90.0);
    if (light.type == LightType::Directional && key == "angular_diameter_deg")
        return make(TargetKind::LightAngularDiameter, i, 1, 0.0, kMaxAngularDiameterDeg);
    why = "this light animates " + std::string(positioned ? "position, " : "") +
          (directed ? "direction, " : "") + "color, intensity" +
          (light.type == LightType::Spot ? ", cone_angle_deg, cone_softness_deg" : "") +
          (light.type == LightType::Directional ? ", angular_diameter_deg" : "") + ", not '" + key +
          "'";
    return std::nullopt;
}

std::optional<AnimationTarget> materialTarget(const Scene& scene, int m, const std::string& key,
                                              std::string& why) {
    if (key == "ior" && scene.materials[size_t(m)].gladstoneDale > 0.0f) {
        why = "material '" + scene.materials[size_t(m)].name +
              "' is hot air (gladstone_dale): its index follows the temperature field";
        return std::nullopt;
    }
    if (key == "absorption") return make(TargetKind::MaterialAbsorption, m, 3, 0.0, 1e30);
    if (key == "scattering") return make(TargetKind::MaterialScattering, m, 3, 0.0, 1e30);
    if (key == "emission") return make(TargetKind::MaterialEmission, m, 3, 0.0, 1e30);
    if (key == "ior") return make(TargetKind::MaterialIor, m, 1, 1.0, 1e30);
    if (key == "g") return make(TargetKind::MaterialG, m, 1, -0.999, 0.999);
    why = "a material animates absorption, scattering, emission, ior or g, not '" + key + "'";
    return std::nullopt;
}

// The keys match the parser's (core/scene_simulation.cpp) and so do the ranges: rates of density
// and of pulling the velocity are ≥ 0, a temperature rate may be negative (a cold source).
std::optional<AnimationTarget> sourceTarget(int i, const std::string& key, std::string& why) {
    if (key == "center") return make(TargetKind::SourceCenter, i, 3);
    if (key == "velocity") return make(TargetKind::SourceVelocity, i, 3);
    if (key == "density_rate") return make(TargetKind::SourceDensityRate, i, 1, 0.0, 1e30);
    if (key == "temperature_rate") return make(TargetKind::SourceTemperatureRate, i, 1);
    if (key == "velocity_rate") return make(TargetKind::SourceVelocityRate, i, 1, 0.0, 1e30);
    why =
        "a smoke source animates center, velocity, density_rate, temperature_rate or "
        "velocity_rate, not '" +
        key + "'";
    return std::nullopt;
}

std::optional<AnimationTarget> simulationTarget(const Scene& scene,
                                                const std::vector<std::string>& p,
                                                std::string& why) {
    if (scene.simulations.empty()) {
        why = "the scene has no \"simulation\" section";
        return std::nullopt;
    }
    // A lone object: /simulation/sources/<i>/<key>; an array: /simulation/<d>/sources/<i>/<key>.
    const bool lone =
        scene.simulations.size() == 1 && scene.simulations[0].jsonPath == "/simulation";
    size_t first = 1;  // where "sources" is in p
    int domain = 0;
    if (!lone) {
        domain = p.size() > 1 ? parseIndex(p[1]) : -1;
        if (domain < 0 || size_t(domain) >= scene.simulations.size()) {
            why = "expected /simulation/<domain>/sources/<index>/<key> with a domain below " +
                  std::to_string(scene.simulations.size());
            return std::nullopt;
        }
        first = 2;
    }
    const SmokeSimulationSpec& simulation = scene.simulations[size_t(domain)];
    if (p.size() != first + 3 || p[first] != "sources") {
        why = "expected " + simulation.jsonPath + "/sources/<index>/<key>";
        return std::nullopt;
    }
    const size_t count = simulation.sources.size();
    const int i = parseIndex(p[first + 1]);
    if (i < 0 || size_t(i) >= count) {
        why = "no simulation source " + p[first + 1] + " (" + simulation.jsonPath + " has " +
              std::to_string(count) + ")";
        return std::nullopt;
    }
    std::optional<AnimationTarget> target = sourceTarget(i, p[first + 2], why);
    if (target) target->domain = domain;
    return target;
}

// A box source keeps its size and moves so that its centre is at `center`.
void moveShape(SimShapeSpec& shape, glm::vec3 center) {
    shape.center = center;
    if (shape.kind != SimShapeSpec::Kind::Box) return;
    const glm::vec3 half = 0.5f * (shape.boxMax - shape.boxMin);
    shape.boxMin = center - half;
    shape.boxMax = center + half;
}

}  // namespace

const char* animationTargetExamples() {
    return "/lights/0/position, /lights/0/intensity, /meshes/0/rotation, /meshes/0/translate, "
           "/meshes/0/deformer/handles/0/translate, /materials/0/absorption, /camera/position, "
           "/camera/look_at, /clip_planes/0/point, /simulation/sources/0/center";
}

std::optional<AnimationTarget> resolveAnimationTarget(const Scene& scene,
                                                      const std::string& pointer,
                                                      std::string& why) {
    const std::vector<std::string> p = splitPointer(pointer);
    auto indexed = [&](size_t count, const char* what) {
        const int i = p.size() == 3 ? parseIndex(p[1]) : -1;
        if (p.size() != 3)
            why = std::string("expected /") + what + "/<index>/<key>";
        else if (i < 0 || size_t(i) >= count)
            why = std::string("no ") + what + " " + p[1] + " (the scene has " +
                  std::to_string(count) + ")";
        return (p.size() == 3 && i >= 0 && size_t(i) < count) ? i : -1;
    };
    if (p.size() == 6 && p[0] == "meshes" && p[2] == "deformer" && p[3] == "handles") {
        const int i = parseIndex(p[1]);
        if (i >= 0 && size_t(i) < scene.meshes.size()) return handleTarget(scene, i, p, why);
        why = "no meshes " + p[1] + " (the scene has " + std::to_string(scene.meshes.size()) + ")";
        return std::nullopt;
    }
    if (!p.empty() && p[0] == "meshes") {
        const int i = indexed(scene.meshes.size(), "meshes");
        return i < 0 ? std::nullopt : meshTarget(scene, i, p[2], why);
    }
    if (!p.empty() && p[0] == "lights") {
        const int i = indexed(scene.lights.size(), "lights");
        return i < 0 ? std::nullopt : lightTarget(scene, i, p[2], why);
    }
    if (!p.empty() && p[0] == "clip_planes") {
        const int i = indexed(scene.clipPlanes.size(), "clip_planes");
        if (i >= 0 && p[2] == "point") return make(TargetKind::ClipPoint, i, 3);
        if (i >= 0 && p[2] == "normal") return make(TargetKind::ClipNormal, i, 3);
        if (i >= 0) why = "a clip plane animates point or normal, not '" + p[2] + "'";
        return std::nullopt;
    }
    if (!p.empty() && p[0] == "materials") {
        // Indices of the scene's own materials, as written (the meshes' come after them).
        size_t own = scene.materials.size();
        for (const MeshObjectSpec& mesh : scene.meshes)
            for (const MaterialSpec& m : scene.materials)
                if (m.name == mesh.name || m.name == mesh.name + ".n") --own;
        const int i = indexed(own, "materials");
        return i < 0 ? std::nullopt : materialTarget(scene, i, p[2], why);
    }
    if (!p.empty() && p[0] == "camera") {
        if (p.size() != 2) {
            why = "expected /camera/<key>";
            return std::nullopt;
        }
        if (scene.camera.automatic) {
            why = "the camera is \"auto\"; give a camera object to animate it";
            return std::nullopt;
        }
        if (p[1] == "position") return make(TargetKind::CameraPosition, 0, 3);
        if (p[1] == "look_at") return make(TargetKind::CameraLookAt, 0, 3);
        if (p[1] == "horizontal_fov_deg") return make(TargetKind::CameraFov, 0, 1, 1e-3, 179.0);
        why = "the camera animates position, look_at or horizontal_fov_deg, not '" + p[1] + "'";
        return std::nullopt;
    }
    if (!p.empty() && p[0] == "simulation") return simulationTarget(scene, p, why);
    why = std::string("not an animatable value; examples: ") + animationTargetExamples();
    return std::nullopt;
}

void writeAnimationTarget(Scene& scene, const AnimationTarget& t, const float* value) {
    float v[4] = {0, 0, 0, 0};
    for (int k = 0; k < t.width; ++k) v[k] = float(std::clamp(double(value[k]), t.lo, t.hi));
    const glm::vec3 v3(v[0], v[1], v[2]);
    const size_t i = size_t(t.index);
    switch (t.kind) {
        case TargetKind::MeshTranslate:
            scene.meshes[i].translation = v3;
            break;
        case TargetKind::MeshScale:
            scene.meshes[i].scale = v3;
            break;
        case TargetKind::MeshRotation: {
            const glm::quat q(value[3], value[0], value[1], value[2]);  // [x, y, z, w]
            const float length = glm::length(q);
            if (length > 0.0f && std::isfinite(length)) scene.meshes[i].rotation = q / length;
            break;
        }
        case TargetKind::HandleTranslate:
            scene.meshes[i].arap->handles[size_t(t.handle)].translation = v3;
            break;
        case TargetKind::HandleRotation: {
            const glm::quat q(value[3], value[0], value[1], value[2]);  // [x, y, z, w]
            const float length = glm::length(q);
            if (length > 0.0f && std::isfinite(length))
                scene.meshes[i].arap->handles[size_t(t.handle)].rotation = q / length;
            break;
        }
        case TargetKind::LightPosition:
            scene.lights[i].position = v3;
            break;
        case TargetKind::LightDirection:
            if (glm::length(v3) > 0.0f) scene.lights[i].direction = glm::normalize(v3);
            break;
        case TargetKind::LightColor:
            scene.lights[i].color = v3;
            break;
        case TargetKind::LightIntensity:
            scene.lights[i].intensity = v[0];
            break;
        case TargetKind::LightCone:
            scene.lights[i].coneAngleDeg = v[0];
            scene.lights[i].coneSoftnessDeg = std::min(scene.lights[i].coneSoftnessDeg, v[0]);
            break;
        case TargetKind::LightSoftness:
            scene.lights[i].coneSoftnessDeg = std::min(v[0], scene.lights[i].coneAngleDeg);
            break;
        case TargetKind::LightAngularDiameter:
            scene.lights[i].angularDiameterDeg = v[0];
            break;
        case TargetKind::ClipPoint:
            scene.clipPlanes[i].point = v3;
            break;
        case TargetKind::ClipNormal:  // a key of zero keeps the last normal, as lights do
            if (glm::length(v3) > 0.0f) scene.clipPlanes[i].normal = glm::normalize(v3);
            break;
        case TargetKind::CameraPosition:
            scene.camera.position = v3;
            break;
        case TargetKind::CameraLookAt:
            scene.camera.lookAt = v3;
            break;
        case TargetKind::CameraFov:
            scene.camera.horizontalFovDeg = v[0];
            break;
        case TargetKind::MaterialAbsorption:
            scene.materials[i].absorption = v3;
            break;
        case TargetKind::MaterialScattering:
            scene.materials[i].scattering = v3;
            break;
        case TargetKind::MaterialEmission:
            scene.materials[i].emission = v3;
            break;
        case TargetKind::MaterialIor:
            scene.materials[i].ior = v[0];
            break;
        case TargetKind::MaterialG:
            scene.materials[i].g = v[0];
            break;
        case TargetKind::SourceCenter:
            moveShape(scene.simulations[size_t(t.domain)].sources[i].shape, v3);
            break;
        case TargetKind::SourceVelocity:
            scene.simulations[size_t(t.domain)].sources[i].velocity = v3;
            break;
        case TargetKind::SourceDensityRate:
            scene.simulations[size_t(t.domain)].sources[i].densityRate = v[0];
            break;
        case TargetKind::SourceTemperatureRate:
            scene.simulations[size_t(t.domain)].sources[i].temperatureRate = v[0];
            break;
        case TargetKind::SourceVelocityRate:
            scene.simulations[size_t(t.domain)].sources[i].velocityRate = v[0];
            break;
    }
}

}  // namespace eikon
