#include <epoxy/gl.h>

#include <string>

#include "core/error.h"
#include "render/gpu_timer.h"
#include "render/params_buffer.h"
#include "render/refraction_volume.h"
#include "render/shader_program.h"
#include "render/volume_textures.h"
#include "shaders/shared/bindings.h"

namespace eikon {

namespace {

size_t voxelCount(glm::ivec3 r) {
    return size_t(r.x) * size_t(r.y) * size_t(r.z);
}

// Groups of 4x4x4 covering `size` (the local size of the three shaders).
void dispatchCovering(glm::ivec3 size) {
    glDispatchCompute(GLuint((size.x + 3) / 4), GLuint((size.y + 3) / 4), GLuint((size.z + 3) / 4));
}

GLuint makeVolumeTexture(glm::ivec3 res) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_3D, texture);
    glTexStorage3D(GL_TEXTURE_3D, 1, GL_RGBA32F, res.x, res.y, res.z);
    setVolumeSampling();
    glBindTexture(GL_TEXTURE_3D, 0);
    return texture;
}

}  // namespace

RefractionVolumesGpu::RefractionVolumesGpu() {
    gradientProgram_ =
        std::make_unique<ShaderProgram>(ShaderProgram::compute("refraction_gradient.comp"));
    minMaxProgram_ = std::make_unique<ShaderProgram>(ShaderProgram::compute("octree_minmax.comp"));
    labelProgram_ = std::make_unique<ShaderProgram>(ShaderProgram::compute("octree_label.comp"));
}

RefractionVolumesGpu::~RefractionVolumesGpu() {
    if (gradient_) glDeleteTextures(1, &gradient_);
    if (octree_) glDeleteTextures(1, &octree_);
    if (pyramid_) glDeleteBuffers(1, &pyramid_);
    deleteChannelGradients();
}

void RefractionVolumesGpu::deleteChannelGradients() {
    for (unsigned& texture : channelGradients_)
        if (texture) glDeleteTextures(1, &texture);
    channelGradients_[0] = channelGradients_[1] = 0;
}

void RefractionVolumesGpu::allocate(glm::ivec3 res) {
    if (gradient_ && res == resolution_) return;
    if (gradient_) glDeleteTextures(1, &gradient_);
    if (octree_) glDeleteTextures(1, &octree_);
    if (pyramid_) glDeleteBuffers(1, &pyramid_);
    deleteChannelGradients();
    gradient_ = makeVolumeTexture(res);
    octree_ = makeVolumeTexture(res);
    const size_t nodes = octreePyramidNodeCount(res);
    glGenBuffers(1, &pyramid_);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, pyramid_);
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(nodes * sizeof(glm::vec4)), nullptr,
                 GL_DYNAMIC_COPY);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    if (glGetError() != GL_NO_ERROR)
        throw Error("refraction volumes", "the driver refused two RGBA32F volumes of " +
                                              std::to_string(res.x) + "x" + std::to_string(res.y) +
                                              "x" + std::to_string(res.z));
    resolution_ = res;
}

void RefractionVolumesGpu::compute(const ViewSetup& setup, VolumeTextures& fields,
                                   const OctreeSettings& settings, GpuStageTimer* timer,
                                   bool withOctree) {
    const glm::ivec3 res(setup.params.resolution);
    allocate(res);
    fields.bind();
    if (timer) timer->begin("gradient");
    computeGradient(gradient_, res);
    if (timer) timer->end();
    if (!withOctree) return;
    if (timer) timer->begin("octree");
    computeOctree(setup, settings);
    if (timer) timer->end();
}

void RefractionVolumesGpu::computeChannelGradients(const ViewSetup& setup, VolumeTextures& fields,
                                                   ParamsBuffer& params, GpuStageTimer* timer) {
    const glm::ivec3 res(setup.params.resolution);
    allocate(res);
    // Made before the fields are bound: making a texture binds it, and then 0, to the active unit.
    for (unsigned& texture : channelGradients_)
        if (!texture) texture = makeVolumeTexture(res);
    fields.bind();
    if (timer) timer->begin("gradient");
    for (int k = 0; k < 2; ++k) {
        params.upload(channelViewParams(setup, k == 0 ? 0 : 2));
        computeGradient(channelGradients_[k], res);
    }
    params.upload(setup.params);
    if (timer) timer->end();
    if (glGetError() != GL_NO_ERROR)
        throw Error("refraction volumes", "the driver refused the red and blue channels' volumes");
}

unsigned RefractionVolumesGpu::channelGradientTexture(int channel) const {
    if (channel == 1) return gradient_;
    return channelGradients_[channel == 0 ? 0 : 1];
}

void RefractionVolumesGpu::computeGradient(unsigned texture, glm::ivec3 res) {
    gradientProgram_->use();
    glBindImageTexture(EK_IMAGE_GRADIENT, texture, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatchCovering(res);
    // The pyramid's level 0 reads n through imageLoad; later passes may sample the texture.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void RefractionVolumesGpu::computeOctree(const ViewSetup& setup, const OctreeSettings& settings) {
    const glm::ivec3 res = resolution_;
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_OCTREE_PYRAMID, pyramid_);
    minMaxProgram_->use();
    minMaxProgram_->setIVec3("resolution", res);
    glBindImageTexture(EK_IMAGE_GRADIENT, gradient_, 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    for (int level = 0; level < octreeLevelCount(res); ++level) {
        minMaxProgram_->setInt("level", level);
        dispatchCovering(octreeLevelSize(res, level));
        // The next level reads this one from the SSBO.
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    labelProgram_->use();
    labelProgram_->setIVec3("resolution", res);
    labelProgram_->setFloat("epsilon", settings.epsilon);
    labelProgram_->setFloat("epsilonPrime", settings.epsilonPrime);
    labelProgram_->setFloat("stepLimit", octreeStepInScene(setup, settings.stepLimitVoxels));
    labelProgram_->setFloat("minStep", octreeStepInScene(setup, settings.minStepVoxels));
    labelProgram_->setFloat("kappaTolerance", settings.kappaTolerance);
    labelProgram_->setFloat("voxelLength", octreeStepInScene(setup, 1.0f));
    glBindImageTexture(EK_IMAGE_OCTREE, octree_, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatchCovering(res);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

RefractionVolumeCpu RefractionVolumesGpu::download(unsigned texture) const {
    RefractionVolumeCpu out(voxelCount(resolution_));
    glBindTexture(GL_TEXTURE_3D, texture);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_FLOAT, out.data());
    glBindTexture(GL_TEXTURE_3D, 0);
    return out;
}

RefractionVolumeCpu RefractionVolumesGpu::downloadGradient() const {
    return download(gradient_);
}
RefractionVolumeCpu RefractionVolumesGpu::downloadOctree() const {
    return download(octree_);
}

}  // namespace eikon
