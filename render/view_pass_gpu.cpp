#include <epoxy/gl.h>

#include "core/error.h"
#include "render/environment_map.h"
#include "render/gpu_timer.h"
#include "render/shader_program.h"
#include "render/view_pass.h"
#include "render/volume_textures.h"
#include "shaders/shared/bindings.h"

namespace eikon {

ViewPassGpu::ViewPassGpu(bool hardwareTrilinear)
    : program_(std::make_unique<ShaderProgram>(ShaderProgram::compute(
          "view.comp", hardwareTrilinear ? std::vector<std::string>{"EK_HARDWARE_TRILINEAR"}
                                         : std::vector<std::string>{}))) {}

ViewPassGpu::~ViewPassGpu() {
    if (outputTexture_) glDeleteTextures(1, &outputTexture_);
}

Image ViewPassGpu::render(const ViewSetup& setup, VolumeTextures& textures,
                          const LightTransport* light, unsigned gradientTexture,
                          GpuStageTimer* timer, unsigned environmentTexture) {
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
    program_->use();
    const auto local = program_->localSize();
    glDispatchCompute(GLuint((width + local[0] - 1) / local[0]),
                      GLuint((height + local[1] - 1) / local[1]), 1);
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
