#pragma once
// The backends a rendering test runs on, by name for its messages, and the one-pixel render the
// transmittance tests read.
#include <glm/vec3.hpp>

#include "render/frame_renderer.h"
#include "render/image.h"

namespace eikon::test {

inline const char* backendName(Backend b) {
    return b == Backend::Gpu ? "GPU" : "CPU twin";
}

// The first pixel of frame 0 of `scene` rendered on `backend` (a one-pixel camera's whole image).
inline glm::vec3 firstPixel(const Scene& scene, Backend backend) {
    FrameRenderer renderer(scene, backend);
    return glm::vec3(renderer.render(0).pixels[0]);
}

}  // namespace eikon::test
