// The liquid in a container (sim/container_fill.h): cups whose cavities have closed-form volumes,
// the shared wine glass, and containers with nothing to fill.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "core/error.h"
#include "core/mesh_primitives.h"
#include "sim/container_fill.h"
#include "sim/mesh_check.h"
#include "sim/refractive_mesh.h"
#include "support/test_paths.h"

using namespace eikon;

namespace {

constexpr double kPi = 3.14159265358979323846;
// Float vertices of size ~1: volumes to this relative error where the polyhedra are the same.
constexpr double kExactVolume = 2e-6;
// The cavity's ends are found by bisection on float data.
constexpr double kHeightTolerance = 1e-6;

// Area of the regular S-gon inscribed in a circle of radius r: what a ring of S vertices bounds.
double polygonArea(double r, int sides) {
    return 0.5 * sides * r * r * std::sin(2.0 * kPi / sides);
}

void requireClosedOutward(const TriangleMesh& mesh) {
    const MeshReport report = checkMesh(mesh);
    std::string problems;
    for (const std::string& problem : meshProblems(report)) problems += problem + "; ";
    INFO(problems);
    CHECK(meshProblems(report).empty());
    CHECK(signedVolume(mesh) > 0.0);
}

}  // namespace

TEST_CASE("a straight cup fills to a prism of its inner polygon", "[container_fill]") {
    // Outer radius 0.5, inner 0.4, floor 0.1 thick, 1 tall; the liquid's rays meet the inner
    // wall at its vertices, so the liquid is the cavity's own prism.
    const int sides = 64;
    const TriangleMesh cup = revolvedProfile(
        {{0.0f, 0.0f}, {0.5f, 0.0f}, {0.5f, 1.0f}, {0.4f, 1.0f}, {0.4f, 0.1f}, {0.0f, 0.1f}},
        sides);
    LiquidFillOptions options;
    options.sectors = sides;
    const LiquidFill liquid = fillContainer(cup, 0.5, "cup", options);
    CHECK(std::abs(liquid.bottom - 0.1) < kHeightTolerance);
    CHECK(std::abs(liquid.rim - 1.0) < kHeightTolerance);
    CHECK(std::abs(liquid.level - 0.55) < kHeightTolerance);
    requireClosedOutward(liquid.mesh);
    const double expected = polygonArea(0.4, sides) * (0.55 - 0.1);
    CHECK(std::abs(signedVolume(liquid.mesh) / expected - 1.0) < kExactVolume);
}

TEST_CASE(
    "a conical glass fills to a frustum, and the cup's own translation moves nothing "
    "but the axis",
    "[container_fill]") {
    // Inner wall from r 0.2 at y 0.1 to r 0.5 at y 1: radius linear in height, so the rings'
    // straight sides lie on the wall and the volume is the frustum's of the polygons.
    const int sides = 48;
    TriangleMesh glass = revolvedProfile(
        {{0.0f, 0.0f}, {0.3f, 0.0f}, {0.6f, 1.0f}, {0.5f, 1.0f}, {0.2f, 0.1f}, {0.0f, 0.1f}},
        sides);
    LiquidFillOptions options;
    options.sectors = sides;
    const double fill = 0.7;
    const LiquidFill liquid = fillContainer(glass, fill, "glass", options);
    const double h = fill * 0.9;
    const double a1 = polygonArea(0.2, sides), a2 = polygonArea(0.2 + 0.3 * fill, sides);
    const double frustum = h / 3.0 * (a1 + a2 + std::sqrt(a1 * a2));
    requireClosedOutward(liquid.mesh);
    CHECK(std::abs(signedVolume(liquid.mesh) / frustum - 1.0) < kExactVolume);

    // Off the origin: the axis is the bounds' centre, so the same liquid, moved.
    for (glm::vec3& p : glass.positions) p += glm::vec3(2.0f, -1.0f, 3.0f);
    const LiquidFill moved = fillContainer(glass, fill, "glass", options);
    CHECK(moved.axis.x == Approx(2.0).margin(1e-6));
    CHECK(moved.axis.y == Approx(3.0).margin(1e-6));
    CHECK(std::abs(moved.level - (liquid.level - 1.0f)) < 1e-5);
    CHECK(std::abs(signedVolume(moved.mesh) / frustum - 1.0) < 1e-5);
}

TEST_CASE("a round-bottomed bowl fills to its spherical cap", "[container_fill]") {
    // Cavity: the lower half of a sphere of radius 0.5 centred at y = 0.6, inside a wall 0.1
    // thick; filled to depth d the liquid is the cap π d² (3R − d) / 3. The rings sample the
    // curved floor, so the polyhedron falls short by the chords' cut: 1 % at the defaults.
    std::vector<glm::vec2> profile = {{0.0f, 0.0f}};
    const int arc = 64;
    for (int i = 0; i <= arc; ++i) {  // outer: radius 0.6 from the bottom pole to the equator
        const double phi = 0.5 * kPi * i / arc;
        if (i > 0)
            profile.emplace_back(0.6f * float(std::sin(phi)), 0.6f - 0.6f * float(std::cos(phi)));
    }
    for (int i = arc; i >= 1; --i) {  // inner: radius 0.5 back down to the floor
        const double phi = 0.5 * kPi * i / arc;
        profile.emplace_back(0.5f * float(std::sin(phi)), 0.6f - 0.5f * float(std::cos(phi)));
    }
    profile.emplace_back(0.0f, 0.1f);
    const TriangleMesh bowl = revolvedProfile(profile, 128);
    const LiquidFill liquid = fillContainer(bowl, 0.6, "bowl");
    CHECK(std::abs(liquid.bottom - 0.1) < 1e-4);
    CHECK(std::abs(liquid.rim - 0.6) < 1e-4);
    const double d = 0.6 * 0.5, r = 0.5;
    const double cap = kPi * d * d * (3.0 * r - d) / 3.0;
    requireClosedOutward(liquid.mesh);
    const double volume = signedVolume(liquid.mesh);
    CHECK(volume < cap);
    CHECK(volume / cap > 0.99);
}

TEST_CASE("the shared wine glass holds a closed liquid below its rim", "[container_fill]") {
    // SOURCES.md: bowl widest at r 0.498 (y ≈ 1.9), rim r ≈ 0.37 at y ≈ 2.46, stem to y 1.0.
    const RefractiveMesh glass = loadRefractiveMesh(test::sharedData("meshes/wine_glass.obj"), {});
    const LiquidFill wine = fillContainer(glass.mesh, 0.5, "wine");
    CHECK(wine.bottom > 1.0f);
    CHECK(wine.bottom < wine.level);
    CHECK(wine.rim > 2.3f);
    CHECK(wine.rim < 2.464f);
    requireClosedOutward(wine.mesh);
    // Inside the glass's outer bounds, below the rim.
    const Bounds3 b = boundsOf(wine.mesh);
    CHECK(b.max.x < 0.498f);
    CHECK(b.min.x > -0.498f);
    CHECK(b.max.y <= wine.level + 1e-6f);
    // Less than the cylinder of the widest radius over the liquid's height.
    CHECK(signedVolume(wine.mesh) < kPi * 0.498 * 0.498 * (wine.level - wine.bottom));
}

TEST_CASE("containers with nothing to fill, and fills out of range, are errors",
          "[container_fill]") {
    const TriangleMesh ball = icosphere(glm::vec3(0.0f), 0.5f, 2);
    CHECK_THROWS_WITH(fillContainer(ball, 0.5, "/meshes/1"),
                      Catch::Contains("/meshes/1") && Catch::Contains("no cavity"));
    const TriangleMesh cup = revolvedProfile(
        {{0.0f, 0.0f}, {0.5f, 0.0f}, {0.5f, 1.0f}, {0.4f, 1.0f}, {0.4f, 0.1f}, {0.0f, 0.1f}}, 32);
    CHECK_THROWS_WITH(fillContainer(cup, 0.0, "w"), Catch::Contains("(0, 1]"));
    CHECK_THROWS_WITH(fillContainer(cup, 1.5, "w"), Catch::Contains("(0, 1]"));
    CHECK_THROWS_WITH(fillContainer(cup, std::nan(""), "w"), Catch::Contains("(0, 1]"));
    CHECK_THROWS_WITH(fillContainer(TriangleMesh{}, 0.5, "w"), Catch::Contains("no triangles"));
}

TEST_CASE("a revolved profile is closed and wound outward either way it runs", "[container_fill]") {
    std::vector<glm::vec2> profile = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 2.0f}, {0.0f, 2.0f}};
    const TriangleMesh up = revolvedProfile(profile, 16);
    requireClosedOutward(up);
    CHECK(signedVolume(up) == Approx(polygonArea(1.0, 16) * 2.0).epsilon(1e-6));
    std::vector<glm::vec2> reversed(profile.rbegin(), profile.rend());
    CHECK(signedVolume(revolvedProfile(reversed, 16)) == Approx(signedVolume(up)).epsilon(1e-6));
    CHECK_THROWS_WITH(revolvedProfile({{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}}, 8),
                      Catch::Contains("on the axis"));
    CHECK_THROWS_WITH(revolvedProfile({{0.0f, 0.0f}, {-1.0f, 0.0f}, {0.0f, 1.0f}}, 8),
                      Catch::Contains("point 1"));
}
