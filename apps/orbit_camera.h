#pragma once
// The viewer's camera: orbits a target around the scene's up axis, zooms along the view line.
#include <glm/vec3.hpp>

#include "core/bounds.h"
#include "core/scene.h"

namespace eikon::app {

class OrbitCamera {
public:
    // Starts where `spec` looks (the automatic camera resolved against `volume`).
    OrbitCamera(const CameraSpec& spec, const Bounds3& volume, int width, int height);

    void orbit(float yawRadians, float pitchRadians);
    void zoom(float factor);  // distance *= factor
    // An explicit camera spec for the current view.
    CameraSpec spec() const;

private:
    CameraSpec base_;
    glm::vec3 target_{0.0f};
    glm::vec3 offset_{0.0f, 0.0f, 1.0f};  // from target to the eye
};

}  // namespace eikon::app
