#include <epoxy/gl.h>

#include "core/error.h"
#include "render/gpu_timer.h"
#include "render/shader_program.h"
#include "render/transport/light_volumes/light_volume.h"
#include "render/volume_kernels_cpu.h"
#include "render/volume_textures.h"
#include "shaders/shared/bindings.h"

namespace eikon {

LightVolumesGpu::LightVolumesGpu(bool hardwareTrilinear) {
    std::vector<std::string> defines;
    if (hardwareTrilinear) defines.push_back("EK_HARDWARE_TRILINEAR");
    sweep_ = std::make_unique<ShaderProgram>(ShaderProgram::compute("light_sweep.comp", defines));
    march_ = std::make_unique<ShaderProgram>(ShaderProgram::compute("light_march.comp", defines));
}

LightVolumesGpu::~LightVolumesGpu() {
    if (texture_) glDeleteTextures(1, &texture_);
}

void LightVolumesGpu::allocate(glm::ivec3 res, int lights) {
    if (texture_ && res == resolution_ && lights == lights_) return;
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
    if (res.z * lights > maxSize)
        throw Error("light volumes", std::to_string(lights) + " light volume(s) of depth " +
                                         std::to_string(res.z) +
                                         " exceed this driver's 3D texture "
                                         "size of " +
                                         std::to_string(maxSize) +
                                         " (lower the volume resolution or the light count)");
    if (texture_) glDeleteTextures(1, &texture_);
    glGenTextures(1, &texture_);
    glActiveTexture(GL_TEXTURE0 + EK_UNIT_LIGHT_TRANSMITTANCE);
    glBindTexture(GL_TEXTURE_3D, texture_);
    glTexStorage3D(GL_TEXTURE_3D, 1, GL_RGBA32F, res.x, res.y, res.z * lights);
    setVolumeSampling();
    glActiveTexture(GL_TEXTURE0);
    if (glGetError() != GL_NO_ERROR)
        throw Error("light volumes", "the driver refused " + std::to_string(lights) +
                                         " RGBA32F volumes of " + std::to_string(res.x) + "x" +
                                         std::to_string(res.y) + "x" + std::to_string(res.z));
    resolution_ = res;
    lights_ = lights;
}

void LightVolumesGpu::compute(const ViewSetup& setup, VolumeTextures& fields,
                              GpuStageTimer* timer) {
    const shared::GpuViewParams& p = setup.params;
    const glm::ivec3 res(p.resolution.x, p.resolution.y, p.resolution.z);
    if (shared::lightCount(p) == 0) return;
    allocate(res, shared::lightCount(p));
    if (timer) timer->begin("light");
    fields.bind();
    // The light texture is written through an image unit; its texture unit gets nothing.
    glActiveTexture(GL_TEXTURE0 + EK_UNIT_LIGHT_TRANSMITTANCE);
    glBindTexture(GL_TEXTURE_3D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindImageTexture(EK_IMAGE_LIGHT_TRANSMITTANCE, texture_, 0, GL_TRUE, 0, GL_READ_WRITE,
                       GL_RGBA32F);
    shared::LightKernelCpu hostKernel{{p}};  // the shared sweep decisions, on the host
    for (int l = 0; l < shared::lightCount(p); ++l) {
        if (shared::lightInFluence(p, l)) continue;  // never read
        if (!hostKernel.sweepsLight(l)) {
            march_->use();
            march_->setInt("lightIndex", l);
            glDispatchCompute(GLuint((res.x + 3) / 4), GLuint((res.y + 3) / 4),
                              GLuint((res.z + 3) / 4));
            continue;
        }
        sweep_->use();
        sweep_->setInt("lightIndex", l);
        const glm::vec3 d(p.lights[l].direction);
        const int axis = hostKernel.sweepAxis(d);
        const int order = hostKernel.sweepOrder(d, axis);
        const int u = (axis + 1) % 3, w = (axis + 2) % 3;
        for (int n = 0; n < res[axis]; ++n) {
            sweep_->setInt("slice", order > 0 ? n : res[axis] - 1 - n);
            glDispatchCompute(GLuint((res[u] + 7) / 8), GLuint((res[w] + 7) / 8), 1);
            // The next slice reads this one through imageLoad.
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    if (timer) timer->end();
}

void LightVolumesGpu::bind() const {
    glActiveTexture(GL_TEXTURE0 + EK_UNIT_LIGHT_TRANSMITTANCE);
    glBindTexture(GL_TEXTURE_3D, texture_);
    glActiveTexture(GL_TEXTURE0);
}

LightVolumeCpu LightVolumesGpu::download(int light) const {
    const size_t n = size_t(resolution_.x) * size_t(resolution_.y) * size_t(resolution_.z);
    std::vector<glm::vec4> all(n * size_t(lights_));
    glBindTexture(GL_TEXTURE_3D, texture_);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_FLOAT, all.data());
    return LightVolumeCpu(all.begin() + std::ptrdiff_t(n * size_t(light)),
                          all.begin() + std::ptrdiff_t(n * size_t(light + 1)));
}

}  // namespace eikon
