// Issue 15, "energy with n = 2": how much of the light that enters a sharp glass ball reaches the
// floor below it, photon by photon against an exact Snell's-law trace of the same sphere. The
// issue measured 82.8 % against 76.2 % for n = 2 before the sharp sphere's coverage and RK4:
// marginal rays bent too little, so too much light stayed on the floor. CPU twin.
//
// Measured here (256² photons), RK4 (the default) against the exact fraction, n = 1.5 / 2:
//   B-spline edge (a sphere's default): 99.3 % / 77.9 % against 94.0 % / 73.9 %;
//   the voxels' coverage (box edge):    96.6 % / 77.6 %;
//   the paper's Euler step:             100 % / 93.0-93.9 % with either edge.
// What RK4 leaves, 3-5 points too much, is the edge's width: a sampled field cannot hold the
// sharp rim, and grazing rays cross its ramp over a long path, bent less than by Snell's law. The
// B-spline's ramp is four voxels wide (the coverage's one): it gives up 2.8 points at n = 1.5 for
// a caustic without rings (BENCHMARKS.md, "A glass ball's floor caustic").
//
// Set-up: the volume [-1, 1]³ at 63³, its bottom face the floor; a sphere of radius 0.8 (falloff 0)
// whose top touches the top face, its centre 1.5 radii above the floor; parallel light straight
// down. A photon's ray enters the lens where its start lies within the sphere's disk; it reaches
// the floor where it escapes through the bottom face.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/procedural.h"
#include "core/sphere_refraction.h"
#include "render/transport/photons/photon_tracing.h"
#include "support/photon_scene.h"
#include "support/scene_builders.h"

using namespace eikon;

namespace {

constexpr float kRadius = 0.8f;
const glm::dvec3 kCentre(0.0, 0.2, 0.0);

// The exact fraction of the parallel light entering the sphere that reaches the floor square
// y = −1, |x|, |z| ≤ 1: rays on a fine grid over the sphere's disk, refracted in and out.
double exactFloorFraction(double ior) {
    const int n = 600;
    int entered = 0, landed = 0;
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            const double x = kRadius * (2.0 * (a + 0.5) / n - 1.0);
            const double z = kRadius * (2.0 * (b + 0.5) / n - 1.0);
            if (x * x + z * z >= double(kRadius) * kRadius) continue;
            ++entered;
            glm::dvec3 p2, t2;
            if (!refractDownThroughSphere(kCentre, kRadius, ior, x, z, p2, t2)) continue;
            if (!(t2.y < 0.0)) continue;
            const glm::dvec3 floor = p2 + ((-1.0 - p2.y) / t2.y) * t2;
            if (std::abs(floor.x) <= 1.0 && std::abs(floor.z) <= 1.0) ++landed;
        }
    return double(landed) / entered;
}

}  // namespace

// [release_only]: 91 s under the sanitizers (CI at 84-90 of its 90 minutes); photons through a
// sharp ball run there in test_ball_lens's cases, onto floors in test_receivers' and the scene
// hashes'.
TEST_CASE("a sharp glass ball sends as much of its light to the floor as Snell's law does",
          "[photons][lens][release_only]") {
    for (EdgeFilter filter : {EdgeFilter::BSpline, EdgeFilter::Box}) {
        SourceSpec ball =
            test::sphereSource("n", glm::vec3(kCentre), kRadius, 1.0f, 0.0f, 2.0f / 63.0f);
        ball.edgeFilter = filter;
        for (float ior : {1.5f, 2.0f}) {
            const test::PhotonScene s(
                63, ior, glm::vec3(0.0f), glm::vec3(0.0f, -1.0f, 0.0f),
                [&](glm::vec3 p) { return float(proceduralValue(ball, glm::dvec3(p))); });
            PhotonSettings settings;
            settings.photonsPerSide = 256;
            const std::vector<shared::GpuPhoton> starts =
                generatePhotonsCpu(s.setup, s.gradient, settings);
            // The fraction of the flux entering the ball that escapes through the floor.
            auto floorFraction = [&](RayIntegrator integrator) {
                settings.integrator = integrator;
                const PhotonResultCpu r = s.trace(settings);
                double entered = 0.0, landed = 0.0;
                for (size_t i = 0; i < starts.size(); ++i) {
                    const glm::vec3 x0(starts[i].position);
                    if (int(starts[i].position.w) != EK_PHOTON_ACTIVE ||
                        x0.x * x0.x + x0.z * x0.z >= kRadius * kRadius)
                        continue;
                    entered += starts[i].flux.y;
                    const shared::GpuPhoton& end = r.photons[i];
                    if (int(end.position.w) == EK_PHOTON_ESCAPED && end.position.y < -1.0f + 1e-4f)
                        landed += starts[i].flux.y;
                }
                return landed / entered;
            };
            const double exact = exactFloorFraction(ior);
            const double rk4 = floorFraction(RayIntegrator::Rk4);
            const double euler = floorFraction(RayIntegrator::Euler);
            const bool box = filter == EdgeFilter::Box;
            INFO((box ? "box" : "B-spline") << " edge, n " << ior << ": of the light entering the "
                                            << "ball " << 100.0 * rk4 << " % (RK4) and "
                                            << 100.0 * euler << " % (Euler) land on the floor, "
                                            << "exactly " << 100.0 * exact << " %");
            if (box) {
                CHECK(std::abs(rk4 - exact) < 0.045);
                CHECK(std::abs(rk4 - exact) < 0.5 * std::abs(euler - exact));
            } else {
                // The B-spline's wider edge bends grazing rays less: at n = 1.5 it keeps 5.4
                // points too many on the floor (coverage: 2.6).
                CHECK(std::abs(rk4 - exact) < (ior == 1.5f ? 0.06 : 0.045));
                CHECK(std::abs(rk4 - exact) < std::abs(euler - exact));
            }
        }
    }
}
