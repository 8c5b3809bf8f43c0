// Inside bits of a closed mesh at cell centres (core/mesh_voxelize.h), the CPU voxelizer shared by
// the render volume's coverage and the smoke solver's obstacles: a box whose faces lie on cell
// faces marks exactly the cells it holds; an icosphere marks every cell inside its faces' nearest
// approach and none outside its vertices' sphere; the result does not depend on the thread count.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <tbb/task_arena.h>
#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/mesh_primitives.h"
#include "core/mesh_voxelize.h"
#include "shaders/shared/platform.h"

using namespace eikon;

TEST_CASE("a box with faces on cell faces is inside at exactly its cells", "[voxelize][core]") {
    // 16 × 12 × 40 cells of 1/16 (z longer than one 32-bit word); box over cells x 4..11,
    // y 2..9, z 5..36.
    const glm::ivec3 n(16, 12, 40);
    const float h = 1.0f / 16.0f;
    const TriangleMesh box = boxMesh(glm::vec3(4, 2, 5) * h, glm::vec3(12, 10, 37) * h);
    const InsideBits bits = voxelizeInsideCpu(box, glm::vec3(0.0f), glm::vec3(h), n);
    REQUIRE(bits.wordsPerColumn == 2);
    int wrong = 0, inside = 0;
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const bool expected = i >= 4 && i < 12 && j >= 2 && j < 10 && k >= 5 && k < 37;
                wrong += bits.inside(i, j, k) != expected;
                inside += bits.inside(i, j, k);
            }
    CHECK(wrong == 0);
    CHECK(inside == 8 * 8 * 32);
}

TEST_CASE("an icosphere is inside between its inradius and its radius", "[voxelize][core]") {
    const glm::vec3 c(0.53f, 0.47f, 0.5f);
    const float r = 0.3f;
    const TriangleMesh sphere = icosphere(c, r, 2);
    // The polyhedron holds the ball of its faces' least distance from the centre and lies in the
    // ball of its vertices.
    double inradius = r;
    for (const glm::uvec3& t : sphere.triangles) {
        const glm::vec3 a = sphere.positions[t.x], b = sphere.positions[t.y],
                        d = sphere.positions[t.z];
        const glm::vec3 normal = glm::normalize(glm::cross(b - a, d - a));
        inradius = std::min(inradius, double(std::abs(glm::dot(normal, a - c))));
    }
    REQUIRE(inradius > 0.95 * r);
    const glm::ivec3 n(32);
    const float h = 1.0f / 32.0f;
    const InsideBits bits = voxelizeInsideCpu(sphere, glm::vec3(0.0f), glm::vec3(h), n);
    int missed = 0, extra = 0, inside = 0;
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const double dist = glm::distance((glm::vec3(i, j, k) + 0.5f) * h, c);
                const bool in = bits.inside(i, j, k);
                inside += in;
                if (dist < inradius - 1e-5) missed += !in;
                if (dist > r + 1e-5) extra += in;
            }
    CHECK(missed == 0);
    CHECK(extra == 0);
    // And the count is the polyhedron's volume in cells, to the sampling error of a 9.6-cell
    // radius (the surface holds ~1200 cells; ±3 % of the ~3700 inside is well over that noise).
    const double cells = std::abs(signedVolume(sphere)) / (double(h) * h * h);
    CHECK(inside == Approx(cells).epsilon(0.03));
}

TEST_CASE("inside bits do not depend on the thread count", "[voxelize][core][determinism]") {
    const TriangleMesh sphere = icosphere(glm::vec3(0.51f, 0.49f, 0.5f), 0.35f, 3);
    auto run = [&](int threads) {
        tbb::task_arena arena(threads);
        InsideBits bits;
        arena.execute([&] {
            bits = voxelizeInsideCpu(sphere, glm::vec3(0.0f), glm::vec3(1.0f / 24), glm::ivec3(24));
        });
        return bits.words;
    };
    CHECK(run(1) == run(2));
}

TEST_CASE("a mesh with a bad index or position is refused by name", "[voxelize][core]") {
    TriangleMesh m = boxMesh(glm::vec3(0.0f), glm::vec3(1.0f));
    m.triangles[3].y = 99;
    CHECK_THROWS_WITH(checkMeshForVoxelization(m, "glass.obj"),
                      Catch::Contains("glass.obj") && Catch::Contains("uses vertex 99"));
    m = boxMesh(glm::vec3(0.0f), glm::vec3(1.0f));
    m.positions[2].x = std::nanf("");
    CHECK_THROWS_WITH(checkMeshForVoxelization(m, "glass.obj"),
                      Catch::Contains("vertex 2 is not finite"));
}

// The shared kernel with a toggle hook that records every flip outside the fine grid instead of
// writing it, so a test sees an out-of-range index whether or not the write would crash.
EK_NAMESPACE_BEGIN
struct CheckedVoxelizeKernel {
    glm::ivec3 fineRes;
    mutable int outOfRange = 0;
    mutable int toggles = 0;

    void toggleSample(int column, int k) const {
        ++toggles;
        if (column < 0 || column >= fineRes.x * fineRes.y || k < 0 || k >= fineRes.z) ++outOfRange;
    }
    uint fetchInsideWord(int) const { return 0u; }

#include "shaders/shared/voxelize.h"
};
EK_NAMESPACE_END

TEST_CASE("a mesh far outside the grid in voxel units toggles nothing out of range",
          "[voxelize][core]") {
    // Issue 14: an icosphere of radius 1e30 rendered in a volume 1e-30 wide (fine coordinates
    // overflow to infinities), and the same sphere in a 2-unit volume (finite coordinates whose
    // edge functions overflow to NaN): int() of a NaN indexed far outside the bits.
    const TriangleMesh huge = icosphere(glm::vec3(0.0f), 1e30f, 1);
    struct Case {
        glm::vec3 gridMin;
        glm::vec3 cell;
    };
    for (const Case& c : {Case{glm::vec3(0.0f), glm::vec3(1e-30f / 64.0f)},
                          Case{glm::vec3(-1.0f), glm::vec3(2.0f / 64.0f)}}) {
        shared::CheckedVoxelizeKernel kernel{glm::ivec3(64)};
        for (const glm::uvec3& t : huge.triangles)
            kernel.voxelizeTriangle(huge.positions[t.x], huge.positions[t.y], huge.positions[t.z],
                                    c.gridMin, c.cell, kernel.fineRes);
        CHECK(kernel.outOfRange == 0);
        // The CPU voxelizer runs the same code; the scene-level check refuses such a mesh.
        CHECK_NOTHROW(voxelizeInsideCpu(huge, c.gridMin, c.cell, glm::ivec3(64)));
        try {
            checkMeshFitsVoxelGrid(huge, "scene.json:/meshes/0", c.gridMin, c.cell, glm::ivec3(64));
            FAIL("no error for a mesh 1e30 across");
        } catch (const Error& e) {
            CHECK(e.where() == "scene.json:/meshes/0");
            CHECK(std::string(e.reason()).find("voxels (of ") != std::string::npos);
            CHECK(std::string(e.reason()).find("the voxelizer resolves at most 1.67772e+07") !=
                  std::string::npos);
        }
    }
    // A mesh inside its grid passes the check.
    CHECK_NOTHROW(checkMeshFitsVoxelGrid(icosphere(glm::vec3(0.5f), 0.3f, 1), "m", glm::vec3(0.0f),
                                         glm::vec3(1.0f / 64.0f), glm::ivec3(64)));
}
