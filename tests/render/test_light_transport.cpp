// The light-transport interface and registry (render/light_transport_registry.h): how a scene
// picks its method, each method's own settings section with the strict reader's errors, the
// cache keys built from each method's settings, and the one output contract every registered
// method gives the view pass.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/light_transport_registry.h"
#include "render/transport/light_volumes/light_volume_transport.h"
#include "render/transport/photons/photon_transport.h"
#include "render/transport/wavefront/wavefront_transport.h"
#include "support/light_transport_setup.h"

using Catch::Matchers::Contains;
using eikon::lightTransportName;
using eikon::Scene;

namespace {

// A glass ball in fog under a spot light: refracting and scattering, so "auto" means photons.
std::string glassInFog(const std::string& renderKeys, bool scatters = true, bool receiver = false) {
    const std::string fog = scatters ? R"(, "scattering": [0.5, 0.5, 0.5])" : "";
    return R"({
      "volume": {"bounds": {"min": [-1, -1, -1], "max": [1, 1, 1]}, "resolution": 16},
      "sources": [
        {"type": "box", "field": "density", "min": [-1, -1, -1], "max": [1, 1, 1], "value": 1,
         "voxel_size": 0.125},
        {"type": "sphere", "field": "n", "center": [0, 0, 0], "radius": 0.5, "value": 1,
         "falloff": 0.1, "voxel_size": 0.125}
      ],
      "materials": [
        {"name": "fog", "field": "density", "absorption": [0.1, 0.1, 0.1])" +
           fog + R"(},
        {"name": "glass", "field": "n", "ior": 1.5}
      ],
      "lights": [{"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0],
                  "intensity": 20, "cone_angle_deg": 20}],
      "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},)" +
           (receiver ? R"( "receivers": [{"type": "plane", "axis": "y", "position": -0.8}],)"
                     : "") +
           R"( "render": {"width": 24, "height": 18)" +
           (renderKeys.empty() ? "" : ", " + renderKeys) + "}}";
}

Scene parse(const std::string& text) {
    return eikon::parseScene(text, "glass.json");
}

struct Failure {
    std::string where;
    std::string reason;
};

// The error makeLightTransport (and so every command, before any work) raises for `text`.
Failure failureOf(const std::string& text) {
    const Scene scene = parse(text);
    try {
        eikon::checkLightTransport(scene);
    } catch (const eikon::Error& e) {
        return {e.where(), e.reason()};
    }
    FAIL("expected an eikon::Error for: " << text);
    return {};
}

// The largest |a − b| of two pictures' colour channels; largest: b's largest channel.
double largestDifference(const eikon::Image& a, const eikon::Image& b, double& largest) {
    double difference = 0.0;
    largest = 0.0;
    for (size_t i = 0; i < b.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            largest = std::max(largest, double(b.pixels[i][c]));
            difference =
                std::max(difference, std::abs(double(a.pixels[i][c]) - double(b.pixels[i][c])));
        }
    return difference;
}

}  // namespace

TEST_CASE("render.light_transport.method: auto picks photons where light bends and shows",
          "[light_transport]") {
    CHECK(lightTransportName(parse(glassInFog(""))) == "photons");
    // Nothing scatters: only a receiver would show the bent light.
    CHECK(lightTransportName(parse(glassInFog("", false))) == "light_volumes");
    CHECK(lightTransportName(parse(glassInFog("", false, true))) == "photons");
    // No refraction: straight light volumes are exact.
    Scene straight = parse(glassInFog(""));
    straight.materials[1].ior = 1.0f;
    CHECK(lightTransportName(straight) == "light_volumes");
    // Named methods are taken as written.
    CHECK(lightTransportName(parse(
              glassInFog(R"("light_transport": {"method": "light_volumes"})"))) == "light_volumes");
    CHECK(lightTransportName(straight) == "light_volumes");
    eikon::test::setTransportMethod(straight, "photons");
    CHECK(lightTransportName(straight) == "photons");
}

TEST_CASE("a light with a disc: the wavefront method refuses it, the others draw it",
          "[light_transport][soft_light]") {
    Scene straight = parse(glassInFog(""));
    straight.materials[1].ior = 1.0f;
    eikon::LightSpec sun;
    sun.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    sun.angularDiameterDeg = 5.0f;
    straight.lights = {sun};
    CHECK(lightTransportName(straight) == "light_volumes");
    eikon::test::setTransportMethod(straight, "wavefront");
    try {
        eikon::checkLightTransport(straight);
        FAIL("the wavefront method accepted a light with a disc");
    } catch (const eikon::Error& e) {
        CHECK(std::string(e.where()) == "glass.json:/lights/0/angular_diameter_deg");
        CHECK_THAT(e.reason(),
                   Contains("the wavefront method draws a light from a single direction"));
    }
    for (const char* method : {"photons", "plane_sweep", "light_volumes"}) {
        eikon::test::setTransportMethod(straight, method);
        CHECK_NOTHROW(eikon::checkLightTransport(straight));
    }
}

TEST_CASE("each method reads its own section: defaults written once, errors at the pointer",
          "[light_transport]") {
    SECTION("photon defaults are the trace's") {
        const eikon::PhotonTransportSettings d = eikon::readPhotonTransportSettings(nullptr);
        const eikon::PhotonSettings trace;
        CHECK(d.trace.photonsPerSide == trace.photonsPerSide);
        CHECK(d.trace.stopFraction == 1e-3f);
        CHECK(d.trace.stepsPerRound == 32);
        CHECK(d.kappaTolerance == 0.1f);
        const eikon::LightVolumeSettings l = eikon::readLightVolumeSettings(nullptr);
        CHECK(l.shadows == eikon::ShadowMode::Swept);
        CHECK(l.shadowStepVoxels == 3.0f);
    }
    SECTION("an unknown method, with a hint") {
        const Failure f = failureOf(glassInFog(R"("light_transport": {"method": "photon"})"));
        CHECK(f.where == "glass.json:/render/light_transport/method");
        CHECK_THAT(f.reason, Contains("did you mean \"photons\"?"));
        CHECK_THAT(f.reason, Contains("auto"));
        CHECK_THAT(f.reason, Contains("light_volumes"));
    }
    SECTION("a misspelt section") {
        const Failure f = failureOf(glassInFog(R"("light_transport": {"photon": {}})"));
        CHECK(f.where == "glass.json:/render/light_transport/photon");
        CHECK_THAT(f.reason, Contains("did you mean 'photons'?"));
    }
    SECTION("a misspelt photon setting") {
        const Failure f =
            failureOf(glassInFog(R"("light_transport": {"photons": {"stop_fractions": 0.1}})"));
        CHECK(f.where == "glass.json:/render/light_transport/photons/stop_fractions");
        CHECK_THAT(f.reason, Contains("did you mean 'stop_fraction'?"));
    }
    SECTION("photon settings out of range") {
        CHECK(failureOf(glassInFog(R"("light_transport": {"photons": {"stop_fraction": 1}})"))
                  .where == "glass.json:/render/light_transport/photons/stop_fraction");
        CHECK(failureOf(glassInFog(R"("light_transport": {"photons": {"steps_per_round": 0}})"))
                  .where == "glass.json:/render/light_transport/photons/steps_per_round");
        const Failure k =
            failureOf(glassInFog(R"("light_transport": {"photons": {"kappa_tolerance": -1}})"));
        CHECK(k.where == "glass.json:/render/light_transport/photons/kappa_tolerance");
        CHECK_THAT(k.reason, Contains(">= 0"));
        CHECK(failureOf(glassInFog(R"("light_transport": {"photons": {"max_step_voxels": 0}})"))
                  .where == "glass.json:/render/light_transport/photons/max_step_voxels");
        const Failure i =
            failureOf(glassInFog(R"("light_transport": {"photons": {"integrator": "rk2"}})"));
        CHECK(i.where == "glass.json:/render/light_transport/photons/integrator");
        CHECK_THAT(i.reason, Contains("\"midpoint\""));
    }
    SECTION("the section of a method that does not run is checked too") {
        const Failure f = failureOf(glassInFog(
            R"("light_transport": {"method": "light_volumes", "photons": {"per_side": 0}})"));
        CHECK(f.where == "glass.json:/render/light_transport/photons/per_side");
    }
    SECTION("light volume settings") {
        const Failure f =
            failureOf(glassInFog(R"("light_transport": {"light_volumes": {"shadows": "sweep"}})"));
        CHECK(f.where == "glass.json:/render/light_transport/light_volumes/shadows");
        CHECK_THAT(f.reason, Contains("did you mean \"swept\"?"));
        CHECK(failureOf(
                  glassInFog(R"("light_transport": {"light_volumes": {"shadow_step_voxels": 0}})"))
                  .where == "glass.json:/render/light_transport/light_volumes/shadow_step_voxels");
    }
    SECTION("not an object") {
        try {
            parse(glassInFog(R"("light_transport": "photons")"));
            FAIL("a string section was accepted");
        } catch (const eikon::Error& e) {
            CHECK(std::string(e.where()) == "glass.json:/render/light_transport");
        }
    }
    SECTION("the command line's overrides merge into the section") {
        Scene s = parse(glassInFog(R"("light_transport": {"photons": {"per_side": 12}})"));
        eikon::test::setShadows(s, "marched");
        eikon::test::setPhotonSetting(s, "stop_fraction", 0.25);
        const auto made = eikon::makeLightTransport(s, eikon::TransportDevice{});
        const eikon::json::Json section = eikon::json::Json::parse(s.render.lightTransport);
        CHECK(section["photons"]["per_side"] == 12);
        CHECK(section["photons"]["stop_fraction"] == 0.25);
        CHECK(section["light_volumes"]["shadows"] == "marched");
        CHECK(made->name() == "photons");
    }
}

// What makes each method run again: its own settings, through its cache key. A setting that
// changes the output must change the key (else a frame would show stale light).
TEST_CASE("a method's cache key follows its own settings", "[light_transport]") {
    const Scene base = parse(glassInFog(""));
    eikon::FrameRenderer renderer(base, eikon::Backend::Cpu);
    renderer.render(0);
    REQUIRE(renderer.transportRuns("photons") == 1);
    renderer.render(0);
    CHECK(renderer.transportRuns("photons") == 1);  // nothing changed
    int runs = 1;
    Scene next = renderer.scene();  // the next frames' scene, as the test changes it
    for (const auto& [key, value] :
         std::vector<std::pair<std::string, double>>{{"per_side", 20},
                                                     {"min_step_voxels", 1.5},
                                                     {"flux_threshold", 1e-3},
                                                     {"stop_fraction", 0.01},
                                                     {"steps_per_round", 5},
                                                     {"kappa_tolerance", 0.3},
                                                     {"max_step_voxels", 4}}) {
        INFO(key);
        eikon::test::setPhotonSetting(next, key, value);
        renderer.render({0, next});
        CHECK(renderer.transportRuns("photons") == ++runs);
    }
    // So does the integrator.
    eikon::patchLightTransport(next, R"({"photons": {"integrator": "verlet"}})");
    renderer.render({0, next});
    CHECK(renderer.transportRuns("photons") == ++runs);
    // Light volume settings change nothing of the photons.
    eikon::test::setShadows(next, "volume");
    renderer.render({0, next});
    CHECK(renderer.transportRuns("photons") == runs);

    Scene straight = base;
    eikon::test::setTransportMethod(straight, "light_volumes");
    eikon::FrameRenderer volumes(straight, eikon::Backend::Cpu);
    volumes.render(0);
    REQUIRE(volumes.transportRuns("light_volumes") == 1);
    Scene nextVolumes = volumes.scene();  // the next frames' scene, as the test changes it
    eikon::test::setTransportSetting(nextVolumes, "light_volumes", "shadow_step_voxels", 2);
    volumes.render({0, nextVolumes});
    CHECK(volumes.transportRuns("light_volumes") == 2);
    eikon::test::setShadows(nextVolumes, "volume");
    volumes.render({0, nextVolumes});
    CHECK(volumes.transportRuns("light_volumes") == 3);
    // Marched at every view sample: no volume to compute.
    eikon::test::setShadows(nextVolumes, "marched");
    volumes.render({0, nextVolumes});
    CHECK(volumes.transportRuns("light_volumes") == 3);
    CHECK(volumes.transportRuns("photons") == 0);
}

TEST_CASE(
    "the wavefront method's settings: errors at the pointer, each in its cache key, its GPU "
    "run",
    "[light_transport][wavefront]") {
    SECTION("defaults are the trace's") {
        const eikon::WavefrontTransportSettings d = eikon::readWavefrontTransportSettings(nullptr);
        const eikon::WavefrontSettings trace;
        CHECK(d.trace.patchesPerSide == trace.patchesPerSide);
        CHECK(d.trace.atCaustic == EK_WAVEFRONT_KEEP);
        CHECK(d.trace.depositSamples == 2);
        CHECK(d.trace.integrator == eikon::WavefrontIntegrator::Rk4);
    }
    SECTION("errors") {
        const Failure f =
            failureOf(glassInFog(R"("light_transport": {"wavefront": {"split_voxel": 1}})"));
        CHECK(f.where == "glass.json:/render/light_transport/wavefront/split_voxel");
        CHECK_THAT(f.reason, Contains("did you mean 'split_voxels'?"));
        const Failure c =
            failureOf(glassInFog(R"("light_transport": {"wavefront": {"at_caustic": "drop"}})"));
        CHECK(c.where == "glass.json:/render/light_transport/wavefront/at_caustic");
        CHECK_THAT(c.reason, Contains("\"remove\""));
        for (const char* bad :
             {R"({"per_side": 0})", R"({"step_voxels": 0})", R"({"max_level": 13})",
              R"({"max_patches": 0})", R"({"deposit_samples": 9})", R"({"flux_threshold": 1})",
              R"({"integrator": "verlet"})"}) {
            INFO(bad);
            const Failure b = failureOf(
                glassInFog(std::string(R"("light_transport": {"wavefront": )") + bad + "}"));
            CHECK(b.where.rfind("glass.json:/render/light_transport/wavefront/", 0) == 0);
        }
    }
    SECTION("a patch budget beyond memory: one line at the section, before any work") {
        Scene scene =
            parse(glassInFog(R"("light_transport": {"wavefront": {"max_patches": 1073741824}})"));
        eikon::test::setTransportMethod(scene, "wavefront");
        try {
            eikon::FrameRenderer(scene, eikon::Backend::Cpu).render(0);
            FAIL("no error");
        } catch (const eikon::Error& e) {
            CHECK(e.where() == "glass.json:/render/light_transport/wavefront");
            CHECK_THAT(e.reason(), Contains("lower per_side or max_patches"));
        }
    }
    SECTION("every setting reruns it; other methods' settings do not") {
        Scene base = parse(glassInFog(""));
        eikon::test::setTransportMethod(base, "wavefront");
        eikon::test::setTransportSetting(base, "wavefront", "per_side", 8);
        eikon::FrameRenderer renderer(base, eikon::Backend::Cpu);
        renderer.render(0);
        REQUIRE(renderer.transportRuns("wavefront") == 1);
        renderer.render(0);
        CHECK(renderer.transportRuns("wavefront") == 1);
        int runs = 1;
        Scene next = renderer.scene();
        for (const auto& [key, value] :
             std::vector<std::pair<std::string, double>>{{"per_side", 10},
                                                         {"step_voxels", 1.5},
                                                         {"split_voxels", 2},
                                                         {"max_level", 4},
                                                         {"max_patches", 1000},
                                                         {"flux_threshold", 1e-3},
                                                         {"deposit_samples", 1}}) {
            INFO(key);
            eikon::test::setTransportSetting(next, "wavefront", key, value);
            renderer.render({0, next});
            CHECK(renderer.transportRuns("wavefront") == ++runs);
        }
        eikon::patchLightTransport(next, R"({"wavefront": {"at_caustic": "remove"}})");
        renderer.render({0, next});
        CHECK(renderer.transportRuns("wavefront") == ++runs);
        eikon::patchLightTransport(next, R"({"wavefront": {"integrator": "euler"}})");
        renderer.render({0, next});
        CHECK(renderer.transportRuns("wavefront") == ++runs);
        eikon::test::setPhotonSetting(next, "per_side", 20);
        renderer.render({0, next});
        CHECK(renderer.transportRuns("wavefront") == runs);
    }
    SECTION("on the GPU the frame and the counts are the CPU twin's") {
        for (bool receiver : {false, true}) {
            INFO((receiver ? "with" : "without") << " a floor receiver");
            Scene scene = parse(glassInFog("", true, receiver));
            eikon::test::setTransportMethod(scene, "wavefront");
            eikon::FrameRenderer gpu(scene, eikon::Backend::Gpu);
            const eikon::Image gpuImage = gpu.render(0);
            eikon::FrameRenderer cpu(scene, eikon::Backend::Cpu);
            const eikon::Image cpuImage = cpu.render(0);
            CHECK(gpu.transportRuns("wavefront") == 1);
            const eikon::TransportStats g = gpu.lightTransport().stats();
            const eikon::TransportStats c = cpu.lightTransport().stats();
            CHECK(g.steps > 0);
            CHECK(g.steps == c.steps);
            CHECK(g.particlesTraced == c.particlesTraced);
            CHECK(g.particlesSplit == c.particlesSplit);
            CHECK(g.rounds == c.rounds);
            REQUIRE(gpuImage.pixels.size() == cpuImage.pixels.size());
            double largest = 0.0;
            const double difference = largestDifference(gpuImage, cpuImage, largest);
            INFO("max |GPU - CPU| " << difference << " of an image max " << largest);
            REQUIRE(largest > 0.01);
            // The trace's deposits are the twin's bits for a directional light
            // (test_wavefront_gpu.cpp) and within their last bits for this point light (atan);
            // the view pass then differs from its twin by float rounding (test_view_pass.cpp).
            CHECK(difference < 1e-4 * largest);
        }
    }
}

TEST_CASE("the plane sweep's settings: errors at the pointer, each in its cache key, its GPU run",
          "[light_transport][plane_sweep]") {
    SECTION("errors") {
        const Failure f = failureOf(
            glassInFog(R"("light_transport": {"plane_sweep": {"planes_per_voxels": 2}})"));
        CHECK(f.where == "glass.json:/render/light_transport/plane_sweep/planes_per_voxels");
        CHECK_THAT(f.reason, Contains("did you mean 'planes_per_voxel'?"));
        for (const char* bad : {R"({"planes_per_voxel": 0})", R"({"planes_per_voxel": 17})",
                                R"({"back_trace_refinements": 5})", R"({"min_cosine": 1})",
                                R"({"intensity_correction": 1})"}) {
            INFO(bad);
            const Failure b = failureOf(
                glassInFog(std::string(R"("light_transport": {"plane_sweep": )") + bad + "}"));
            CHECK(b.where.rfind("glass.json:/render/light_transport/plane_sweep/", 0) == 0);
        }
    }
    SECTION("a point light inside the box cannot be swept: one line, before any work") {
        std::string text = glassInFog(R"("light_transport": {"method": "plane_sweep"})");
        const std::string from = R"("position": [0, 3, 0])";
        text.replace(text.find(from), from.size(), R"("position": [0, 0.5, 0])");
        Scene scene = parse(text);
        try {
            eikon::FrameRenderer(scene, eikon::Backend::Cpu).render(0);
            FAIL("no error");
        } catch (const eikon::Error& e) {
            CHECK_THAT(std::string(e.what()), Contains("outside the face its light enters"));
        }
    }
    SECTION("every setting reruns it; other methods' settings do not") {
        Scene base = parse(glassInFog(""));
        eikon::test::setTransportMethod(base, "plane_sweep");
        eikon::FrameRenderer renderer(base, eikon::Backend::Cpu);
        renderer.render(0);
        REQUIRE(renderer.transportRuns("plane_sweep") == 1);
        renderer.render(0);
        CHECK(renderer.transportRuns("plane_sweep") == 1);
        int runs = 1;
        Scene next = renderer.scene();
        for (const char* patch : {R"({"plane_sweep": {"planes_per_voxel": 2}})",
                                  R"({"plane_sweep": {"back_trace_refinements": 2}})",
                                  R"({"plane_sweep": {"intensity_correction": false}})",
                                  R"({"plane_sweep": {"min_cosine": 0.3}})"}) {
            INFO(patch);
            eikon::patchLightTransport(next, patch);
            renderer.render({0, next});
            CHECK(renderer.transportRuns("plane_sweep") == ++runs);
        }
        eikon::test::setPhotonSetting(next, "per_side", 20);
        renderer.render({0, next});
        CHECK(renderer.transportRuns("plane_sweep") == runs);
    }
    SECTION("on the GPU the frame is the CPU twin's (llvmpipe: the twin's rounding)") {
        for (bool receiver : {false, true}) {
            INFO((receiver ? "with" : "without") << " a floor receiver");
            Scene scene = parse(glassInFog("", true, receiver));
            eikon::test::setTransportMethod(scene, "plane_sweep");
            eikon::FrameRenderer gpu(scene, eikon::Backend::Gpu);
            const eikon::Image gpuImage = gpu.render(0);
            const eikon::Image cpuImage =
                eikon::FrameRenderer(scene, eikon::Backend::Cpu).render(0);
            CHECK(gpu.transportRuns("plane_sweep") == 1);
            CHECK(gpu.lightTransport().stats().steps > 0);
            REQUIRE(gpuImage.pixels.size() == cpuImage.pixels.size());
            double largest = 0.0;
            const double difference = largestDifference(gpuImage, cpuImage, largest);
            INFO("max |GPU - CPU| " << difference << " of an image max " << largest);
            REQUIRE(largest > 0.01);
            // The sweep's volumes and maps are the same bits (test_plane_sweep_gpu.cpp); the
            // view pass then differs from its twin by float rounding (test_view_pass.cpp).
            CHECK(difference < 1e-4 * largest);
        }
    }
}

// Every registered method, run on the CPU twin, fills the output contract the view pass reads:
// per-light transmittance for the lights lit straight, fluence and direction (and the receiver
// map) for the lights lit through the fluence; and it lights the fog (a method that produced
// nothing would leave the image dark).
TEST_CASE("every registered method fills the one output contract", "[light_transport]") {
    for (const eikon::LightTransportMethod& method : eikon::lightTransportMethods()) {
        INFO(method.name);
        Scene scene = parse(glassInFog("", true, true));
        eikon::test::setTransportMethod(scene, method.name);
        eikon::test::setPhotonSetting(scene, "per_side", 48);
        eikon::FrameRenderer renderer(scene, eikon::Backend::Cpu);
        const eikon::Image image = renderer.render(0);
        REQUIRE(renderer.lightTransport().name() == method.name);
        CHECK(renderer.transportRuns(method.name) == 1);
        const eikon::TransportOutputCpu out = renderer.lightTransport().outputCpu();
        const size_t voxels = 16 * 16 * 16;
        const bool fluence = out.fluence != nullptr;
        CHECK((fluence || out.lightTransmittance.size() == scene.lights.size()));
        if (fluence) {
            CHECK(out.direction != nullptr);
            CHECK(out.fluenceVoxels == voxels);
            CHECK(out.receiverMap != nullptr);
            CHECK(out.receiverTexels > 0);
        }
        double sum = 0.0;
        for (const glm::vec4& p : image.pixels) sum += p.r + p.g + p.b;
        CHECK(sum > 0.0);
    }
}
