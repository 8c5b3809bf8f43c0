#pragma once
// Small builders for scenes made in code, and the checks around them, shared by the rendering
// tests.
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "core/scene.h"

namespace eikon::test {

inline SourceSpec boxSource(const std::string& field, glm::vec3 lo, glm::vec3 hi, float value,
                            float falloff = 0.0f, float voxel = 0.05f) {
    SourceSpec s;
    s.type = SourceType::Box;
    s.field = field;
    s.boxMin = lo;
    s.boxMax = hi;
    s.value = value;
    s.falloff = falloff;
    s.voxelSize = voxel;
    return s;
}

inline SourceSpec sphereSource(const std::string& field, glm::vec3 center, float radius,
                               float value, float falloff, float voxel = 0.05f) {
    SourceSpec s;
    s.type = SourceType::Sphere;
    s.field = field;
    s.center = center;
    s.radius = radius;
    s.value = value;
    s.falloff = falloff;
    s.voxelSize = voxel;
    return s;
}

inline MaterialSpec material(const std::string& name, const std::string& field,
                             glm::vec3 absorption, glm::vec3 scattering = glm::vec3(0.0f),
                             float g = 0.0f, glm::vec3 emission = glm::vec3(0.0f)) {
    MaterialSpec m;
    m.name = name;
    m.field = field;
    m.absorption = absorption;
    m.scattering = scattering;
    m.g = g;
    m.emission = emission;
    return m;
}

inline LightSpec directionalLight(glm::vec3 direction, float intensity,
                                  glm::vec3 color = glm::vec3(1)) {
    LightSpec l;
    l.type = LightType::Directional;
    l.direction = glm::normalize(direction);
    l.intensity = intensity;
    l.color = color;
    return l;
}

inline CameraSpec cameraAt(glm::vec3 position, glm::vec3 lookAt, float fovDeg = 45.0f) {
    CameraSpec c;
    c.automatic = false;
    c.position = position;
    c.lookAt = lookAt;
    c.up = glm::vec3(0, 1, 0);
    c.horizontalFovDeg = fovDeg;
    return c;
}

inline void setVolume(Scene& scene, glm::vec3 lo, glm::vec3 hi, glm::ivec3 resolution) {
    scene.volume.autoBounds = false;
    scene.volume.bounds.min = lo;
    scene.volume.bounds.max = hi;
    scene.volume.autoResolution = false;
    scene.volume.resolution = resolution;
}

// The volume [−1, 1]³ at 16³ in a white environment, seen straight along −z through its centre by
// one pixel: with only absorbing media the pixel is the transmittance exp(−∫κ) along the z axis.
inline Scene transmittanceProbe() {
    Scene s;
    setVolume(s, glm::vec3(-1.0f), glm::vec3(1.0f), glm::ivec3(16));
    s.camera = cameraAt(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f), 10.0f);
    s.environment.color = glm::vec3(1.0f);
    s.render.width = 1;
    s.render.height = 1;
    return s;
}

// Field "density" as a scan's two tissue classes would give it: a box shell of value 0.5 over
// [−0.5, 0.5]³ around a core of 1 over [−0.25, 0.25]³ (voxels of 0.125). A ray along an axis
// crosses 0.5 of shell and 0.5 of core.
inline void addShellAroundCore(Scene& s) {
    s.sources.push_back(
        boxSource("density", glm::vec3(-0.5f), glm::vec3(0.5f), 0.5f, 0.0f, 0.125f));
    s.sources.push_back(
        boxSource("density", glm::vec3(-0.25f), glm::vec3(0.25f), 1.0f, 0.0f, 0.125f));
}

constexpr double kPi = 3.14159265358979323846;

inline double relativeError(double value, double expected) {
    return std::abs(value - expected) / std::abs(expected);
}

// A slab z in [-L/2, L/2] with L = 1 (x, y in [-1, 1]) of density 1, scattering `sigma` per unit
// (no absorption, g = 0), lit along +z by a directional light of irradiance E, seen along −z
// from the axis (odd image sizes put a pixel centre on it), black background. The volume is the
// slab on the source's own voxel centres. The centre pixel is, per channel,
//   L_pixel = ∫0^L sigma p E e^(−sigma (L − s)) e^(−sigma s) ds = sigma p E L e^(−sigma L),
// p = 1/4π: at depth s the light has crossed L − s of the slab and the view ray s, at a
// scattering angle of 0.
inline Scene scatteringSlab(glm::vec3 sigma, float irradiance) {
    Scene scene;
    scene.sources.push_back(
        boxSource("density", glm::vec3(-1.0f, -1.0f, -0.5f), glm::vec3(1.0f, 1.0f, 0.5f), 1.0f));
    scene.materials.push_back(material("scatterer", "density", glm::vec3(0.0f), sigma, 0.0f));
    scene.lights.push_back(directionalLight(glm::vec3(0.0f, 0.0f, 1.0f), irradiance));
    setVolume(scene, glm::vec3(-1.0f, -1.0f, -0.5f), glm::vec3(1.0f, 1.0f, 0.5f),
              glm::ivec3(40, 40, 20));
    scene.camera = cameraAt(glm::vec3(0.0f, 0.0f, 4.0f), glm::vec3(0.0f), 30.0f);
    scene.render.width = 33;
    scene.render.height = 25;
    return scene;
}

inline double slabCentrePixel(double sigma, double irradiance) {
    return sigma * irradiance * std::exp(-sigma) / (4.0 * kPi);
}

// Lit fog around a glass sphere (n = 1.5, soft rim) under a directional light, 32³, 40x30:
// light bends and focuses, the viewing rays bend too.
inline Scene glassSphereInFog() {
    Scene scene;
    scene.sources.push_back(boxSource("density", glm::vec3(-1.0f), glm::vec3(1.0f), 1.0f));
    scene.sources.push_back(sphereSource("n", glm::vec3(0.0f, 0.2f, 0.0f), 0.45f, 1.0f, 0.1f));
    scene.materials.push_back(
        material("fog", "density", glm::vec3(0.05f), glm::vec3(0.6f, 0.5f, 0.4f), 0.2f));
    MaterialSpec glass = material("glass", "n", glm::vec3(0.05f, 0.1f, 0.2f));
    glass.ior = 1.5f;
    scene.materials.push_back(glass);
    scene.lights.push_back(directionalLight(glm::vec3(0.1f, -1.0f, 0.05f), 3.0f));
    setVolume(scene, glm::vec3(-1.0f), glm::vec3(1.0f), glm::ivec3(32));
    scene.camera = cameraAt(glm::vec3(0.0f, 0.3f, 4.0f), glm::vec3(0.0f), 45.0f);
    scene.render.width = 40;
    scene.render.height = 30;
    return scene;
}

}  // namespace eikon::test
