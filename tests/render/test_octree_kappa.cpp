// The octree extension of issue 3: extinction limiting the photon step (shaders/shared/octree.h,
// OctreeSettings::kappaTolerance). Where n is flat the paper's octree lets a photon cross the
// whole volume in one step, taking κ at that step's midpoint for all of it; through a thin
// absorber that is wrong by orders of magnitude. With a tolerance, nodes whose κ varies are
// refined, and the transmission matches the closed form. CPU twin; the GPU runs the same labels
// (test_refraction.cpp compares the octree volumes).
#include <catch2/catch.hpp>

#include <cmath>

#include "support/photon_scene.h"
#include "support/scene_builders.h"

using eikon::OctreeSettings;
using eikon::PhotonResultCpu;
using eikon::PhotonSettings;
using eikon::test::PhotonScene;
using eikon::test::relativeError;

namespace {

constexpr int kRes = 32;
constexpr double kVoxel = 2.0 / kRes;
constexpr float kKappa = 8.0f;  // per scene unit, inside the slab

// A slab four voxels thick, y in [0, 0.25): the field is 1 at the centres inside, 0 outside.
float slab(glm::vec3 x) {
    return x.y > 0.0f && x.y < 0.25f ? 1.0f : 0.0f;
}

// The share of the emitted flux that leaves the box, per the photons' bookkeeping.
double transmitted(const PhotonResultCpu& r) {
    return r.totals.escaped.g / r.totals.emitted.g;
}

}  // namespace

TEST_CASE("octree: extinction limits photon steps through a thin absorber in flat n",
          "[photons][octree]") {
    // Light straight down through the slab, n ≡ 1 (ior 1). Along a vertical line the field,
    // trilinear between centres, ramps over one voxel at each face, so the optical depth is
    // κ × 4 voxels exactly: T = e^(−κ · 4h) = e^−2.
    const double expected = std::exp(-double(kKappa) * 4.0 * kVoxel);
    PhotonSettings settings;
    settings.photonsPerSide = 32;
    OctreeSettings paper;  // κ does not limit steps
    OctreeSettings limited;
    limited.kappaTolerance = 0.1f;
    const glm::vec3 down(0.0f, -1.0f, 0.0f);
    const PhotonResultCpu a =
        PhotonScene(kRes, 1.0f, glm::vec3(kKappa), down, slab, glm::vec3(1.0f), paper)
            .trace(settings);
    const PhotonResultCpu b =
        PhotonScene(kRes, 1.0f, glm::vec3(kKappa), down, slab, glm::vec3(1.0f), limited)
            .trace(settings);
    INFO("closed form " << expected << "; paper's octree: transmitted " << transmitted(a) << " in "
                        << a.steps << " steps; with kappa_tolerance 0.1: " << transmitted(b)
                        << " in " << b.steps << " steps");
    REQUIRE(a.photonsTraced == b.photonsTraced);
    // Without the extension every photon crosses the box in one step and takes κ/2 (the slab's
    // face, y = 0, is the midpoint) over all 2 units: e^−8 = 3.4e-4 (measured: exactly that).
    CHECK(relativeError(transmitted(a), expected) > 0.5);
    // With it, voxel-aligned one-voxel steps at their midpoints integrate the piecewise-linear
    // κ exactly: measured equal to e^−2 in all six printed digits.
    CHECK(relativeError(transmitted(b), expected) < 1e-4);
    // The price: more steps, but only around the slab (measured 13 per photon against 1).
    CHECK(b.steps > a.steps);
    CHECK(b.steps < 16 * int64_t(b.photonsTraced));
}
