#include "apps/orbit_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/camera.h"

namespace eikon::app {

OrbitCamera::OrbitCamera(const CameraSpec& spec, const Bounds3& volume, int width, int height)
    : base_(spec) {
    const CameraFrame frame = makeCameraFrame(spec, volume, width, height);
    target_ = spec.automatic ? automaticCameraBox(spec, volume).center() : spec.lookAt;
    offset_ = frame.origin - target_;
    base_.automatic = false;
    if (spec.automatic) base_.up = automaticCameraUp(spec);
}

void OrbitCamera::orbit(float yawRadians, float pitchRadians) {
    const glm::vec3 up = glm::normalize(base_.up);
    glm::vec3 rotated = glm::angleAxis(yawRadians, up) * offset_;
    const glm::vec3 right = glm::cross(up, rotated);
    if (glm::length(right) > 1e-6f) {
        const glm::vec3 pitched = glm::angleAxis(pitchRadians, glm::normalize(right)) * rotated;
        // Stop short of the poles, where "up" would be parallel to the view.
        const float c = glm::dot(glm::normalize(pitched), up);
        if (std::abs(c) < 0.995f) rotated = pitched;
    }
    offset_ = rotated;
}

void OrbitCamera::zoom(float factor) {
    offset_ *= std::clamp(factor, 0.1f, 10.0f);
}

CameraSpec OrbitCamera::spec() const {
    CameraSpec s = base_;
    s.lookAt = target_;
    s.position = target_ + offset_;
    return s;
}

}  // namespace eikon::app
