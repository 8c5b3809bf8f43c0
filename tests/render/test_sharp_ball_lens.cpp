// Issue 15, item 1: the simplest glass ball a user writes, a procedural sphere with the default
// falloff 0, focuses. Its field is its step averaged along the normal by the cubic B-spline
// (core/procedural.h, edgeWeight; the voxels' coverage, the earlier filter, focused too). Sampled
// as a step at the voxel centres it terraced the surface, the caps were flat with ∇n straight down,
// and the beam's narrowest cross-section was 2.5-4.6 voxels RMS (measured with the step for these
// cases): no focus. CPU twin (the GPU's photons equal it bit for bit: test_photons_gpu.cpp).
//
// The measure, the issue's: the RMS radius of the fluence in each horizontal slice below the
// ball, about the slice's centroid. A focus is where it is least.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "core/procedural.h"
#include "support/photon_scene.h"
#include "support/scene_builders.h"

using eikon::PhotonResultCpu;
using eikon::PhotonSettings;
using eikon::test::PhotonScene;

namespace {

constexpr int kRes = 63;  // issue 3's test budget, 64³ at most
constexpr double kVoxel = 2.0 / kRes;
constexpr float kRadius = 0.6f;

struct Focus {
    double narrowestRms = 0.0;  // voxels
    double position = 0.0;      // distance below the centre of the run of narrowest slices
};

// Slices from the one that holds the ball's lowest point down to the box: the least RMS radius, and
// the middle of the run of slices within 0.3 voxel of it (a focus is several slices long).
Focus focusBelow(const PhotonResultCpu& t, glm::vec3 centre) {
    const int top = int(std::floor((double(centre.y) - kRadius + 1.0) / kVoxel));
    std::vector<double> rms(size_t(top) + 1, 1e30);
    for (int j = 1; j <= top; ++j) {
        double w = 0.0, wx = 0.0, wz = 0.0, w2 = 0.0;
        for (int k = 0; k < kRes; ++k)
            for (int i = 0; i < kRes; ++i) {
                const double g = t.radiance[(size_t(k) * kRes + size_t(j)) * kRes + size_t(i)].g;
                w += g;
                wx += g * i;
                wz += g * k;
                w2 += g * (double(i) * i + double(k) * k);
            }
        if (w > 0.0)
            rms[j] = std::sqrt(std::max(0.0, w2 / w - (wx / w) * (wx / w) - (wz / w) * (wz / w)));
    }
    int best = 1;
    for (int j = 1; j <= top; ++j)
        if (rms[j] < rms[best]) best = j;
    int lo = best, hi = best;
    while (lo > 1 && rms[lo - 1] <= rms[best] + 0.3) --lo;
    while (hi < top && rms[hi + 1] <= rms[best] + 0.3) ++hi;
    const double y = -1.0 + (0.5 * (lo + hi) + 0.5) * kVoxel;
    return {rms[best], double(centre.y) - y};
}

}  // namespace

TEST_CASE("a sharp glass ball (falloff 0) focuses a paraxial beam at nR / (2(n - 1))",
          "[photons][lens]") {
    // A beam of radius 0.3 R from a spot light 40 units above; the image of a source at D lies at
    // 1 / (1/f − 1/D) from the centre. Centres on and off the voxel grid.
    const float distance = 40.0f;
    const float coneDeg = glm::degrees(std::atan(0.3f * kRadius / distance));
    for (float ior : {1.5f, 2.0f})
        for (glm::vec3 offset : {glm::vec3(0.0f), glm::vec3(0.3f, 0.4f, 0.45f)}) {
            const glm::vec3 centre = glm::vec3(0.0f, 0.3f, 0.0f) + offset * float(kVoxel);
            const auto ball =
                eikon::test::sphereSource("n", centre, kRadius, 1.0f, 0.0f, float(kVoxel));
            const auto light = PhotonScene::spotLight(centre + glm::vec3(0.0f, distance, 0.0f),
                                                      glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(1.0f),
                                                      coneDeg, 0.05f * coneDeg);
            const PhotonScene scene(kRes, ior, glm::vec3(0.0f), light, [&](glm::vec3 p) {
                return float(eikon::proceduralValue(ball, glm::dvec3(p)));
            });
            PhotonSettings settings;
            settings.photonsPerSide = 96;
            const Focus focus = focusBelow(scene.trace(settings), centre);
            const double f = double(ior) * kRadius / (2.0 * (double(ior) - 1.0));
            const double expected = 1.0 / (1.0 / f - 1.0 / double(distance));
            const double error = (focus.position - expected) / kVoxel;
            INFO("n " << ior << ", centre offset " << offset.x << " " << offset.y << " " << offset.z
                      << " voxel: narrowest " << focus.narrowestRms << " voxels RMS, focus "
                      << focus.position << " below the centre, expected " << expected << ": "
                      << error << " voxels");
            // Measured with RK4 (the photons' default) and the B-spline edge: narrowest 0 and
            // 0.26 voxel RMS for n = 1.5, 0 and 0.30 for n = 2 (the step: 2.5-4.6); focus −0.55
            // and −0.15 voxel from the formula for n = 1.5, +0.26 and +0.16 for n = 2, whose
            // focus lies on the ball's back surface (0.2 voxel beyond it). (The voxels' coverage
            // with RK4: narrowest 0-0.38, focus −0.55, −0.65, +0.26, +0.66; with Euler: 0-0.51,
            // −0.55, +0.35, +0.26, +1.16.)
            CHECK(focus.narrowestRms < 0.75);
            CHECK(std::abs(error) < 1.0);
        }
}
