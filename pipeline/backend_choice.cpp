#include "pipeline/backend_choice.h"

#include "core/error.h"

namespace eikon {
namespace {

std::string describe(const GlContext& gl) {
    return gl.rendererName() + " (" + gl.versionString() + ")" +
           (gl.debugOutput() ? ", OpenGL debug output on (driver messages as warnings)" : "");
}

}  // namespace

BackendChoice chooseBackend(const std::string& requested) {
    BackendChoice choice;
    if (requested == "cpu") {
        choice.description = "CPU twin (TBB), as asked";
        return choice;
    }
    if (requested == "gpu") {
        choice.context = createHeadlessContext();
        choice.backend = Backend::Gpu;
        choice.description = "GPU: " + describe(*choice.context);
        return choice;
    }
    try {
        choice.context = createHeadlessContext();
    } catch (const Error& e) {
        const std::string reason = e.reason().substr(0, e.reason().find('\n'));
        choice.description = "CPU twin (TBB): no usable OpenGL 4.3 here (" + reason + ")";
        return choice;
    }
    if (isSoftwareRenderer(choice.context->rendererName())) {
        choice.description = "CPU twin (TBB): OpenGL here is a software rasterizer, " +
                             describe(*choice.context) +
                             ", which runs the same code slower; --backend gpu uses it anyway";
        choice.context.reset();
        return choice;
    }
    choice.backend = Backend::Gpu;
    choice.description = "GPU: " + describe(*choice.context);
    return choice;
}

}  // namespace eikon
