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

bool sameBits(const glm::vec4& a, const glm::vec4& b) {
    return std::memcmp(&a, &b, sizeof(glm::vec4)) == 0;
}

}  // namespace

ConstantBricks::ConstantBricks(glm::ivec3 res) : resolution(res) {
    const int edge = 1 << kConstantBrickShift;
    count = (res + glm::ivec3(edge - 1)) / edge;
    std::fill(std::begin(column), std::end(column), -1);
    mask.assign(size_t(count.x) * size_t(count.y) * size_t(count.z), 0);
}

template <typename Fetch>
void ConstantBricks::add(int slot, const Fetch& fetch) {
    if (slot < 0 || slot >= kVolumeSlotCount || column[slot] >= 0)
        throw Error("constant bricks", "slot " + std::to_string(slot) + " added twice or unknown");
    column[slot] = columns++;
    values.resize(size_t(columns) * mask.size());
    const int edge = 1 << kConstantBrickShift;
    const glm::ivec3 last = resolution - glm::ivec3(1);
    const auto voxelIndex = [&](int x, int y, int z) {
        return (size_t(z) * size_t(resolution.y) + size_t(y)) * size_t(resolution.x) + size_t(x);
    };
    const uint16_t bit = uint16_t(1u << slot);
    tbb::parallel_for(tbb::blocked_range<int>(0, count.z), [&](const tbb::blocked_range<int>& r) {
        for (int bz = r.begin(); bz != r.end(); ++bz)
            for (int by = 0; by < count.y; ++by)
                for (int bx = 0; bx < count.x; ++bx) {
                    // The corners i0 of the brick and the voxels i0 + 1 beside them, clamped.
                    const glm::ivec3 lo = glm::ivec3(bx, by, bz) * edge;
                    const glm::ivec3 hi = glm::min(lo + edge, last);
                    const glm::vec4 first = fetch(voxelIndex(lo.x, lo.y, lo.z));
                    bool constant = finite(first);
                    for (int z = lo.z; z <= hi.z && constant; ++z)
                        for (int y = lo.y; y <= hi.y && constant; ++y)
                            for (int x = lo.x; x <= hi.x && constant; ++x)
                                constant = sameBits(fetch(voxelIndex(x, y, z)), first);
                    if (!constant) continue;
                    const size_t b = brickIndex(lo);
                    mask[b] = uint16_t(mask[b] | bit);
                    values[size_t(column[slot]) * mask.size() + b] = first;
                }
    });
}

void ConstantBricks::addField(int slot, const float* field) {
    add(slot, [field](size_t i) { return glm::vec4(field[i], 0.0f, 0.0f, 0.0f); });
}

void ConstantBricks::addVolume(int slot, const glm::vec4* volume) {
    add(slot, [volume](size_t i) { return volume[i]; });
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
