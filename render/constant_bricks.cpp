#include "render/constant_bricks.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/common.hpp>

#include "core/error.h"

namespace eikon {

namespace {

bool finite(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

uint32_t wordAt(const unsigned char* bytes, size_t word) {
    uint32_t w;
    std::memcpy(&w, bytes + word * sizeof(uint32_t), sizeof(uint32_t));
    return w;
}

// Whether every voxel in [lo, hi] (inclusive) of a volume of `words` 32-bit words a voxel holds
// the bits of voxel lo. The words of each row are compared without a branch and each row decides,
// where a vec4 a voxel went through memcmp: the Houdini smoke's view pass (111×222×112, the
// density and the light volume) took 413.5 -> 396.4 ms on one core (BENCHMARKS.md).
template <int kWords>
bool sameBitsOver(const unsigned char* bytes, glm::ivec3 res, glm::ivec3 lo, glm::ivec3 hi) {
    const auto voxelIndex = [&](int x, int y, int z) {
        return (size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) + size_t(x);
    };
    uint32_t first[kWords];
    for (int w = 0; w < kWords; ++w)
        first[w] = wordAt(bytes, voxelIndex(lo.x, lo.y, lo.z) * kWords + w);
    const int rowVoxels = hi.x - lo.x + 1;
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y) {
            const size_t row = voxelIndex(lo.x, y, z) * kWords;
            uint32_t differ = 0;
            for (int x = 0; x < rowVoxels; ++x)
                for (int w = 0; w < kWords; ++w)
                    differ |= wordAt(bytes, row + size_t(x * kWords + w)) ^ first[w];
            if (differ) return false;
        }
    return true;
}

}  // namespace

ConstantBricks::ConstantBricks(glm::ivec3 res) : resolution(res) {
    const int edge = 1 << kConstantBrickShift;
    count = (res + glm::ivec3(edge - 1)) / edge;
    std::fill(std::begin(column), std::end(column), -1);
    mask.assign(size_t(count.x) * size_t(count.y) * size_t(count.z), 0);
}

template <int kWords>
void ConstantBricks::add(int slot, const void* volume) {
    if (slot < 0 || slot >= kVolumeSlotCount || column[slot] >= 0)
        throw Error("constant bricks", "slot " + std::to_string(slot) + " added twice or unknown");
    column[slot] = columns++;
    values.resize(size_t(columns) * mask.size());
    const auto* bytes = static_cast<const unsigned char*>(volume);
    const int edge = 1 << kConstantBrickShift;
    const glm::ivec3 last = resolution - glm::ivec3(1);
    const uint16_t bit = uint16_t(1u << slot);
    tbb::parallel_for(tbb::blocked_range<int>(0, count.z), [&](const tbb::blocked_range<int>& r) {
        for (int bz = r.begin(); bz != r.end(); ++bz)
            for (int by = 0; by < count.y; ++by)
                for (int bx = 0; bx < count.x; ++bx) {
                    // The corners i0 of the brick and the voxels i0 + 1 beside them, clamped.
                    const glm::ivec3 lo = glm::ivec3(bx, by, bz) * edge;
                    if (leftOut_ && (*leftOut_)[brickIndex(lo)]) continue;
                    const glm::ivec3 hi = glm::min(lo + edge, last);
                    const size_t firstVoxel = (size_t(lo.z) * size_t(resolution.y) + size_t(lo.y)) *
                                                  size_t(resolution.x) +
                                              size_t(lo.x);
                    glm::vec4 first(0.0f);
                    std::memcpy(&first, bytes + firstVoxel * kWords * sizeof(float),
                                kWords * sizeof(float));
                    // Every voxel holds first's bits: all finite where first is.
                    if (!finite(first) || !sameBitsOver<kWords>(bytes, resolution, lo, hi))
                        continue;
                    const size_t b = brickIndex(lo);
                    mask[b] = uint16_t(mask[b] | bit);
                    values[size_t(column[slot]) * mask.size() + b] = first;
                }
    });
}

void ConstantBricks::leaveOut(const std::vector<uint8_t>& bricks) {
    if (columns > 0 || bricks.size() != mask.size())
        throw Error("constant bricks", "bricks left out after a slot, or of another volume");
    leftOut_ = &bricks;
}

void ConstantBricks::addField(int slot, const float* field) {
    add<1>(slot, field);  // fetchVolume gives (value, 0, 0, 0): the value alone decides
}

void ConstantBricks::addVolume(int slot, const glm::vec4* volume) {
    static_assert(sizeof(glm::vec4) == 4 * sizeof(float));
    add<4>(slot, volume);
}

size_t ConstantBricks::constantCount(int slot) const {
    const uint16_t bit = uint16_t(1u << slot);
    return size_t(std::count_if(mask.begin(), mask.end(), [bit](uint16_t m) { return m & bit; }));
}

bool constantBricksEnabled() {
    const char* env = std::getenv("EIKON_CONSTANT_BRICKS");
    return !(env && std::string(env) == "0");
}

}  // namespace eikon
