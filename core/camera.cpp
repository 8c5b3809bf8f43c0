#include "core/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace eikon {

Bounds3 automaticCameraBox(const CameraSpec& spec, const Bounds3& volume) {
    return spec.framed ? *spec.framed : volume;
}

glm::vec3 automaticCameraUp(const CameraSpec& spec) {
    const glm::vec3 a = glm::abs(spec.up);
    if (a.z > a.x && a.z > a.y) return {0, 0, 1};
    if (a.x > a.y && a.x > a.z) return {1, 0, 0};
    return {0, 1, 0};
}

glm::vec3 frontOf(glm::vec3 up) {
    // z up (Blender): from −y, Blender's front view; x up: from +z; y up (OpenVDB, Houdini): +z.
    if (up.z > 0.5f) return {0, -1, 0};
    return {0, 0, 1};
}

CameraFrame makeCameraFrame(const CameraSpec& spec, const Bounds3& volume, int width, int height) {
    CameraFrame cam;
    cam.aspect = float(width) / float(height);
    cam.tanHalfFovX = std::tan(glm::radians(spec.horizontalFovDeg) * 0.5f);
    glm::vec3 position = spec.position, lookAt = spec.lookAt, up = spec.up;
    if (spec.automatic) {
        const Bounds3 box = automaticCameraBox(spec, volume);
        const float tanHalfNarrow = std::min(cam.tanHalfFovX, cam.tanHalfFovX / cam.aspect);
        const float radius = 0.5f * glm::length(box.size());
        const float distance = radius / std::sin(std::atan(tanHalfNarrow));
        lookAt = box.center();
        up = automaticCameraUp(spec);
        position = lookAt + distance * glm::normalize(frontOf(up) + 0.25f * up);
    }
    cam.origin = position;
    cam.forward = glm::normalize(lookAt - position);
    cam.right = glm::normalize(glm::cross(cam.forward, up));
    cam.up = glm::cross(cam.right, cam.forward);
    return cam;
}

namespace {

// Pixels per unit of u = x / depth: u spans [−tanHalfFovX, tanHalfFovX] across the width, and v
// spans the same per pixel (square pixels).
float pixelsPerTangent(const CameraFrame& camera, int width) {
    return 0.5f * float(width) / camera.tanHalfFovX;
}

}  // namespace

std::optional<glm::vec2> projectToImage(const CameraFrame& camera, glm::vec3 p, int width) {
    const glm::vec3 d = p - camera.origin;
    const float depth = glm::dot(d, camera.forward);
    if (!(depth > 0.0f)) return std::nullopt;
    const float scale = pixelsPerTangent(camera, width);
    const float height = float(width) / camera.aspect;
    return glm::vec2(0.5f * float(width) + scale * glm::dot(d, camera.right) / depth,
                     0.5f * height - scale * glm::dot(d, camera.up) / depth);
}

glm::vec3 cameraPlaneMotion(const CameraFrame& camera, glm::vec3 p, glm::vec2 pixels, int width) {
    const float depth = glm::dot(p - camera.origin, camera.forward);
    if (!(depth > 0.0f)) return glm::vec3(0.0f);
    const float worldPerPixel = depth / pixelsPerTangent(camera, width);
    return worldPerPixel * (pixels.x * camera.right - pixels.y * camera.up);
}

}  // namespace eikon
