#pragma once
// Small builders for scenes made in code, shared by the rendering tests.
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

}  // namespace eikon::test
