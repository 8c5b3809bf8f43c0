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

// The bricks of a volume of `res` voxels. fields: every material slot's values; gradient: the
// ∇n volume (xyz ∇n, w n) when the view's rays are curved, else null.
EmptyBricks findEmptyBricks(glm::ivec3 res, const std::vector<const float*>& fields,
                            const glm::vec4* gradient);

}  // namespace eikon
