#pragma once
// Dense field volumes on the GPU: one R32F 3D texture holding every field slot, stacked along z
// (slot s at z offset s·resolution.z; see shaders/volume_bindings.glsl for why). A slot is
// re-uploaded only when its field, the field's version or the render volume changed, so a camera
// or light change costs no upload; uploads() counts what was sent, for tests and --stats.
#include <cstdint>
#include <string>
#include <vector>

#include "core/dense_grid.h"

namespace eikon {

// Sampling state for the bound GL_TEXTURE_3D: linear filtering (used when the shaders let the
// texture unit filter; texelFetch ignores it) and clamping to the edge.
void setVolumeSampling();

class VolumeTextures {
public:
    VolumeTextures() = default;
    ~VolumeTextures();
    VolumeTextures(const VolumeTextures&) = delete;
    VolumeTextures& operator=(const VolumeTextures&) = delete;

    // Makes slot s hold slotGrids[s] (all on one render volume); returns how many slots had to
    // be uploaded. Throws eikon::Error when the stack exceeds the driver's 3D texture size.
    int update(const std::vector<const DenseGrid*>& slotGrids);
    // Binds the stacked texture to texture unit EK_UNIT_FIELDS (shaders/shared/bindings.h).
    void bind() const;

    int uploads() const { return uploads_; }
    std::uint64_t uploadedBytes() const { return uploadedBytes_; }

private:
    struct Slot {
        std::string field;
        std::uint64_t version = 0;
        RenderVolume volume;
    };
    unsigned texture_ = 0;
    glm::ivec3 resolution_{0};
    std::vector<Slot> slots_;
    int uploads_ = 0;
    std::uint64_t uploadedBytes_ = 0;
};

}  // namespace eikon
