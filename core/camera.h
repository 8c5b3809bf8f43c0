#pragma once
// Camera frames: the automatic camera that frames a box, and the orthonormal basis a camera spec
// implies. Pixel (0, 0) is the top-left corner of the image.
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/bounds.h"
#include "core/scene.h"

namespace eikon {

struct CameraFrame {
    glm::vec3 origin{0.0f};
    glm::vec3 right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, -1};
    float tanHalfFovX = 0.414f;
    float aspect = 1.0f;  // width / height
};

// Resolves "auto" (look at the box's centre from the front, slightly above, far enough that the
// box's bounding sphere fits the narrower field of view) and builds the basis. The box is
// spec.framed when set, else `volume`; up is spec.up's axis, and "the front" is +z for y or x up,
// −y for z up (Blender's front view).
CameraFrame makeCameraFrame(const CameraSpec& spec, const Bounds3& volume, int width, int height);

// The parts of "auto": the box framed, the up axis (+x, +y or +z, the largest component of
// spec.up), and the side looked from for an up axis.
Bounds3 automaticCameraBox(const CameraSpec& spec, const Bounds3& volume);
glm::vec3 automaticCameraUp(const CameraSpec& spec);
glm::vec3 frontOf(glm::vec3 up);

// Where the world point p shows on a width-wide image, in pixels from the image's top-left
// corner (pixel (x, y)'s centre is at (x + 0.5, y + 0.5)): the inverse of the viewing ray through
// a pixel (shaders/shared/view_march.h pixelRayDirection). Nothing for a point on or behind the
// camera's plane.
std::optional<glm::vec2> projectToImage(const CameraFrame& camera, glm::vec3 p, int width);

// The world motion, parallel to the image plane, that moves the world point p by `pixels` on a
// width-wide image (x to the right, y down) and keeps its depth: a drag in the camera plane
// through p. Zero for a point on or behind the camera's plane.
glm::vec3 cameraPlaneMotion(const CameraFrame& camera, glm::vec3 p, glm::vec2 pixels, int width);

}  // namespace eikon
