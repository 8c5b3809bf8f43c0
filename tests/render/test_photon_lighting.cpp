// Photon lighting end to end through FrameRenderer (render/transport/photons/photon_radiance.h):
// the viewing pass reading the smoothed photon volumes instead of light volumes. A closed form
// (single scattering in a slab), GPU = CPU twin for the volumes and the image, which stages rerun
// on which change, and which scenes need no photons at all.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/gl_context.h"
#include "render/image.h"
#include "support/backends.h"
#include "support/light_transport_setup.h"
#include "support/scene_builders.h"

using eikon::Backend;
using eikon::FrameRenderer;
using eikon::Image;
using eikon::PhotonVolumes;
using eikon::Scene;
using eikon::test::backendName;
using eikon::test::boxSource;
using eikon::test::cameraAt;
using eikon::test::directionalLight;
using eikon::test::material;
using eikon::test::relativeError;
using eikon::test::setVolume;
using eikon::test::sphereSource;

namespace {

// The slab of scene_builders.h lit through photons, one per voxel column.
Scene photonLitSlab(glm::vec3 sigma, float irradiance) {
    Scene scene = eikon::test::scatteringSlab(sigma, irradiance);
    eikon::test::setTransportMethod(scene, "photons");
    eikon::test::setPhotonSetting(scene, "per_side", 40);
    return scene;
}

// The glass sphere in fog (scene_builders.h) at 64 photons per side.
Scene glassInFog() {
    Scene scene = eikon::test::glassSphereInFog();
    eikon::test::setPhotonSetting(scene, "per_side", 64);
    return scene;
}

}  // namespace

TEST_CASE("photon lighting: single scattering in a slab matches the closed form",
          "[photons][view]") {
    const double E = 2.0;
    const glm::vec3 sigma(0.5f, 1.5f, 3.0f);
    const Scene scene = photonLitSlab(sigma, float(E));
    for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
        INFO(backendName(backend));
        FrameRenderer renderer(scene, backend);
        const Image image = renderer.render(0);
        REQUIRE(renderer.transportRuns("photons") == 1);
        REQUIRE(renderer.transportRuns("light_volumes") == 0);  // the only light comes as photons
        const glm::vec4 p = image.at(image.width / 2, image.height / 2);
        for (int c = 0; c < 3; ++c) {
            const double s = sigma[c];
            const double expected = eikon::test::slabCentrePixel(s, E);
            INFO("channel " << c << ": sigma " << s << ", got " << p[c] << ", expected " << expected
                            << ", relative error " << relativeError(p[c], expected));
            // Deposits are exact per voxel (no noise: one photon per column, uniform κ), so what
            // is left is discretisation: the voxel mean of e^(−σz) against its value, the 3×3×3
            // smoothing ((σh)²/4 inside, renormalised one-sided at the two faces), and trilinear
            // lookups, all growing with σh. Measured on both backends: 2.0e-4, 1.8e-3, 7.3e-3
            // for σ = 0.5, 1.5, 3 (about (σh)²/3, h = 0.05).
            CHECK(relativeError(p[c], expected) < 0.02);
        }
    }
}

TEST_CASE("photon lighting: GPU volumes and image equal the CPU twin's", "[photons][gpu]") {
    const Scene scene = glassInFog();
    FrameRenderer gpu(scene, Backend::Gpu);
    FrameRenderer cpu(scene, Backend::Cpu);
    const Image gpuImage = gpu.render(0);
    const Image cpuImage = cpu.render(0);
    const PhotonVolumes g = eikon::test::photonVolumesOf(gpu);
    const PhotonVolumes c = eikon::test::photonVolumesOf(cpu);
    REQUIRE(c.photonsTraced > 0);
    CHECK(g.photonsTraced == c.photonsTraced);
    CHECK(gpu.lastTransportStats().particlesTraced == c.photonsTraced);
    CHECK(cpu.lastTransportStats().particlesTraced == c.photonsTraced);
    CHECK(g.steps == c.steps);
    CHECK(gpu.transportSteps() == cpu.transportSteps());
    REQUIRE(g.radiance.size() == c.radiance.size());
    if (gpu.context() && eikon::isSoftwareRenderer(gpu.context()->rendererName())) {
        // llvmpipe runs the twin's exact math: the same bits after resolve and smoothing.
        CHECK(std::memcmp(g.radiance.data(), c.radiance.data(),
                          c.radiance.size() * sizeof(glm::vec4)) == 0);
        CHECK(std::memcmp(g.direction.data(), c.direction.data(),
                          c.direction.size() * sizeof(glm::vec4)) == 0);
    }
    const eikon::ImageDifference d = eikon::compareImages(gpuImage, cpuImage);
    INFO("max |GPU - CPU| " << d.maxAbs << " of " << d.referenceMax);
    CHECK(d.referenceMax > 0.01);
    // The view pass itself differs only in float rounding (test_view_pass.cpp: ~1e-6).
    CHECK(d.maxAbs < 1e-4 * d.referenceMax);

    // The glass focuses light: the brightest photon voxel is brighter than anything the fog
    // alone would hold (the incident irradiance times a voxel length per voxel volume, about E).
    float brightest = 0.0f;
    for (const glm::vec4& v : c.radiance) brightest = std::max(brightest, v.g);
    const glm::vec3 h = cpu.volume().voxelSize();
    CHECK(brightest / (h.x * h.y * h.z) > 1.5f * 3.0f);
}

TEST_CASE("photon lighting: the same scene twice gives identical images", "[photons]") {
    const Scene scene = glassInFog();
    for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
        INFO(backendName(backend));
        const Image a = FrameRenderer(scene, backend).render(0);
        const Image b = FrameRenderer(scene, backend).render(0);
        CHECK(a.pixels == b.pixels);
    }
}

TEST_CASE("photon lighting: a camera move traces no photons, a light change does",
          "[photons][stages]") {
    for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
        INFO(backendName(backend));
        Scene scene = glassInFog();
        eikon::test::setPhotonSetting(scene, "per_side", 32);
        scene.render.width = 24;
        scene.render.height = 18;
        FrameRenderer renderer(scene, backend);
        const Image first = renderer.render(0);
        REQUIRE(renderer.transportRuns("photons") == 1);
        const int64_t steps = renderer.transportSteps();
        REQUIRE(steps > 0);
        // The counts --stats prints, against the trace's own.
        const PhotonVolumes traced = eikon::test::photonVolumesOf(renderer);
        CHECK(renderer.lastTransportStats().rounds == traced.rounds);
        CHECK(traced.rounds > 0);
        CHECK(renderer.lastTransportStats().particlesCut == traced.photonsCut);

        Scene next = renderer.scene();  // the next frames' scene, as the test changes it
        next.camera.position = glm::vec3(1.0f, 0.5f, 3.5f);
        const Image moved = renderer.render({0, next});
        CHECK(moved.pixels != first.pixels);
        CHECK(renderer.transportRuns("photons") == 1);
        CHECK(renderer.transportSteps() == steps);  // zero photon steps for the camera move
        CHECK(renderer.gradientUpdates() == 1);

        renderer.render({1, next});  // a new frame of the same still scene
        CHECK(renderer.transportSteps() == steps);

        next.lights[0].direction = glm::normalize(glm::vec3(-0.3f, -1.0f, 0.1f));
        renderer.render({0, next});
        CHECK(renderer.transportRuns("photons") == 2);
        CHECK(renderer.transportSteps() > steps);
        CHECK(renderer.gradientUpdates() == 1);  // n did not change

        next.materials[0].scattering = glm::vec3(0.3f);  // σ: photons rerun
        renderer.render({0, next});
        CHECK(renderer.transportRuns("photons") == 3);
        CHECK(renderer.gradientUpdates() == 1);

        // The march's round size and stop rule decide which photons are cut: photons rerun.
        eikon::test::setPhotonSetting(next, "stop_fraction", 0.01f);
        renderer.render({0, next});
        CHECK(renderer.transportRuns("photons") == 4);
        eikon::test::setPhotonSetting(next, "steps_per_round", 5);
        renderer.render({0, next});
        CHECK(renderer.transportRuns("photons") == 5);
        CHECK(renderer.gradientUpdates() == 1);
    }
}

TEST_CASE("photon lighting: scenes that need no photons trace none", "[photons][stages]") {
    SECTION("n = 1 everywhere, photons on auto: straight light volumes") {
        Scene scene = glassInFog();
        scene.materials[1].ior = 1.0f;
        eikon::test::setTransportMethod(scene, "auto");
        FrameRenderer renderer(scene, Backend::Cpu);
        renderer.render(0);
        CHECK(renderer.transportRuns("photons") == 0);
        CHECK(renderer.transportRuns("light_volumes") == 1);
        CHECK(renderer.gradientUpdates() == 0);
    }
    SECTION("refraction but nothing scatters: no photons, no light volumes") {
        Scene scene = glassInFog();
        scene.materials[0].scattering = glm::vec3(0.0f);
        FrameRenderer renderer(scene, Backend::Cpu);
        renderer.render(0);
        CHECK(renderer.transportRuns("photons") == 0);
        CHECK(renderer.transportRuns("light_volumes") == 0);
        CHECK(renderer.gradientUpdates() == 1);  // the view rays still bend
    }
    SECTION("photons off: light volumes even with refraction") {
        Scene scene = glassInFog();
        eikon::test::setTransportMethod(scene, "light_volumes");
        FrameRenderer renderer(scene, Backend::Cpu);
        renderer.render(0);
        CHECK(renderer.transportRuns("photons") == 0);
        CHECK(renderer.transportRuns("light_volumes") == 1);
    }
}
