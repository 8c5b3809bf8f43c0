#include "render/empty_bricks.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/common.hpp>

namespace eikon {

namespace {

// Whether a voxel holds something a view step could see or be bent by. NaN counts as something.
bool voxelOccupied(size_t i, const std::vector<const float*>& fields, const glm::vec4* gradient) {
    for (const float* f : fields)
        if (!(f[i] == 0.0f)) return true;
    if (!gradient) return false;
    const glm::vec4 g = gradient[i];
    // +0 exactly: a −0 would turn the sign of a zero in the ray's momentum (v + dτ·n∇n).
    for (int k = 0; k < 3; ++k)
        if (g[k] != 0.0f || std::signbit(g[k])) return true;
    return !(g.w >= 0.5f);
}

}  // namespace

size_t EmptyBricks::emptyCount() const {
    return size_t(std::count(empty.begin(), empty.end(), uint8_t(1)));
}

EmptyBricks findEmptyBricks(glm::ivec3 res, const std::vector<const float*>& fields,
                            const glm::vec4* gradient) {
    EmptyBricks bricks;
    const int edge = 1 << kEmptyBrickShift;
    bricks.count = (res + glm::ivec3(edge - 1)) / edge;
    const glm::ivec3 c = bricks.count;
    const auto voxelIndex = [&](int x, int y, int z) {
        return (size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) + size_t(x);
    };
    std::vector<uint8_t> occupied(size_t(res.x) * size_t(res.y) * size_t(res.z));
    tbb::parallel_for(tbb::blocked_range<int>(0, res.z), [&](const tbb::blocked_range<int>& r) {
        for (int z = r.begin(); z != r.end(); ++z)
            for (int y = 0; y < res.y; ++y)
                for (int x = 0; x < res.x; ++x) {
                    const size_t i = voxelIndex(x, y, z);
                    occupied[i] = voxelOccupied(i, fields, gradient) ? 1 : 0;
                }
    });
    bricks.empty.assign(size_t(c.x) * size_t(c.y) * size_t(c.z), 0);
    tbb::parallel_for(tbb::blocked_range<int>(0, c.z), [&](const tbb::blocked_range<int>& r) {
        for (int bz = r.begin(); bz != r.end(); ++bz)
            for (int by = 0; by < c.y; ++by)
                for (int bx = 0; bx < c.x; ++bx) {
                    // The brick's voxels and one more on every side, clamped at the volume's faces
                    // (a sample there reads the face's voxels, as GL_CLAMP_TO_EDGE does).
                    const glm::ivec3 lo =
                        glm::max(glm::ivec3(bx, by, bz) * edge - 1, glm::ivec3(0));
                    const glm::ivec3 hi =
                        glm::min(glm::ivec3(bx, by, bz) * edge + edge, res - glm::ivec3(1));
                    bool any = false;
                    for (int z = lo.z; z <= hi.z && !any; ++z)
                        for (int y = lo.y; y <= hi.y && !any; ++y)
                            for (int x = lo.x; x <= hi.x && !any; ++x)
                                any = occupied[voxelIndex(x, y, z)] != 0;
                    const size_t b =
                        (size_t(bz) * size_t(c.y) + size_t(by)) * size_t(c.x) + size_t(bx);
                    bricks.empty[b] = any ? 0 : 1;
                }
    });
    return bricks;
}

}  // namespace eikon
