#pragma once
// Camera frames: the automatic camera that frames a box, and the orthonormal basis a camera spec
// implies. Pixel (0, 0) is the top-left corner of the image.
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
// box's bounding sphere fits the narrower field of view) and builds the basis.
CameraFrame makeCameraFrame(const CameraSpec& spec, const Bounds3& volume, int width, int height);

}  // namespace eikon
