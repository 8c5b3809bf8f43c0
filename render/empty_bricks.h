#pragma once
// Empty space for the CPU twin's viewing pass: bricks of 4×4×4 voxels through which a view step
// meets nothing. A brick is empty when, over its voxels and the voxels one beyond its faces (what
// a trilinear sample taken anywhere within half a voxel of the brick reads), every material's
// field is zero and, for curved rays, ∇n is exactly +0 with n ≥ 1/2. A step whose samples all fall
// in one such brick adds no radiance, keeps the transmittance (e^0 = 1) and, with no force in the
// ray equation, goes straight: view_march.h (EK_SKIP_EMPTY_SPACE) takes it with that arithmetic,
// without sampling the fields, the fluence or the light volumes, and gets the same floats as the
// full step (the sums gain +0, the products ×1; +0, not −0, so that no sign of zero changes).
// tests/render/test_empty_space.cpp holds the twin to that, bit for bit.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace eikon {

constexpr int kEmptyBrickShift = 2;  // a brick is 2^2 = 4 voxels an edge

struct EmptyBricks {
    glm::ivec3 count{0};         // bricks per axis
    std::vector<uint8_t> empty;  // 1: empty; x fastest, then y, then z
    size_t emptyCount() const;
};

// Where the ray o + d·t (volume index space) leaves the run of empty bricks it is in at t: the
// parameter where it enters the first brick along it that is not empty, or leaves the bricks; t
// where the brick around o + d·t is not empty or outside. The bricks are walked one by one
// (Amanatides and Woo's traversal), at most count.x + count.y + count.z of them; the parameter is
// as exact as float arithmetic makes it, to a few units in the last place.
inline float emptyRunEnd(const uint8_t* empty, glm::ivec3 count, glm::vec3 o, glm::vec3 d,
                         float t) {
    constexpr float size = float(1 << kEmptyBrickShift);
    const glm::vec3 p = o + d * t;
    glm::ivec3 b;
    glm::ivec3 step(0);
    glm::vec3 next(3.0e38f);    // the parameter of the next face crossed along each axis
    glm::vec3 across(3.0e38f);  // and the parameter a brick takes to cross
    for (int a = 0; a < 3; ++a) {
        const float f = std::floor(p[a] / size);
        if (!(f >= 0.0f && f < float(count[a]))) return t;  // outside (or NaN)
        b[a] = int(f);
        if (d[a] > 0.0f) {
            step[a] = 1;
            next[a] = (float(b[a] + 1) * size - o[a]) / d[a];
            across[a] = size / d[a];
        } else if (d[a] < 0.0f) {
            step[a] = -1;
            next[a] = (float(b[a]) * size - o[a]) / d[a];
            across[a] = -size / d[a];
        }
    }
    const auto at = [&](glm::ivec3 c) {
        return empty[(size_t(c.z) * size_t(count.y) + size_t(c.y)) * size_t(count.x) + size_t(c.x)];
    };
    if (!at(b)) return t;
    for (int bricks = count.x + count.y + count.z; bricks > 0; --bricks) {
        const int a = next.x <= next.y ? (next.x <= next.z ? 0 : 2) : (next.y <= next.z ? 1 : 2);
        if (step[a] == 0) break;  // d = 0 (or NaN): no face ahead
        const float leave = next[a];
        b[a] += step[a];
        if (b[a] < 0 || b[a] >= count[a] || !at(b)) return leave;
        next[a] += across[a];
    }
    return t;
}

// The bricks of a volume of `res` voxels. fields: every material slot's values; gradient: the
// ∇n volume (xyz ∇n, w n) when the view's rays are curved, else null.
EmptyBricks findEmptyBricks(glm::ivec3 res, const std::vector<const float*>& fields,
                            const glm::vec4* gradient);

}  // namespace eikon
