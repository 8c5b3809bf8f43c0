#include <epoxy/gl.h>

#include "render/shader_program.h"
#include "render/smoothing.h"
#include "shaders/shared/bindings.h"

namespace eikon {

VolumeSmootherGpu::VolumeSmootherGpu()
    : program_(std::make_unique<ShaderProgram>(ShaderProgram::compute("smooth_volume.comp"))) {}

VolumeSmootherGpu::~VolumeSmootherGpu() = default;

void VolumeSmootherGpu::smooth(unsigned source, unsigned target, glm::ivec3 res) {
    program_->use();
    program_->setIVec3("resolution", res);
    glBindImageTexture(EK_IMAGE_SMOOTH_SOURCE, source, 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(EK_IMAGE_SMOOTH_TARGET, target, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(GLuint((res.x + 3) / 4), GLuint((res.y + 3) / 4), GLuint((res.z + 3) / 4));
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace eikon
