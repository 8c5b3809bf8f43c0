#include "render/transport/deposit_volumes_gpu.h"

#include <epoxy/gl.h>

#include <string>

#include "core/error.h"
#include "render/gpu_timer.h"
#include "render/gpu_transfer.h"
#include "render/receiver_map.h"
#include "render/shader_program.h"
#include "render/smoothing.h"
#include "render/transport/fixed_point.h"
#include "render/volume_textures.h"
#include "shaders/shared/bindings.h"

namespace eikon {

void readFixedDeposits(unsigned buffer, glm::ivec3 res, const glm::dvec4& scale,
                       std::vector<glm::vec4>& radiance, std::vector<glm::vec4>& direction) {
    constexpr size_t kWords = 12;  // 6 sums of (low, high) words a voxel
    const size_t voxels = size_t(res.x) * size_t(res.y) * size_t(res.z);
    const std::vector<unsigned> words = readStorageWords(buffer, 0, voxels * kWords);
    radiance.assign(voxels, glm::vec4(0.0f));
    direction.assign(voxels, glm::vec4(0.0f));
    for (size_t i = 0; i < voxels; ++i) {
        const unsigned* cell = &words[i * kWords];
        for (int c = 0; c < 3; ++c) {
            radiance[i][c] = float(fromFixedPoint(joinFixedWords(cell + 2 * c), scale[c]));
            direction[i][c] = float(fromFixedPoint(joinFixedWords(cell + 6 + 2 * c), scale.w));
        }
    }
}

std::vector<glm::vec4> readFixedReceiverMap(unsigned buffer, const shared::GpuViewParams& params,
                                            const glm::dvec3& e) {
    const size_t sums = 3 * receiverMapTexels(params);
    const std::vector<unsigned> words = readStorageWords(buffer, 0, 2 * sums);
    std::vector<int64_t> fixed(sums);
    for (size_t i = 0; i < sums; ++i) fixed[i] = joinFixedWords(&words[2 * i]);
    return receiverMapFromFixed(
        params, fixed,
        glm::dvec3(fixedPointScaleFor(e.x, 1.0), fixedPointScaleFor(e.y, 1.0),
                   fixedPointScaleFor(e.z, 1.0)));
}

DepositVolumesGpu::DepositVolumesGpu()
    : smoother_(std::make_unique<VolumeSmootherGpu>()),
      resolve_(std::make_unique<ShaderProgram>(ShaderProgram::compute("photon_resolve.comp"))) {}

DepositVolumesGpu::~DepositVolumesGpu() {
    glDeleteTextures(2, raw_);
    glDeleteTextures(2, smoothed_);
    if (receiverMap_) glDeleteBuffers(1, &receiverMap_);
}

void DepositVolumesGpu::allocate(glm::ivec3 res) {
    if (raw_[0] && res == resolution_) return;
    glDeleteTextures(2, raw_);
    glDeleteTextures(2, smoothed_);
    glGenTextures(2, raw_);
    glGenTextures(2, smoothed_);
    for (unsigned* t : {&raw_[0], &raw_[1], &smoothed_[0], &smoothed_[1]}) {
        glBindTexture(GL_TEXTURE_3D, *t);
        glTexStorage3D(GL_TEXTURE_3D, 1, GL_RGBA32F, res.x, res.y, res.z);
        setVolumeSampling();
    }
    glBindTexture(GL_TEXTURE_3D, 0);
    if (glGetError() != GL_NO_ERROR)
        throw Error("photon radiance", "the driver refused four RGBA32F volumes of " +
                                           std::to_string(res.x) + "x" + std::to_string(res.y) +
                                           "x" + std::to_string(res.z));
    resolution_ = res;
}

void DepositVolumesGpu::compute(glm::ivec3 res, unsigned depositBuffer, const glm::dvec4& s,
                                const std::vector<glm::vec4>& receiverMap, GpuStageTimer* timer) {
    allocate(res);
    if (timer) timer->begin("smooth");
    // Neither volume may stay bound for sampling while images write it.
    for (GLuint unit : {EK_UNIT_FLUENCE, EK_UNIT_FLUENCE_DIRECTION}) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_3D, 0);
    }
    glActiveTexture(GL_TEXTURE0);
    resolve_->use();
    resolve_->setIVec3("resolution", res);
    glUniform4d(resolve_->uniformLocation("depositScale"), s.x, s.y, s.z, s.w);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_PHOTON_DEPOSITS, depositBuffer);
    glBindImageTexture(EK_IMAGE_PHOTON_RADIANCE_RAW, raw_[0], 0, GL_TRUE, 0, GL_WRITE_ONLY,
                       GL_RGBA32F);
    glBindImageTexture(EK_IMAGE_PHOTON_DIRECTION_RAW, raw_[1], 0, GL_TRUE, 0, GL_WRITE_ONLY,
                       GL_RGBA32F);
    glDispatchCompute(GLuint((res.x + 3) / 4), GLuint((res.y + 3) / 4), GLuint((res.z + 3) / 4));
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    smoother_->smooth(raw_[0], smoothed_[0], res);
    smoother_->smooth(raw_[1], smoothed_[1], res);
    if (timer) timer->end();
    // The map is read back and converted on the host by the twin's own code (a few hundred KB,
    // once per trace), then uploaded for the view pass.
    uploadVec4Buffer(receiverMap_, receiverMap);
    if (const GLenum err = glGetError(); err != GL_NO_ERROR)
        throw Error("photon radiance", "OpenGL error " + std::to_string(err));
}

void DepositVolumesGpu::bind() const {
    glActiveTexture(GL_TEXTURE0 + EK_UNIT_FLUENCE);
    glBindTexture(GL_TEXTURE_3D, smoothed_[0]);
    glActiveTexture(GL_TEXTURE0 + EK_UNIT_FLUENCE_DIRECTION);
    glBindTexture(GL_TEXTURE_3D, smoothed_[1]);
    glActiveTexture(GL_TEXTURE0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_RECEIVER_MAP, receiverMap_);
}

std::vector<glm::vec4> DepositVolumesGpu::radiance() const {
    return downloadRgbaVolume(smoothed_[0], resolution_);
}

std::vector<glm::vec4> DepositVolumesGpu::direction() const {
    return downloadRgbaVolume(smoothed_[1], resolution_);
}

}  // namespace eikon
