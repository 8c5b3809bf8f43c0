// Optics of the procedural index profiles against closed forms: a Luneburg lens (n = sqrt(2 −
// (r/R)²)) brings parallel light to a focus on its far surface, for view rays and photons alike;
// a layered medium whose n grows linearly with height bends view rays into catenaries, turning
// rays that head down back up (a mirage). Then the shipped scenes that use them render, and a
// field that would make n < 1 stops a render with an error naming it. CPU twin.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "core/procedural.h"
#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/smoothing.h"
#include "render/transport/wavefront/wavefront_tracing.h"
#include "render/volume_kernels_cpu.h"
#include "support/backends.h"
#include "support/fluence_peak.h"
#include "support/light_transport_setup.h"
#include "support/linear_n2_medium.h"
#include "support/photon_scene.h"
#include "support/scene_builders.h"
#include "support/test_paths.h"

using namespace eikon;
using eikon::test::PhotonScene;

namespace {

// At most 64³ (issue 3's test budget), odd so that the axis x = z = 0 runs through a column of
// voxel centres.
constexpr int kRes = 63;
constexpr double kVoxel = 2.0 / kRes;

// A Luneburg lens as the scene parser makes it: value 1, read with ior 2.
SourceSpec luneburgLens(glm::vec3 centre, float radius) {
    SourceSpec s = test::sphereSource("n", centre, radius, 1.0f, 0.0f, float(kVoxel));
    s.profile = SourceProfile::Luneburg;
    return s;
}

// The scene's field sampled where the procedural grid stores it, at the render volume's voxel
// centres (what resampling a grid aligned with the volume gives).
std::function<float(glm::vec3)> fieldOf(const SourceSpec& src) {
    return [src](glm::vec3 p) { return float(proceduralValue(src, glm::dvec3(p))); };
}

// Where a view ray entering at `entry` along unit `dir` leaves PhotonScene's box, and the
// direction it leaves with, traced by the shared view-march code at the scene's step.
glm::vec3 traceViewRay(const PhotonScene& s, glm::vec3 entry, glm::vec3 dir, glm::vec3& exitDir) {
    shared::ViewKernelCpu k{{s.setup.params}};
    k.fields[0] = s.field.values.data();
    k.gradient = s.gradient.data();
    glm::vec3 radiance(0.0f), transmittance(1.0f);
    return k.traceCurvedRay(entry, dir, false, radiance, transmittance, exitDir);
}

// The scene's view rays at `stepVoxels` with `integrator` (the ∇n volume depends on neither).
void setViewStep(PhotonScene& s, float stepVoxels,
                 RayIntegrator integrator = RayIntegrator::Euler) {
    s.scene.render.stepVoxels = stepVoxels;
    s.scene.render.integrator = integrator;
    s.setup = makeViewSetup(s.scene, s.field.volume,
                            makeCameraFrame(s.scene.camera, s.field.volume.bounds, 4, 4));
}

// The position along the axis x = z = 0 of the brightest smoothed fluence below height `top`
// (scene units), refined to a fraction of a voxel.
double brightestOnAxisBelow(const std::vector<glm::vec4>& radiance, glm::ivec3 resolution,
                            double top) {
    const std::vector<glm::vec4> smoothed = smoothVolumeCpu(radiance, resolution);
    const int axis = kRes / 2;
    auto at = [&](int j) {
        return double(smoothed[(size_t(axis) * kRes + size_t(j)) * kRes + size_t(axis)].g);
    };
    bool interior = false;
    const double peak =
        test::refinedPeak(at, 1, int(std::floor((top + 1.0) / kVoxel)) - 1, interior);
    REQUIRE(interior);
    return -1.0 + (peak + 0.5) * kVoxel;
}

double brightestOnAxisBelow(const PhotonResultCpu& traced, double top) {
    return brightestOnAxisBelow(traced.radiance, traced.resolution, top);
}

// n = n0 + g (y − y0) on [-1, 1]^3: a ramp along y from `from` at y = -1 to `to` at y = 1, read
// with ior 2 (n = 1 + f).
struct LinearLayers {
    float from, to;
    double n(double y) const { return 1.0 + from + (to - from) * (y + 1.0) / 2.0; }
    double slope() const { return (double(to) - from) / 2.0; }
};

// The closed form of a ray in a medium whose n depends linearly on y (slope g > 0): the
// horizontal part of n·t is conserved, C = n cos φ, and along the horizontal distance u
//   n(u) = C cosh(a + g u / C),   a = asinh(tan φ0),
// a catenary; tan φ = sinh(a + g u / C). Returns where it leaves [-1, 1]^3 (marched in u, then
// bisected) and, in exitDir, its direction there.
glm::dvec3 catenaryExit(const LinearLayers& m, glm::dvec3 x0, glm::dvec3 dir, glm::dvec3& exitDir) {
    const double g = m.slope();
    const glm::dvec3 horizontal = glm::normalize(glm::dvec3(dir.x, 0.0, dir.z));
    const double cosPhi = std::sqrt(dir.x * dir.x + dir.z * dir.z);
    const double c = m.n(x0.y) * cosPhi;
    const double a = std::asinh(dir.y / cosPhi);
    const double yStar = x0.y - m.n(x0.y) / g;  // where n would reach 0
    auto at = [&](double u) {
        glm::dvec3 x = x0 + horizontal * u;
        x.y = yStar + (c / g) * std::cosh(a + g * u / c);
        return x;
    };
    const double lo = test::boxExitParameter(at);
    exitDir = glm::normalize(horizontal + glm::dvec3(0.0, std::sinh(a + g * lo / c), 0.0));
    return at(lo);
}

}  // namespace

TEST_CASE("Luneburg lens: every parallel view ray leaves through the far pole",
          "[profiles][lens]") {
    // The lens touches the bottom face at its far pole, so a ray's exit point is where it
    // crosses the pole's plane; the distance from there to the pole is its miss.
    const float radius = 0.6f;
    const glm::vec3 centre(0.0f, -1.0f + radius, 0.0f);
    const glm::dvec3 pole(0.0, -1.0, 0.0);
    PhotonScene s(kRes, 2.0f, glm::vec3(0.0f), glm::vec3(0.0f, -1.0f, 0.0f),
                  fieldOf(luneburgLens(centre, radius)));
    // The worst miss, in voxels, of rays at heights from the axis out to `reach` R, in two planes
    // through the axis.
    auto worstMiss = [&](double reach) {
        double worst = 0.0;
        for (int i = 0; i <= 18; ++i) {
            const double h = 0.05 * i * radius;
            if (h > reach * radius + 1e-9) break;
            for (glm::dvec3 side : {glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.6, 0.0, -0.8)}) {
                const glm::vec3 entry = glm::vec3(side * h) + glm::vec3(0.0f, 1.0f, 0.0f);
                glm::vec3 exitDir;
                const glm::vec3 exit =
                    traceViewRay(s, entry, glm::vec3(0.0f, -1.0f, 0.0f), exitDir);
                REQUIRE(exit.y == Approx(-1.0f).margin(1e-5));
                worst = std::max(worst, glm::length(glm::dvec3(exit) - pole) / kVoxel);
            }
        }
        return worst;
    };
    // Measured at 63³ with the paper's Euler step (misses grow with the height, all on the entry
    // side of the axis: the march bends too little, so the focus lies a little beyond the pole):
    //   step 1 voxel:    0.50 (h <= 0.6 R), 1.49 (h <= 0.9 R)
    //   step 0.5 voxel:  0.26,              0.81
    //   step 0.25 voxel: 0.14,              0.45
    // first order in the step. Measured in voxels the misses do not depend on the resolution (at
    // h = 0.9 R, step 0.25: 0.50, 0.42, 0.41 voxel at 31³, 63³, 127³): the error lives at the
    // voxel scale, where the rim's kink in n (at r = R) is smoothed.
    double previous = 1e9;
    for (float step : {1.0f, 0.5f, 0.25f}) {
        setViewStep(s, step, RayIntegrator::Euler);
        const double paraxial = worstMiss(0.6), marginal = worstMiss(0.9);
        INFO("Euler, step " << step << " voxels: worst miss " << paraxial
                            << " voxels (h <= 0.6 R), " << marginal << " (h <= 0.9 R)");
        CHECK(marginal < previous);
        previous = marginal;
        if (step == 1.0f) {
            CHECK(paraxial < 0.6);
            CHECK(marginal < 2.0);
        }
        if (step == 0.25f) {
            CHECK(paraxial < 0.2);
            CHECK(marginal < 0.6);
        }
    }
    // The second-order integrators at the default 1-voxel step: measured 0.045 (h <= 0.6 R) and
    // 0.088 (h <= 0.9 R) for Verlet (the default) and RK4, 0.046 and 0.100 for midpoint: 11× and
    // 17× better than Euler at the same step, 3× and 5× better than Euler at a quarter of it. The
    // floor is the sampled ∇n's error at the rim, not the march's.
    for (RayIntegrator integrator :
         {RayIntegrator::Verlet, RayIntegrator::Rk4, RayIntegrator::Midpoint}) {
        setViewStep(s, 1.0f, integrator);
        const double paraxial = worstMiss(0.6), marginal = worstMiss(0.9);
        INFO(rayIntegratorName(integrator)
             << ": worst miss " << paraxial << " voxels (h <= 0.6 R), " << marginal
             << " (h <= 0.9 R)");
        CHECK(paraxial < 0.07);
        CHECK(marginal < 0.13);
    }
}

// [release_only]: 42 s under the sanitizers; photons through a graded index run there in
// test_photons' linear n² parabola and test_ball_lens's cases.
TEST_CASE("Luneburg lens: photons focus on the far surface, full beam and paraxial",
          "[profiles][lens][photons][release_only]") {
    const float radius = 0.6f;
    const glm::vec3 centre(0.0f, 0.25f, 0.0f);
    const auto field = fieldOf(luneburgLens(centre, radius));
    PhotonSettings settings;
    settings.photonsPerSide = 128;

    SECTION("full parallel beam: no spherical aberration, the focus is the pole") {
        const PhotonScene s(kRes, 2.0f, glm::vec3(0.0f), glm::vec3(0.0f, -1.0f, 0.0f), field);
        const double y = brightestOnAxisBelow(s.trace(settings), centre.y);
        const double expected = centre.y - radius;
        INFO("brightest at y = " << y << ", the pole at " << expected << ": "
                                 << (y - expected) / kVoxel << " voxels");
        // Measured 0.04 voxel from the pole at the default settings (RK4; the paper's Euler step:
        // 0.82 beyond it). Issue 3's bound for the ball lens: 1.5 voxels, for the smoothing's
        // width and the march's error.
        CHECK(std::abs(y - expected) < 1.5 * kVoxel);
    }
    SECTION("full parallel beam: the focus converges on the pole as the step shrinks") {
        // With ε = ε' = 0 every photon step is the minimum step. Measured with the paper's Euler
        // step: 0.82, 0.43, 0.20 voxel beyond the pole at steps 1, 0.5, 0.25 voxel: first order.
        settings.integrator = RayIntegrator::Euler;
        double previous = 1e9;
        for (float step : {1.0f, 0.5f, 0.25f}) {
            OctreeSettings fixed;
            fixed.epsilon = fixed.epsilonPrime = 0.0f;
            fixed.minStepVoxels = step;
            const PhotonScene s(kRes, 2.0f, glm::vec3(0.0f), glm::vec3(0.0f, -1.0f, 0.0f), field,
                                glm::vec3(1.0f), fixed);
            settings.minStepVoxels = step;
            const double error =
                std::abs(brightestOnAxisBelow(s.trace(settings), centre.y) - (centre.y - radius)) /
                kVoxel;
            INFO("step " << step << " voxels: brightest " << error << " voxels from the pole");
            CHECK(error < 0.6 * previous);
            previous = error;
        }
        CHECK(previous < 0.35);
    }
    SECTION("narrow paraxial beam from a distant spot: thin-lens imaging with f = R") {
        // A spot light at distance D on the axis with a cone of radius R/5 at the lens. Both
        // principal planes of a sphere lie at its centre, and parallel light focuses at the
        // surface, so f = R and the image lies 1 / (1/R − 1/D) beyond the centre.
        const float distance = 40.0f;
        const float coneDeg = glm::degrees(std::atan(radius / 5.0f / distance));
        const PhotonScene s(kRes, 2.0f, glm::vec3(0.0f),
                            PhotonScene::spotLight(centre + glm::vec3(0.0f, distance, 0.0f),
                                                   glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(1.0f),
                                                   coneDeg, 0.05f * coneDeg),
                            field);
        settings.photonsPerSide = 96;
        const PhotonResultCpu traced = s.trace(settings);
        REQUIRE(traced.photonsTraced > 1000);
        const double y = brightestOnAxisBelow(traced, centre.y);
        const double expected = centre.y - 1.0 / (1.0 / radius - 1.0 / distance);
        INFO("brightest at y = " << y << ", expected " << expected << ": "
                                 << (y - expected) / kVoxel << " voxels");
        // Measured 0.22 voxel from the image (RK4; Euler: 1.20 beyond it); issue 3's bound for
        // the ball lens, 1.5 voxels.
        CHECK(std::abs(y - expected) < 1.5 * kVoxel);
    }
}

TEST_CASE("Luneburg lens: a parallel wavefront collapses on the far surface",
          "[profiles][lens][wavefront]") {
    const float radius = 0.6f;
    const glm::vec3 centre(0.0f, 0.25f, 0.0f);
    PhotonScene s(kRes, 2.0f, glm::vec3(0.0f), glm::vec3(0.0f, -1.0f, 0.0f),
                  fieldOf(luneburgLens(centre, radius)));
    s.markGraded();  // a graded index: no surface to reflect at
    WavefrontSettings settings;
    settings.maxLevel = 3;  // the light spreads past the pole: splitting there costs, not helps
    const WavefrontResultCpu traced = traceWavefrontsCpu(s.setup, {&s.field}, s.gradient, settings);
    CHECK(traced.causticCrossings > 0);
    const double y = brightestOnAxisBelow(traced.radiance, traced.resolution, centre.y);
    const double expected = centre.y - radius;
    INFO("brightest at y = " << y << ", the pole at " << expected << ": " << (y - expected) / kVoxel
                             << " voxels; " << traced.patchesTraced << " patches");
    // Measured −0.035 voxels (3 split levels; photons above: 0.04); the issue's bound.
    CHECK(std::abs(y - expected) < 0.5 * kVoxel);
}

TEST_CASE("a layer whose n grows linearly with height bends view rays into catenaries",
          "[profiles][curved]") {
    // The ramp box fills the volume: n from 1 at the bottom to 2 at the top, a gradient of 0.5
    // per unit, five times the linear n² test's: rays heading down at up to ~25° turn and leave
    // going up, as light over a hot road does.
    const LinearLayers medium{0.0f, 1.0f};
    SourceSpec layers = test::boxSource("n", glm::vec3(-1.0f), glm::vec3(1.0f), 0.0f);
    layers.profile = SourceProfile::Ramp;
    layers.rampAxis = 1;
    layers.rampFrom = medium.from;
    layers.rampTo = medium.to;
    layers.voxelSize = float(kVoxel);
    PhotonScene s(kRes, 2.0f, glm::vec3(0.0f), glm::vec3(0.0f, -1.0f, 0.0f), fieldOf(layers));

    const glm::vec3 entry(-0.1f, 0.5f, 1.0f);
    // The worst exit-point error (voxels) and exit-direction error (radians) of four rays, and
    // how many of them were mirage rays that the march turned up.
    auto measure = [&](const char* label, double& worstAngle, int& turned) {
        double worst = 0.0;
        worstAngle = 0.0;
        turned = 0;
        for (glm::vec3 d : {glm::vec3(0.0f, -0.36f, -1.0f), glm::vec3(0.2f, -0.25f, -1.0f),
                            glm::vec3(-0.3f, -0.5f, -1.0f), glm::vec3(0.1f, 0.1f, -1.0f)}) {
            const glm::vec3 dir = glm::normalize(d);
            glm::vec3 exitDir;
            const glm::vec3 got = traceViewRay(s, entry, dir, exitDir);
            glm::dvec3 wantDir;
            const glm::dvec3 want =
                catenaryExit(medium, glm::dvec3(entry), glm::dvec3(dir), wantDir);
            const double error = glm::length(glm::dvec3(got) - want) / kVoxel;
            const double angle = std::acos(std::min(1.0, glm::dot(glm::dvec3(exitDir), wantDir)));
            INFO(label << ", direction " << dir.x << ", " << dir.y << ", " << dir.z << ": exit "
                       << got.x << ", " << got.y << ", " << got.z << ", closed form " << want.x
                       << ", " << want.y << ", " << want.z << " (" << error
                       << " voxels), exit direction " << glm::degrees(angle) << " degrees off");
            worst = std::max(worst, error);
            worstAngle = std::max(worstAngle, angle);
            if (dir.y < 0.0f && wantDir.y > 0.0) {
                ++turned;  // a mirage ray: it went down and leaves going up
                CHECK(exitDir.y > 0.0f);
            }
        }
        return worst;
    };
    // The paper's Euler step. Measured worst exit errors: 0.42, 0.21, 0.11 voxel at steps 1, 0.5,
    // 0.25 voxel (first order), exit directions within 0.14, 0.07, 0.03 degree.
    double previous = 1e9;
    for (float step : {1.0f, 0.5f, 0.25f}) {
        setViewStep(s, step, RayIntegrator::Euler);
        double worstAngle = 0.0;
        int turned = 0;
        const double worst = measure("Euler", worstAngle, turned);
        INFO("Euler, step " << step << ": worst exit error " << worst
                            << " voxels, worst exit direction " << glm::degrees(worstAngle)
                            << " degrees");
        CHECK(turned >= 2);
        CHECK(glm::degrees(worstAngle) < 0.5);
        CHECK(worst < 0.6 * previous);
        previous = worst;
        if (step == 1.0f) CHECK(worst < 0.5);
    }
    CHECK(previous < 0.15);
    // The second-order integrators at the default 1-voxel step: measured 0.00075 voxel and 0.009
    // degree for Verlet (the default), 0.0012 voxel and 0.004 degree for RK4: 350-560× and
    // 16-37× better than Euler.
    for (RayIntegrator integrator : {RayIntegrator::Verlet, RayIntegrator::Rk4}) {
        setViewStep(s, 1.0f, integrator);
        double worstAngle = 0.0;
        int turned = 0;
        const double worst = measure(rayIntegratorName(integrator).c_str(), worstAngle, turned);
        INFO(rayIntegratorName(integrator)
             << ", step 1: worst exit error " << worst << " voxels, worst exit direction "
             << glm::degrees(worstAngle) << " degrees");
        CHECK(turned >= 2);
        CHECK(worst < 0.005);
        CHECK(glm::degrees(worstAngle) < 0.02);
    }
}

TEST_CASE("the index-profile scenes render on the CPU twin", "[profiles][scenes]") {
    for (const char* name : {"luneburg_lens", "mirage_slab", "three_glass_cube",
                             "glass_sphere_floor", "houdini_smoke_glass"}) {
        Scene scene = loadScene(test::sourcePath("data/scenes/" + std::string(name) + ".json"));
        scene.render.width = 40;
        scene.render.height = 30;
        eikon::test::setPhotonSetting(scene, "per_side", 32);
        FrameRenderer renderer(scene, Backend::Cpu);
        const Image image = renderer.render(0);
        double total = 0.0;
        bool finite = true;
        for (const glm::vec4& p : image.pixels) {
            finite = finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
            total += p.x + p.y + p.z;
        }
        INFO(name << ": mean pixel " << total / (3.0 * image.pixels.size()));
        CHECK(finite);
        CHECK(total > 0.0);
        // Every one of them bends light.
        CHECK(renderer.gradientUpdates() == 1);
    }
}

TEST_CASE("a negative field read by a refracting material stops the render, naming it",
          "[profiles][bad-input]") {
    // Temperature may be negative; read as glass of ior 1.5 it would make n = 0.5 in the ball.
    Scene scene;
    scene.path = "cold_glass.json";
    SourceSpec cold = test::sphereSource("temperature", glm::vec3(0.0f), 0.5f, -1.0f, 0.0f, 0.1f);
    cold.jsonPath = "/sources/0";
    scene.sources.push_back(cold);
    MaterialSpec glass = test::material("glass", "temperature", glm::vec3(0.0f));
    glass.ior = 1.5f;
    scene.materials.push_back(glass);
    test::setVolume(scene, glm::vec3(-1.0f), glm::vec3(1.0f), glm::ivec3(20));
    scene.render.width = 8;
    scene.render.height = 6;
    for (Backend backend : {Backend::Cpu, Backend::Gpu}) {
        INFO(test::backendName(backend));
        FrameRenderer renderer(scene, backend);
        CHECK_THROWS_WITH(renderer.render(0),
                          Catch::StartsWith("cold_glass.json:/materials/0/field: material 'glass' "
                                            "(ior 1.5) reads field 'temperature' (from "
                                            "cold_glass.json:/sources/0), which is -1 at (") &&
                              Catch::Contains("the materials make n = 0.5 there"));
        // Once the field is fixed, the same renderer renders.
        Scene next = renderer.scene();  // the next frames' scene, as the test changes it
        next.materials[0].ior = 1.0f;
        CHECK_NOTHROW(renderer.render({0, next}));
    }
}
