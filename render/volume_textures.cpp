#include "render/volume_textures.h"

#include <epoxy/gl.h>

#include "core/error.h"
#include "shaders/shared/bindings.h"

namespace eikon {

void setVolumeSampling() {
    // No mipmaps: a LINEAR (not MIPMAP) minification filter keeps the texture complete.
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTexParameteri(GL_TEXTURE_3D, wrap, GL_CLAMP_TO_EDGE);
}

VolumeTextures::~VolumeTextures() {
    if (texture_) glDeleteTextures(1, &texture_);
}

int VolumeTextures::update(const std::vector<const DenseGrid*>& slotGrids) {
    if (slotGrids.empty()) return 0;
    const glm::ivec3 res = slotGrids.front()->volume.resolution;
    const int count = int(slotGrids.size());
    if (!texture_ || res != resolution_ || count != int(slots_.size())) {
        GLint maxSize = 0;
        glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
        if (res.x > maxSize || res.y > maxSize || res.z * count > maxSize)
            throw Error("upload", std::to_string(count) + " field volume(s) of " +
                                      std::to_string(res.x) + "x" + std::to_string(res.y) + "x" +
                                      std::to_string(res.z) + " need a 3D texture of depth " +
                                      std::to_string(res.z * count) + "; this driver allows " +
                                      std::to_string(maxSize) +
                                      " per side (lower the scene's volume resolution)");
        if (texture_) glDeleteTextures(1, &texture_);
        glGenTextures(1, &texture_);
        glBindTexture(GL_TEXTURE_3D, texture_);
        glTexStorage3D(GL_TEXTURE_3D, 1, GL_R32F, res.x, res.y, res.z * count);
        setVolumeSampling();
        resolution_ = res;
        slots_.assign(size_t(count), Slot{});  // everything uploads again
    }
    int uploaded = 0;
    glBindTexture(GL_TEXTURE_3D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (int s = 0; s < count; ++s) {
        const DenseGrid& grid = *slotGrids[size_t(s)];
        Slot& slot = slots_[size_t(s)];
        if (grid.volume.resolution != res)
            throw Error("upload", "field '" + grid.field + "' was resampled on another volume");
        if (slot.version == grid.version && slot.field == grid.field &&
            slot.volume == grid.volume && grid.version != 0)
            continue;
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, s * res.z, res.x, res.y, res.z, GL_RED, GL_FLOAT,
                        grid.values.data());
        slot.field = grid.field;
        slot.version = grid.version;
        slot.volume = grid.volume;
        ++uploaded;
        uploadedBytes_ += grid.values.size() * sizeof(float);
    }
    if (glGetError() != GL_NO_ERROR)
        throw Error("upload", "the driver refused the field volumes (out of memory?)");
    uploads_ += uploaded;
    return uploaded;
}

void VolumeTextures::bind() const {
    glActiveTexture(GL_TEXTURE0 + EK_UNIT_FIELDS);
    glBindTexture(GL_TEXTURE_3D, texture_);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace eikon
