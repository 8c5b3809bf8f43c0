#include "core/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace eikon {

CameraFrame makeCameraFrame(const CameraSpec& spec, const Bounds3& volume, int width, int height) {
    CameraFrame cam;
    cam.aspect = float(width) / float(height);
    cam.tanHalfFovX = std::tan(glm::radians(spec.horizontalFovDeg) * 0.5f);
    glm::vec3 position = spec.position, lookAt = spec.lookAt, up = spec.up;
    if (spec.automatic) {
        const float tanHalfNarrow = std::min(cam.tanHalfFovX, cam.tanHalfFovX / cam.aspect);
        const float radius = 0.5f * glm::length(volume.size());
        const float distance = radius / std::sin(std::atan(tanHalfNarrow));
        lookAt = volume.center();
        position = lookAt + distance * glm::normalize(glm::vec3(0.0f, 0.25f, 1.0f));
        up = glm::vec3(0, 1, 0);
    }
    cam.origin = position;
    cam.forward = glm::normalize(lookAt - position);
    cam.right = glm::normalize(glm::cross(cam.forward, up));
    cam.up = glm::cross(cam.right, cam.forward);
    return cam;
}

}  // namespace eikon
