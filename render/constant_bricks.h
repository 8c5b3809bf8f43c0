#pragma once
// Constant bricks for the CPU twins' trilinear samples: bricks of 4×4×4 voxel corners over which
// a volume holds one value. A trilinear sample (shaders/shared/sampling.h) whose lower corner
// voxel i0 lies in brick b reads voxels i0 and i0 + 1 (clamped at the faces), all within b's
// voxels and one more on its high faces. Where every one of them holds the same value c, each of
// the eight corners is c and the sample is mix(mix(mix(c, c, fx), ·, fy), ·, fz): sampleVolume
// takes those three mixes (EK_CONSTANT_BRICKS) without fetching the eight corners, and gets the
// same floats. Such regions are common: n and ∇n = +0 inside and outside a glass, the fluence
// where no photon went, the density in a uniform fog. tests/render/test_constant_bricks.cpp holds
// the samples and the pictures to the bit.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shaders/shared/gpu_types.h"

namespace eikon {

constexpr int kConstantBrickShift = 2;  // a brick is 2^2 = 4 corner voxels an edge
// Every slot of the volume passes' fetchVolume (shaders/shared/volume_slots.h).
constexpr int kVolumeSlotCount = EK_FLUENCE_DIRECTION_SLOT + 1;

struct ConstantBricks {
    glm::ivec3 resolution{0};
    glm::ivec3 count{0};  // bricks per axis
    int columns = 0;      // slots added
    int column[kVolumeSlotCount];
    // Bit s of a brick's mask: slot s holds one value over the brick; x fastest, then y, then z.
    std::vector<uint16_t> mask;
    // The value, what fetchVolume returns for every voxel there: [column[s] * bricks + brick].
    std::vector<glm::vec4> values;

    // Bricks for a volume of `res` voxels with no slot added yet.
    explicit ConstantBricks(glm::ivec3 res);
    // Finds where slot `slot` is constant: a field (fetchVolume gives (value, 0, 0, 0)) or a
    // volume of vec4. Each slot once, before any sample is taken. Values compare by their bits
    // (+0 and −0 differ), and a brick holding a NaN or an infinity is never constant.
    void addField(int slot, const float* values);
    void addVolume(int slot, const glm::vec4* values);
    // Bricks (1 in `bricks`, x fastest, then y, then z) whose values need not be found: slots
    // added after this leave them not constant, and their samples fetch the eight corners (the
    // same floats). The view leaves out its empty bricks, where it takes no sample of its own
    // brick. Before any slot is added; `bricks` must outlive the adds.
    void leaveOut(const std::vector<uint8_t>& bricks);

    size_t brickIndex(glm::ivec3 corner) const {
        const glm::ivec3 b = corner >> kConstantBrickShift;
        return (size_t(b.z) * size_t(count.y) + size_t(b.y)) * size_t(count.x) + size_t(b.x);
    }
    // How many bricks hold slot `slot` constant.
    size_t constantCount(int slot) const;

private:
    const std::vector<uint8_t>* leftOut_ = nullptr;
    // A slot of kWords 32-bit words a voxel (1: a field; 4: a vec4), compared by their bits.
    template <int kWords>
    void add(int slot, const void* volume);
};

// Whether the CPU twins take constant bricks' samples that way; EIKON_CONSTANT_BRICKS=0 samples
// every corner (to measure what the bricks gain, and to test that they change nothing).
bool constantBricksEnabled();

}  // namespace eikon
