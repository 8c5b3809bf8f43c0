// The water surface (sim/water_surface.h): a droplet's ring spreads at the wave speed, volume is
// kept, the mesh is closed and outward, and frame f is the same however it is reached.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "sim/mesh_check.h"
#include "sim/water_surface.h"

using namespace eikon;
using sim::Droplet;
using sim::WaterSettings;
using sim::WaterSurface;

namespace {

// Closed, manifold and wound outward, by the same check mesh files must pass.
bool closedAndOutward(const TriangleMesh& m) {
    try {
        requireClosedRefractiveMesh(checkMesh(m), "water");
        return true;
    } catch (const Error& e) {
        UNSCOPED_INFO(e.what());
        return false;
    }
}

}  // namespace

TEST_CASE("a droplet's ring travels at the wave speed", "[water]") {
    // 4 × 4 pool, 256² cells (dx = 1/64), c = 1, a dent of σ = 2 cells at the centre at t = 0.
    WaterSettings s;
    s.cells = {256, 256};
    s.size = {4.0f, 4.0f};
    s.waveSpeed = 1.0f;
    s.fps = 24.0;
    s.droplets = {Droplet{0.0, {0.0f, 0.0f}, 2.0f / 64.0f, 0.01f}};
    WaterSurface water(s);
    for (int frame : {12, 24, 36}) {
        water.advanceToFrame(frame);
        const double t = water.time();
        // The ring's radius: where the dent has travelled, the lowest point along +x beyond a
        // quarter of the expected radius (dispersion leaves a raised wake behind it).
        int peak = 0;
        float lowest = 0.0f;
        for (int i = 128 + int(0.25 * t * 64.0); i < 256; ++i) {
            const float h = water.height(i, 128) + water.height(i, 127);
            if (h < lowest) lowest = h, peak = i;
        }
        const double radius = (peak + 0.5) / 64.0 - 2.0;
        INFO("t = " << t << " s: ring at " << radius << ", c t = " << t);
        CHECK(std::abs(radius - t) < 2.0 / 64.0);  // within 2 cells
    }
}

TEST_CASE("droplets keep the water's volume, and damping calms the surface", "[water]") {
    WaterSettings s;
    s.cells = {96, 64};
    s.size = {3.0f, 2.0f};
    s.depth = 0.25f;
    s.waveSpeed = 0.8f;
    s.damping = 0.5f;
    for (int d = 0; d < 8; ++d)
        s.droplets.push_back(
            {0.13 * d, {-1.2f + 0.3f * float(d), 0.5f - 0.1f * float(d)}, 0.04f, 0.03f});
    WaterSurface water(s);
    const double area = 3.0 * 2.0;
    water.advanceToFrame(24);
    float early = 0.0f;
    for (int k = 0; k < 64; ++k)
        for (int i = 0; i < 96; ++i) early = std::max(early, std::abs(water.height(i, k)));
    water.advanceToFrame(240);
    float late = 0.0f;
    for (int k = 0; k < 64; ++k)
        for (int i = 0; i < 96; ++i) late = std::max(late, std::abs(water.height(i, k)));
    INFO("volume change " << water.volumeAboveRest() << " over " << area * 0.25);
    CHECK(std::abs(water.volumeAboveRest()) < 1e-8 * area * 0.25);
    // γ = 0.5/s over 9 s: amplitudes fall by about e^(−γt/2) ≈ 0.1.
    INFO("max |h| at 1 s " << early << ", at 10 s " << late);
    CHECK(late < 0.2f * early);
}

TEST_CASE("the body of water is a closed mesh wound outward, with the water's volume", "[water]") {
    WaterSettings s;
    s.cells = {24, 16};
    s.size = {1.5f, 1.0f};
    s.depth = 0.2f;
    s.droplets = {Droplet{0.0, {0.1f, -0.1f}, 0.08f, 0.05f}};
    WaterSurface water(s);
    TriangleMesh rest = water.mesh();
    CHECK(closedAndOutward(rest));
    CHECK(rest.triangles.size() == size_t(4 * 24 * 16 + 4 * (24 + 16)));
    water.advanceToFrame(5);
    const TriangleMesh moved = water.mesh();
    CHECK(closedAndOutward(moved));
    const double restVolume = 1.5 * 1.0 * 0.2;
    CHECK(signedVolume(moved) > 0.0);
    // The surface through cell corners (means of cells) holds the same water up to the smoothing
    // of the corner means: within 1 % of the dent's volume of the rest volume.
    INFO("mesh volume " << signedVolume(moved) << ", rest " << restVolume);
    CHECK(std::abs(signedVolume(moved) - restVolume) < 1e-4 * restVolume);
}

TEST_CASE("frame f is the same however it is reached", "[water]") {
    WaterSettings s;
    s.cells = {40, 40};
    s.droplets = {Droplet{0.2, {0.3f, 0.1f}, 0.06f, 0.02f},
                  Droplet{0.5, {-0.4f, -0.2f}, 0.05f, 0.03f}};
    WaterSurface direct(s), stepped(s);
    direct.advanceToFrame(30);
    for (int f : {7, 19, 30}) stepped.advanceToFrame(f);
    bool same = true;
    for (int k = 0; k < 40; ++k)
        for (int i = 0; i < 40; ++i) same = same && direct.height(i, k) == stepped.height(i, k);
    CHECK(same);
    stepped.advanceToFrame(3);  // back: from rest again
    stepped.advanceToFrame(30);
    for (int k = 0; k < 40; ++k)
        for (int i = 0; i < 40; ++i) same = same && direct.height(i, k) == stepped.height(i, k);
    CHECK(same);
}

TEST_CASE("bad water settings are errors", "[water]") {
    WaterSettings s;
    s.cells = {1, 8};
    CHECK_THROWS_AS(WaterSurface(s), Error);
    s = WaterSettings{};
    s.waveSpeed = 0.0f;
    CHECK_THROWS_AS(WaterSurface(s), Error);
    s = WaterSettings{};
    s.droplets = {Droplet{0.0, {5.0f, 0.0f}, 0.1f, 0.01f}};
    CHECK_THROWS_WITH(WaterSurface(s), Catch::Contains("droplet 0"));
}
