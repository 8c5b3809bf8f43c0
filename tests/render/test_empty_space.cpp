// Empty space in the CPU twin's viewing pass (render/empty_bricks.h, view_march.h
// EK_SKIP_EMPTY_SPACE): which bricks are empty, and that stepping through them without sampling
// gives the picture of every step taken in full, to the bit.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "core/scene.h"
#include "render/empty_bricks.h"
#include "render/frame_renderer.h"
#include "render/image.h"
#include "support/light_transport_setup.h"
#include "support/test_paths.h"

using eikon::EmptyBricks;
using eikon::findEmptyBricks;

namespace {

size_t brickIndex(const EmptyBricks& b, int x, int y, int z) {
    return (size_t(z) * size_t(b.count.y) + size_t(y)) * size_t(b.count.x) + size_t(x);
}

// The picture of a fresh CPU renderer, with empty space skipped or every step taken in full.
eikon::Image renderCpu(const eikon::Scene& scene, bool skip) {
    if (skip)
        unsetenv("EIKON_SKIP_EMPTY_SPACE");
    else
        setenv("EIKON_SKIP_EMPTY_SPACE", "0", 1);
    eikon::FrameRenderer renderer(scene, eikon::Backend::Cpu);
    eikon::Image image = renderer.render(0);
    unsetenv("EIKON_SKIP_EMPTY_SPACE");
    return image;
}

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

TEST_CASE("skipping empty space gives the picture of every step taken in full, to the bit",
          "[empty_space][view]") {
    struct Case {
        std::string name;  // what it covers
        std::string file;
        float ior;     // > 0: the first material's, to bend the rays
        int perSide;   // > 0: photons per side
        float fogTop;  // < 1e9: the first source (a box of fog) ends at this height
    };
    const Case cases[] = {
        {"straight rays: a fog sphere in a box, light volumes", "fog_sphere_spot", 0.0f, 0, 1e9f},
        {"curved rays through a graded sphere", "fog_sphere_spot", 1.3f, 0, 1e9f},
        // The ball sits half in a layer of fog, half in empty space; its rays reflect, and the
        // camera's rays end on the floor.
        {"a glass ball's sharp surface, photons, a receiver", "glass_sphere_floor", 0.0f, 24, 0.3f},
        {"a glass mesh's sharp surface, photons, a receiver", "glass_mesh_floor", 0.0f, 24, 0.0f},
        {"dispersion: three rays a pixel, each channel's own gradient", "crystal_dispersion", 0.0f,
         0, 1e9f},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        eikon::Scene scene =
            eikon::loadScene(eikon::test::sourcePath("data/scenes/" + c.file + ".json"));
        scene.render.width = 40;
        scene.render.height = 30;
        if (c.ior > 0.0f) scene.materials[0].ior = c.ior;
        if (c.fogTop < 1e9f) scene.sources[0].boxMax.y = c.fogTop;
        if (c.perSide > 0)
            eikon::test::setTransportSetting(scene, "photons", "per_side", c.perSide);
        const eikon::Image full = renderCpu(scene, false);
        const eikon::Image skipped = renderCpu(scene, true);
        const bool sameBits = full.width == skipped.width && full.height == skipped.height &&
                              full.pixels == skipped.pixels;
        CHECK(sameBits);
    }
}
