#include <epoxy/gl.h>

#include <algorithm>
#include <glm/vec4.hpp>

#include "render/shader_program.h"
#include "render/voxelize.h"
#include "shaders/shared/bindings.h"

namespace eikon {

namespace {

template <typename T>
void uploadBuffer(GLuint& buffer, const std::vector<T>& data) {
    if (!buffer) glGenBuffers(1, &buffer);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER,
                 GLsizeiptr(std::max<size_t>(data.size() * sizeof(T), 16)),
                 data.empty() ? nullptr : data.data(), GL_DYNAMIC_DRAW);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

GLuint groups(size_t count, int size) {
    return GLuint((count + size_t(size) - 1) / size_t(size));
}

}  // namespace

CoverageTextureGpu::CoverageTextureGpu(glm::ivec3 resolution) : resolution_(resolution) {
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_3D, texture_);
    glTexStorage3D(GL_TEXTURE_3D, 1, GL_R32F, resolution.x, resolution.y, resolution.z);
}

CoverageTextureGpu::~CoverageTextureGpu() {
    if (texture_) glDeleteTextures(1, &texture_);
}

std::vector<float> CoverageTextureGpu::download() const {
    std::vector<float> out(size_t(resolution_.x) * size_t(resolution_.y) * size_t(resolution_.z));
    glBindTexture(GL_TEXTURE_3D, texture_);
    glGetTexImage(GL_TEXTURE_3D, 0, GL_RED, GL_FLOAT, out.data());
    return out;
}

MeshVoxelizerGpu::MeshVoxelizerGpu()
    : toggle_(std::make_unique<ShaderProgram>(ShaderProgram::compute("voxelize_toggle.comp"))),
      scan_(std::make_unique<ShaderProgram>(ShaderProgram::compute("voxelize_scan.comp"))),
      coverage_(std::make_unique<ShaderProgram>(ShaderProgram::compute("voxelize_coverage.comp"))),
      blur_(std::make_unique<ShaderProgram>(ShaderProgram::compute("gaussian_blur.comp"))) {}

MeshVoxelizerGpu::~MeshVoxelizerGpu() {
    const GLuint buffers[] = {positions_, triangles_, bits_};
    for (GLuint b : buffers)
        if (b) glDeleteBuffers(1, &b);
    if (scratch_) glDeleteTextures(1, &scratch_);
}

std::vector<float> MeshVoxelizerGpu::voxelizeToHost(const TriangleMesh& mesh,
                                                    const RenderVolume& volume) {
    if (!hostTarget_ || hostTarget_->resolution() != volume.resolution) {
        hostTarget_.reset();
        hostTarget_ = std::make_unique<CoverageTextureGpu>(volume.resolution);
    }
    voxelize(mesh, volume, hostTarget_->texture());
    return hostTarget_->download();
}

void MeshVoxelizerGpu::voxelize(const TriangleMesh& mesh, const RenderVolume& volume,
                                unsigned target) {
    const glm::ivec3 res = volume.resolution;
    // The fine grid of shaders/shared/voxelize.h, by its own constants (core/mesh_voxelize.h).
    const int supersample = voxelizeSupersample();
    const glm::ivec3 fineRes = res * supersample;
    const glm::vec3 fineVoxel = volume.voxelSize() / float(supersample);
    const int words = voxelizeWordsPerColumn(fineRes.z);
    const size_t columns = size_t(fineRes.x) * size_t(fineRes.y);

    std::vector<glm::vec4> positions;
    positions.reserve(mesh.positions.size());
    for (const glm::vec3& p : mesh.positions) positions.emplace_back(p, 1.0f);
    std::vector<glm::uvec4> triangles;
    triangles.reserve(mesh.triangles.size());
    for (const glm::uvec3& t : mesh.triangles) triangles.emplace_back(t, 0u);
    uploadBuffer(positions_, positions);
    uploadBuffer(triangles_, triangles);
    // The bit columns are kept between calls and cleared on the GPU: no zeros sent each frame.
    const size_t bitWords = columns * size_t(words);
    if (!bits_ || bitWords != bitWords_) {
        uploadBuffer(bits_, std::vector<GLuint>(bitWords, 0u));
        bitWords_ = bitWords;
    } else {
        const GLuint zero = 0;
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, bits_);
        glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT,
                          &zero);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    }

    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_VOXELIZE_POSITIONS, positions_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_VOXELIZE_TRIANGLES, triangles_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_VOXELIZE_BITS, bits_);

    toggle_->use();
    toggle_->setVec3("volumeMin", volume.bounds.min);
    toggle_->setVec3("fineVoxelSize", fineVoxel);
    toggle_->setIVec3("fineResolution", fineRes);
    toggle_->setInt("triangleCount", int(triangles.size()));
    toggle_->setInt("wordsPerColumn", words);
    if (!triangles.empty()) glDispatchCompute(groups(triangles.size(), 64), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    scan_->use();
    scan_->setInt("columnCount", int(columns));
    scan_->setInt("wordsPerColumn", words);
    glDispatchCompute(groups(columns, 64), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    coverage_->use();
    coverage_->setIVec3("resolution", res);
    coverage_->setIVec3("fineResolution", fineRes);
    glBindImageTexture(EK_IMAGE_COVERAGE, target, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    glDispatchCompute(groups(size_t(res.x), 4), groups(size_t(res.y), 4), groups(size_t(res.z), 4));
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void MeshVoxelizerGpu::ensureScratch(glm::ivec3 res) {
    if (scratch_ && scratchRes_ == res) return;
    if (scratch_) glDeleteTextures(1, &scratch_);
    glGenTextures(1, &scratch_);
    glBindTexture(GL_TEXTURE_3D, scratch_);
    glTexStorage3D(GL_TEXTURE_3D, 1, GL_R32F, res.x, res.y, res.z);
    scratchRes_ = res;
}

void MeshVoxelizerGpu::blur(unsigned texture, glm::ivec3 res, const IndexBlurSettings& settings) {
    if (settings.radiusVoxels <= 0) return;
    ensureScratch(res);
    blur_->use();
    blur_->setIVec3("resolution", res);
    blur_->setFloat("sigma", settings.sigmaVoxels);
    blur_->setInt("radius", settings.radiusVoxels);
    // x: texture → scratch, y: scratch → texture, z: texture → scratch, then copied back.
    const unsigned order[4] = {texture, scratch_, texture, scratch_};
    for (int axis = 0; axis < 3; ++axis) {
        blur_->setInt("axis", axis);
        glBindImageTexture(EK_IMAGE_BLUR_SOURCE, order[axis], 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32F);
        glBindImageTexture(EK_IMAGE_BLUR_TARGET, order[axis + 1], 0, GL_TRUE, 0, GL_WRITE_ONLY,
                           GL_R32F);
        glDispatchCompute(groups(size_t(res.x), 4), groups(size_t(res.y), 4),
                          groups(size_t(res.z), 4));
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    }
    glCopyImageSubData(scratch_, GL_TEXTURE_3D, 0, 0, 0, 0, texture, GL_TEXTURE_3D, 0, 0, 0, 0,
                       res.x, res.y, res.z);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace eikon
