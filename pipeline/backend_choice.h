#pragma once
// Which backend renders: "gpu" (OpenGL 4.3 compute), "cpu" (the CPU twins, running the same
// shared code), or "auto": the GPU when it is hardware, the CPU twin when OpenGL is a software
// rasterizer (the twin runs the same code several times faster there, see BENCHMARKS.md) or
// missing.
#include <memory>
#include <string>

#include "render/frame_renderer.h"
#include "render/gl_context.h"

namespace eikon {

struct BackendChoice {
    Backend backend = Backend::Cpu;
    std::unique_ptr<GlContext> context;  // the headless context for Backend::Gpu
    std::string description;             // one line for the user: what renders and why
};

// Throws eikon::Error for "gpu" without a usable OpenGL 4.3.
BackendChoice chooseBackend(const std::string& requested);

}  // namespace eikon
