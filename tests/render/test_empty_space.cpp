// Empty space in the CPU twin's viewing pass (render/empty_bricks.h, view_march.h
// EK_SKIP_EMPTY_SPACE): which bricks are empty, and that stepping through them without sampling
// gives the picture of every step taken in full, to the bit.
#include <catch2/catch.hpp>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "render/empty_bricks.h"
#include "support/cpu_view_variants.h"

using eikon::EmptyBricks;
using eikon::findEmptyBricks;

namespace {

size_t brickIndex(const EmptyBricks& b, int x, int y, int z) {
    return (size_t(z) * size_t(b.count.y) + size_t(y)) * size_t(b.count.x) + size_t(x);
}

// A seeded linear congruential sequence: the same random cases on every machine.
struct Sequence {
    uint32_t h;
    uint32_t next(uint32_t n) {  // in [0, n)
        h = h * 1664525u + 1013904223u;
        return (h >> 8) % n;
    }
    float uniform(float lo, float hi) {
        return lo + (hi - lo) * float(next(1u << 20)) / float(1u << 20);
    }
};

}  // namespace

TEST_CASE("empty bricks: a voxel that holds something keeps every brick whose samples read it",
          "[empty_space]") {
    const glm::ivec3 res(12, 8, 10);  // bricks 3 × 2 × 3, the last along z two voxels deep
    const size_t voxels = size_t(res.x) * size_t(res.y) * size_t(res.z);
    std::vector<float> field(voxels, 0.0f);
    const auto at = [&](int x, int y, int z) {
        return (size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) + size_t(x);
    };
    SECTION("all zero: every brick is empty") {
        const EmptyBricks b = findEmptyBricks(res, {field.data()}, nullptr);
        CHECK(b.count == glm::ivec3(3, 2, 3));
        CHECK(b.emptyCount() == 18);
    }
    SECTION("one voxel inside a brick, away from its faces: that brick alone") {
        field[at(5, 1, 5)] = 0.5f;  // brick (1, 0, 1), not beside another brick's voxels
        const EmptyBricks b = findEmptyBricks(res, {field.data()}, nullptr);
        CHECK(b.emptyCount() == 17);
        CHECK(b.empty[brickIndex(b, 1, 0, 1)] == 0);
    }
    SECTION("one voxel on a brick's face: the neighbour across it reads it too") {
        field[at(4, 1, 5)] = 1e-30f;  // brick (1, 0, 1), its first voxel along x
        const EmptyBricks b = findEmptyBricks(res, {field.data()}, nullptr);
        CHECK(b.emptyCount() == 16);
        CHECK(b.empty[brickIndex(b, 0, 0, 1)] == 0);
        CHECK(b.empty[brickIndex(b, 1, 0, 1)] == 0);
    }
    SECTION("a corner voxel reaches the seven bricks around that corner") {
        field[at(3, 3, 3)] = -2.0f;  // brick (0, 0, 0), at its corner toward (1, 1, 1)
        const EmptyBricks b = findEmptyBricks(res, {field.data()}, nullptr);
        CHECK(b.emptyCount() == 18 - 8);
    }
    SECTION("NaN is not empty") {
        field[at(10, 6, 9)] = std::numeric_limits<float>::quiet_NaN();
        const EmptyBricks b = findEmptyBricks(res, {field.data()}, nullptr);
        CHECK(b.empty[brickIndex(b, 2, 1, 2)] == 0);
        CHECK(b.emptyCount() == 17);
    }
    SECTION("curved rays: ∇n must be +0 and n at least 1/2") {
        std::vector<glm::vec4> gradient(voxels, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        CHECK(findEmptyBricks(res, {field.data()}, gradient.data()).emptyCount() == 18);
        // A −0 would turn the sign of a zero in the ray's momentum: not empty.
        gradient[at(5, 1, 5)].y = -0.0f;
        CHECK(findEmptyBricks(res, {field.data()}, gradient.data()).emptyCount() == 17);
        gradient[at(5, 1, 5)].y = 0.0f;
        gradient[at(9, 5, 1)].w = 0.25f;  // brick (2, 1, 0)
        CHECK(findEmptyBricks(res, {field.data()}, gradient.data()).emptyCount() == 17);
        gradient[at(9, 5, 1)].w = 1.0f;
        gradient[at(1, 1, 9)].z = 1e-7f;  // brick (0, 0, 2)
        CHECK(findEmptyBricks(res, {field.data()}, gradient.data()).emptyCount() == 17);
        // Straight rays read no gradient.
        CHECK(findEmptyBricks(res, {field.data()}, nullptr).emptyCount() == 18);
    }
    SECTION("every field counts") {
        std::vector<float> other(voxels, 0.0f);
        other[at(9, 5, 1)] = 3.0f;
        CHECK(findEmptyBricks(res, {field.data(), other.data()}, nullptr).emptyCount() == 17);
    }
}

TEST_CASE("empty bricks are the bricks whose voxels and one more on every side hold nothing",
          "[empty_space]") {
    // Against the definition, brick by brick, on volumes whose edges are not whole bricks, with
    // something in a few voxels (near faces, edges and corners of bricks as often as not).
    Sequence random{12345u};
    const auto next = [&random](uint32_t n) { return random.next(n); };
    for (int trial = 0; trial < 40; ++trial) {
        const glm::ivec3 res(int(next(14)) + 1, int(next(14)) + 1, int(next(14)) + 1);
        const size_t voxels = size_t(res.x) * size_t(res.y) * size_t(res.z);
        std::vector<float> field(voxels, 0.0f);
        std::vector<glm::vec4> gradient(voxels, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        const int filled = int(next(6));
        for (int k = 0; k < filled; ++k) {
            const size_t i = next(uint32_t(voxels));
            if (next(2))
                field[i] = 1.0f;
            else
                gradient[i].x = 0.5f;
        }
        const bool curved = trial % 2 == 1;
        const EmptyBricks b =
            findEmptyBricks(res, {field.data()}, curved ? gradient.data() : nullptr);
        const auto occupied = [&](int x, int y, int z) {
            const size_t i = (size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) + size_t(x);
            return field[i] != 0.0f || (curved && gradient[i].x != 0.0f);
        };
        INFO("trial " << trial << ", " << res.x << "×" << res.y << "×" << res.z);
        REQUIRE(b.count == (res + glm::ivec3(3)) / 4);
        int wrong = 0;
        for (int bz = 0; bz < b.count.z; ++bz)
            for (int by = 0; by < b.count.y; ++by)
                for (int bx = 0; bx < b.count.x; ++bx) {
                    bool any = false;
                    for (int z = std::max(4 * bz - 1, 0); z <= std::min(4 * bz + 4, res.z - 1); ++z)
                        for (int y = std::max(4 * by - 1, 0); y <= std::min(4 * by + 4, res.y - 1);
                             ++y)
                            for (int x = std::max(4 * bx - 1, 0);
                                 x <= std::min(4 * bx + 4, res.x - 1); ++x)
                                any = any || occupied(x, y, z);
                    wrong += b.empty[brickIndex(b, bx, by, bz)] != (any ? 0 : 1);
                }
        CHECK(wrong == 0);
    }
}

TEST_CASE("a ray's run of empty bricks ends where it enters a brick that is not empty",
          "[empty_space]") {
    // Against the bricks read off the ray at 1/1000 of a brick apart, on random grids and rays.
    Sequence random{777u};
    const auto next = [&random](uint32_t n) { return random.next(n); };
    const auto uniform = [&random](float lo, float hi) { return random.uniform(lo, hi); };
    int runs = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const glm::ivec3 count(int(next(6)) + 1, int(next(6)) + 1, int(next(6)) + 1);
        std::vector<uint8_t> empty(size_t(count.x) * size_t(count.y) * size_t(count.z));
        for (uint8_t& e : empty) e = next(5) != 0;  // four in five empty
        const glm::vec3 size = glm::vec3(count) * 4.0f;
        // At t the ray is inside the bricks but for one trial in eight.
        const float margin = trial % 8 == 0 ? 8.0f : 0.0f;
        const glm::vec3 start(uniform(-margin, size.x + margin), uniform(-margin, size.y + margin),
                              uniform(-margin, size.z + margin));
        glm::vec3 d(uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f), uniform(-1.0f, 1.0f));
        if (trial % 7 == 0) d[trial % 3] = 0.0f;  // along a face's plane
        const float t = uniform(0.0f, 8.0f);
        const glm::vec3 o = start - d * t;
        // 1: in an empty brick; 0: in one that is not; -1: outside the bricks.
        const auto state = [&](float s) {
            const glm::ivec3 b = glm::ivec3(glm::floor((o + d * s) / 4.0f));
            if (glm::any(glm::lessThan(b, glm::ivec3(0))) ||
                glm::any(glm::greaterThanEqual(b, count)))
                return -1;
            return int(empty[(size_t(b.z) * size_t(count.y) + size_t(b.y)) * size_t(count.x) +
                             size_t(b.x)]);
        };
        const float end = eikon::emptyRunEnd(empty.data(), count, o, d, t);
        INFO("trial " << trial);
        if (state(t) != 1) {
            CHECK(end == t);
            continue;
        }
        ++runs;
        const float dt = 4.0f / 1000.0f / std::max(glm::length(d), 1e-3f);
        CHECK(end >= t);
        int wrong = 0;
        for (float s = t; s < end - dt && s < t + 1e4f; s += dt) wrong += state(s) != 1;
        CHECK(wrong == 0);  // nothing but empty bricks before the end
        if (glm::length(d) > 1e-3f && end < t + 1e4f) CHECK(state(end + dt) != 1);  // and after
    }
    CHECK(runs > 200);
}

TEST_CASE("skipping empty space gives the picture of every step taken in full, to the bit",
          "[empty_space][view]") {
    CHECK(eikon::test::casesChangedBySwitch("EIKON_SKIP_EMPTY_SPACE") ==
          std::vector<std::string>{});
}
