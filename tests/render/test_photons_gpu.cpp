// The GPU photon pass (shaders/photon_trace.comp) against its CPU twin on the scenes of
// test_photons.cpp: the radiance and direction volumes, the totals and every photon's final
// state, and two GPU runs against each other; directional, point and spot lights.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <functional>

#include "core/camera.h"
#include "render/gl_context.h"
#include "render/params_buffer.h"
#include "render/refraction_volume.h"
#include "render/transport/photons/photon_tracing_gpu.h"
#include "render/volume_textures.h"
#include "support/linear_n2_medium.h"
#include "support/photon_gpu_compare.h"

using namespace eikon;
using eikon::test::GpuPhotonScene;
using eikon::test::GpuRun;
using eikon::test::requireIdentical;

namespace {

float ball(glm::vec3 x) {
    return 0.5f - 0.5f * std::tanh((glm::length(x) - 0.5f) / 0.1f);
}

}  // namespace

TEST_CASE("GPU photons equal the CPU twin: straight n = 1 and a linear n^2 gradient",
          "[photons][gpu]") {
    auto context = createHeadlessContext();
    GpuRun gpu;
    SECTION("uniform n = 1, clear") {
        const GpuPhotonScene s(32, 1.0f, glm::vec3(0.0f),
                               glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f)),
                               [](glm::vec3) { return 0.0f; });
        PhotonSettings settings;
        settings.photonsPerSide = 48;
        requireIdentical(gpu.trace(s, settings), s.trace(settings));
    }
    SECTION("linear n^2 gradient") {
        const GpuPhotonScene s(32, 2.0f, glm::vec3(0.0f),
                               glm::normalize(glm::vec3(0.15f, -1.0f, -0.25f)),
                               eikon::test::linearN2Field);
        PhotonSettings settings;
        settings.photonsPerSide = 16;
        requireIdentical(gpu.trace(s, settings), s.trace(settings));
    }
}

TEST_CASE("GPU photons equal the CPU twin with refraction and extinction", "[photons][gpu]") {
    auto context = createHeadlessContext();
    GpuRun gpu;
    SECTION(
        "energy balance: a soft n = 1.5 ball, absorbing, some photons dropped; each "
        "integrator") {
        const GpuPhotonScene s(32, 1.5f, glm::vec3(4.0f, 6.0f, 10.0f),
                               glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f)), ball,
                               glm::vec3(1.0f, 0.7f, 0.4f));
        for (RayIntegrator integrator : {RayIntegrator::Euler, RayIntegrator::Midpoint,
                                         RayIntegrator::Rk4, RayIntegrator::Verlet}) {
            INFO(rayIntegratorName(integrator));
            PhotonSettings settings;
            settings.photonsPerSide = 64;
            settings.fluxThreshold = 0.05f;
            settings.integrator = integrator;
            const PhotonResultCpu r = gpu.trace(s, settings);
            requireIdentical(r, s.trace(settings));
            CHECK(r.totals.dropped.z > 0.0);
        }
    }
    SECTION("a sharp n = 2.4 ball under grazing light") {
        for (glm::vec3 d : {glm::vec3(1.0f, -0.002f, 0.0f), glm::vec3(0.3f, -1.0f, 0.001f)}) {
            const GpuPhotonScene s(32, 2.4f, glm::vec3(0.3f, 0.6f, 1.0f), glm::normalize(d),
                                   [](glm::vec3 x) { return glm::length(x) < 0.5f ? 1.0f : 0.0f; });
            PhotonSettings settings;
            settings.photonsPerSide = 64;
            settings.maxSteps = 4000;
            INFO("direction " << d.x << " " << d.y << " " << d.z);
            requireIdentical(gpu.trace(s, settings), s.trace(settings));
        }
    }
}

TEST_CASE("two GPU photon runs are identical", "[photons][gpu]") {
    auto context = createHeadlessContext();
    GpuRun gpu;
    const GpuPhotonScene s(24, 1.5f, glm::vec3(1.0f, 2.0f, 4.0f),
                           glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f)), ball,
                           glm::vec3(1.0f, 0.7f, 0.4f));
    PhotonSettings settings;
    settings.photonsPerSide = 48;
    settings.seed = 7;
    const PhotonResultCpu one = gpu.trace(s, settings);
    const PhotonResultCpu two = gpu.trace(s, settings);  // buffers reused: cleared between runs
    requireIdentical(one, two);
}

TEST_CASE("GPU photons equal the CPU twin for point and spot lights, run after run",
          "[photons][gpu]") {
    // The refracting, absorbing ball of the directional tests, lit in each of the layouts point
    // and spot lights take: a cube of grids around a light inside the box, one perspective grid
    // toward the box, one along a spot's axis.
    auto context = createHeadlessContext();
    GpuRun gpu;
    const glm::vec3 color(1.0f, 0.7f, 0.4f);
    const glm::vec3 absorption(4.0f, 6.0f, 10.0f);
    auto check = [&](const LightSpec& light, int side) {
        const GpuPhotonScene s(32, 1.5f, absorption, light, ball);
        PhotonSettings settings;
        settings.photonsPerSide = side;
        const PhotonResultCpu one = gpu.trace(s, settings);
        requireIdentical(one, s.trace(settings));
        requireIdentical(gpu.trace(s, settings), one);
    };
    SECTION("a point light inside the box (six grids)") {
        check(GpuPhotonScene::pointLight(glm::vec3(0.1f, 0.2f, -0.15f), color), 32);
    }
    SECTION("a point light outside the box (one grid toward it)") {
        check(GpuPhotonScene::pointLight(glm::vec3(0.3f, 2.6f, -0.4f), color), 48);
    }
    SECTION("a spot light (one grid along its axis)") {
        check(GpuPhotonScene::spotLight(glm::vec3(0.15f, 2.4f, -0.1f),
                                        glm::normalize(glm::vec3(0.1f, -1.0f, 0.05f)), color, 20.0f,
                                        5.0f),
              48);
    }
    SECTION("a directional light with a disc (each photon its own direction of the disc)") {
        LightSpec sun =
            GpuPhotonScene::directionalLight(glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f)), color);
        sun.angularDiameterDeg = 15.0f;
        check(sun, 48);
    }
}

TEST_CASE("with the driver's own math the GPU photons agree with the CPU twin in total",
          "[photons][gpu]") {
    // What a hardware GPU runs (no EK_EXACT_MATH): single photons may take other paths after a
    // last-bit difference, but the energy budget and the deposited total must agree closely.
    auto context = createHeadlessContext();
    GpuRun gpu(/*exactMath=*/false);
    const GpuPhotonScene s(32, 1.5f, glm::vec3(4.0f, 6.0f, 10.0f),
                           glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f)), ball,
                           glm::vec3(1.0f, 0.7f, 0.4f));
    PhotonSettings settings;
    settings.photonsPerSide = 64;
    const PhotonResultCpu r = gpu.trace(s, settings);
    const PhotonResultCpu cpu = s.trace(settings);
    for (int c = 0; c < 3; ++c) {
        INFO("channel " << c);
        CHECK(r.totals.emitted[c] == Approx(cpu.totals.emitted[c]).epsilon(1e-6));
        CHECK(r.totals.escaped[c] == Approx(cpu.totals.escaped[c]).epsilon(1e-3));
        double deposited = 0.0, deposited0 = 0.0;
        for (size_t i = 0; i < r.radiance.size(); ++i) {
            deposited += r.radiance[i][c];
            deposited0 += cpu.radiance[i][c];
        }
        CHECK(deposited == Approx(deposited0).epsilon(1e-3));
        const double balance = r.totals.emitted[c] - r.totals.escaped[c] -
                               r.totals.extinguished[c] - r.totals.dropped[c];
        CHECK(std::abs(balance) < 1e-6 * r.totals.emitted[c]);
    }
}
