#include <epoxy/gl.h>

#include "core/error.h"
#include "render/environment_map.h"
#include "render/gpu_timer.h"
#include "render/params_buffer.h"
#include "render/shader_program.h"
#include "render/view_pass.h"
#include "render/volume_textures.h"
#include "shaders/shared/bindings.h"

namespace eikon {

namespace {

std::unique_ptr<ShaderProgram> makeViewProgram(bool hardwareTrilinear, bool perChannel,
                                               bool specular) {
    std::vector<std::string> defines;
    if (hardwareTrilinear) defines.push_back("EK_HARDWARE_TRILINEAR");
    if (perChannel) defines.push_back("EK_VIEW_PER_CHANNEL");
    if (specular) defines.push_back("EK_SPECULAR");
    return std::make_unique<ShaderProgram>(ShaderProgram::compute("view.comp", defines));
}

}  // namespace

ViewPassGpu::ViewPassGpu(bool hardwareTrilinear) : hardwareTrilinear_(hardwareTrilinear) {
    programs_[0] = makeViewProgram(hardwareTrilinear, false, false);  // the common one, now
}

ShaderProgram& ViewPassGpu::program(bool perChannel, bool specular) {
    std::unique_ptr<ShaderProgram>& slot = programs_[(perChannel ? 1 : 0) + (specular ? 2 : 0)];
    if (!slot) slot = makeViewProgram(hardwareTrilinear_, perChannel, specular);
    return *slot;
}

ViewPassGpu::~ViewPassGpu() {
    if (outputTexture_) glDeleteTextures(1, &outputTexture_);
}

Image ViewPassGpu::render(const ViewSetup& setup, VolumeTextures& textures,
                          const LightTransport* light, unsigned gradientTexture,
                          GpuStageTimer* timer, unsigned environmentTexture,
                          const ViewDispersionGpu* dispersion) {
    const shared::GpuViewParams& p = setup.params;
    const int width = p.image.x, height = p.image.y;
    if (timer) timer->begin("view");
    if (!outputTexture_ || width != outputWidth_ || height != outputHeight_) {
        if (outputTexture_) glDeleteTextures(1, &outputTexture_);
        glGenTextures(1, &outputTexture_);
        glBindTexture(GL_TEXTURE_2D, outputTexture_);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, width, height);
        outputWidth_ = width;
        outputHeight_ = height;
    }
    glBindImageTexture(EK_IMAGE_VIEW_OUTPUT, outputTexture_, 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_RGBA32F);
    textures.bind();
    if (light) light->bindGpu();
    glActiveTexture(GL_TEXTURE0 + EK_UNIT_GRADIENT);
    glBindTexture(GL_TEXTURE_3D, gradientTexture);
    if (shared::environmentType(p) == EK_ENVIRONMENT_IMAGE && !environmentTexture)
        throw Error("view pass", "the environment image was not uploaded");
    glActiveTexture(GL_TEXTURE0 + EK_UNIT_ENVIRONMENT);
    glBindTexture(GL_TEXTURE_2D, environmentTexture);
    glActiveTexture(GL_TEXTURE0);
    if (shared::readsFluence(p) && !light)
        throw Error("view pass", "lighting through the fluence needs its volumes");
    const auto dispatch = [&](ShaderProgram& program) {
        program.use();
        const auto local = program.localSize();
        glDispatchCompute(GLuint((width + local[0] - 1) / local[0]),
                          GLuint((height + local[1] - 1) / local[1]), 1);
    };
    // The lights' highlights are a variant of their own, so that a scene without them runs the
    // code it always ran (shaders/shared/view_march.h, EK_SPECULAR).
    const bool specular = shared::curvedRays(p) && shared::anySurfaceHighlights(p);
    if (shared::curvedRays(p) && dispersesView(setup)) {
        // One dispatch per channel, each with its channel's n and ∇n volume, adding its channel
        // to what the one before wrote (view.comp, EK_VIEW_PER_CHANNEL).
        if (!dispersion || !dispersion->params)
            throw Error("view pass", "dispersion needs each channel's gradient volume");
        ShaderProgram& perChannel = program(true, specular);
        glBindImageTexture(EK_IMAGE_VIEW_OUTPUT, outputTexture_, 0, GL_FALSE, 0, GL_READ_WRITE,
                           GL_RGBA32F);
        for (int c = 0; c < 3; ++c) {
            dispersion->params->upload(channelViewParams(setup, c));
            glActiveTexture(GL_TEXTURE0 + EK_UNIT_GRADIENT);
            glBindTexture(GL_TEXTURE_3D, dispersion->gradientTextures[c]);
            glActiveTexture(GL_TEXTURE0);
            dispatch(perChannel);
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
        dispersion->params->upload(p);
    } else {
        dispatch(program(false, specular));
    }
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    if (timer) timer->end();

    if (timer) timer->begin("readback");
    Image image(width, height);
    glBindTexture(GL_TEXTURE_2D, outputTexture_);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, image.pixels.data());
    if (timer) timer->end();
    if (const GLenum err = glGetError(); err != GL_NO_ERROR)
        throw Error(
            "view pass", "OpenGL error 0x" + [&] {
                char buf[16];
                std::snprintf(buf, sizeof(buf), "%04x", err);
                return std::string(buf);
            }());
    return image;
}

}  // namespace eikon
