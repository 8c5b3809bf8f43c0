#pragma once
// The backends a rendering test runs on, by name for its messages.
#include "render/frame_renderer.h"

namespace eikon::test {

inline const char* backendName(Backend b) {
    return b == Backend::Gpu ? "GPU" : "CPU twin";
}

}  // namespace eikon::test
