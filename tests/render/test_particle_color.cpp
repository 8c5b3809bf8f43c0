// Particle colour rendered (core/particle_color.h, shaders/shared/optics.h particleColorOverStep):
// a uniform emitting medium against the closed form with a named map, scattering tinted while
// extinction is not, the colour of a transfer-function material read from its field's own value,
// the slot limit as a one-line error, and the GPU against the CPU twin.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/particle_color.h"
#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/image.h"
#include "support/backends.h"
#include "support/scene_builders.h"

using Catch::Matchers::Contains;
using eikon::Backend;
using eikon::FrameRenderer;
using eikon::Image;
using eikon::Scene;
using eikon::test::backendName;
using eikon::test::boxSource;
using eikon::test::material;

namespace {

// One pixel looking along −z through [−1, 1]³ (16³) at a black environment.
Scene darkProbe() {
    Scene s = eikon::test::transmittanceProbe();
    s.environment.color = glm::vec3(0.0f);
    return s;
}

// A ball of fog (values 0 to 0.8) lit from above, its scattering coloured by inferno over
// [0, 0.8], seen from the side at width × height.
Scene litFogBall(int width, int height) {
    Scene scene = darkProbe();
    scene.render.width = width;
    scene.render.height = height;
    scene.camera = eikon::test::cameraAt(glm::vec3(1.5f, 1.0f, 4.0f), glm::vec3(0.0f), 40.0f);
    scene.sources.push_back(
        eikon::test::sphereSource("density", glm::vec3(0.1f), 0.6f, 0.8f, 0.3f, 0.125f));
    scene.lights.push_back(eikon::test::directionalLight(glm::vec3(-1.0f, -2.0f, -0.5f), 3.0f));
    scene.materials.push_back(material("fog", "density", glm::vec3(0.3f), glm::vec3(2.0f), 0.3f));
    scene.materials[0].particleColor.map = "inferno";
    scene.materials[0].particleColor.range = glm::vec2(0.0f, 0.8f);
    return scene;
}

eikon::ParticleColorSpec points(std::vector<glm::vec4> p) {
    eikon::ParticleColorSpec s;
    s.points = std::move(p);
    return s;
}

}  // namespace

TEST_CASE("A uniform emitting medium glows in its map's colour, by the closed form",
          "[particle_color]") {
    // Value 0.5 everywhere, emission 1 and absorption 1 per unit: along the 2 units of the volume
    // L = tint(0.5) · 0.5 · (1 − e^(−0.5·2)) / 0.5. The tint is viridis's middle: green-teal.
    Scene scene = darkProbe();
    scene.sources.push_back(
        boxSource("density", glm::vec3(-1.0f), glm::vec3(1.0f), 0.5f, 0.0f, 0.125f));
    scene.materials.push_back(
        material("glow", "density", glm::vec3(1.0f), glm::vec3(0.0f), 0.0f, glm::vec3(1.0f)));
    scene.materials[0].particleColor.map = "viridis";
    const glm::vec3 tint = eikon::particleColorAt(scene.materials[0].particleColor, 0.5f);
    REQUIRE(tint.g > 2.0f * tint.r);  // a colour, not grey: a lost tint would show
    const double glow = 1.0 - std::exp(-1.0);
    for (Backend backend : {Backend::Cpu, Backend::Gpu}) {
        INFO(backendName(backend));
        const glm::vec3 l = eikon::test::firstPixel(scene, backend);
        CHECK(l.r == Approx(tint.r * glow).epsilon(1e-4));
        CHECK(l.g == Approx(tint.g * glow).epsilon(1e-4));
        CHECK(l.b == Approx(tint.b * glow).epsilon(1e-4));
    }
}

TEST_CASE("A colour band thinner than a step is pre-integrated, not hit or missed",
          "[particle_color]") {
    // A ramp f = (z + 1)/2 through [−1, 1]³, emitting 1 per unit of f in a colour that is white
    // only in a thin triangular band of values (base 6/255, area 3/255, its corners on table
    // entries), black elsewhere; no absorption. Steps of 4 voxels (0.5 units, a quarter of f's
    // range each): the band lies inside the step from f = 0.75 to 0.5.
    //   Exact: L = ∫ f tint dz = 2 · f_band · area.
    //   Pre-integrated: the step's mean colour area/0.25 at its midpoint's f, 0.625.
    //   Sampled at the midpoint (f = 0.625): the band hit at 79 % of its peak (17× too bright) or
    //   missed (0), depending on where it lies.
    const auto glowThrough = [](float bandCentre) {
        Scene scene = darkProbe();
        eikon::SourceSpec ramp =
            boxSource("density", glm::vec3(-1.0f), glm::vec3(1.0f), 1.0f, 0.0f, 0.125f);
        ramp.profile = eikon::SourceProfile::Ramp;
        ramp.rampAxis = 2;
        ramp.rampFrom = 0.0f;
        ramp.rampTo = 1.0f;
        scene.sources.push_back(ramp);
        scene.materials.push_back(
            material("glow", "density", glm::vec3(0.0f), glm::vec3(0.0f), 0.0f, glm::vec3(1.0f)));
        const float w = 3.0f / 255.0f;
        scene.materials[0].particleColor = points({{0.0f, 0.0f, 0.0f, 0.0f},
                                                   {bandCentre - w, 0.0f, 0.0f, 0.0f},
                                                   {bandCentre, 1.0f, 1.0f, 1.0f},
                                                   {bandCentre + w, 0.0f, 0.0f, 0.0f},
                                                   {1.0f, 0.0f, 0.0f, 0.0f}});
        scene.render.stepVoxels = 4.0f;
        return scene;
    };
    const double area = 3.0 / 255.0;
    for (Backend backend : {Backend::Cpu, Backend::Gpu}) {
        INFO(backendName(backend));
        // Centred on the step's midpoint (160/255 = 0.627): within 0.4 % of exact.
        const float centred = 160.0f / 255.0f;
        const double exactCentred = 2.0 * centred * area;
        CHECK(eikon::test::firstPixel(glowThrough(centred), backend).g ==
              Approx(0.625 * area / 0.25 * 0.5).epsilon(1e-3));
        CHECK(eikon::test::firstPixel(glowThrough(centred), backend).g ==
              Approx(exactCentred).epsilon(5e-3));
        // Between midpoints (143/255 = 0.561), where the midpoint sees none of it: the band's
        // light, weighed by the step's middle value instead of its own (11 % more).
        const float between = 143.0f / 255.0f;
        const double exactBetween = 2.0 * between * area;
        const double l = eikon::test::firstPixel(glowThrough(between), backend).g;
        CHECK(l == Approx(0.625 * area / 0.25 * 0.5).epsilon(1e-3));
        CHECK(l == Approx(exactBetween).epsilon(0.12));
    }
}

TEST_CASE("A particle colour tints what is scattered, not what is taken away", "[particle_color]") {
    // The lit scattering slab (σ = 2 per unit): with a constant colour c the picture is c times
    // the uncoloured one, and its transmittance (alpha) is the same to the bit.
    Scene plain = eikon::test::scatteringSlab(glm::vec3(2.0f), 3.0f);
    plain.render.width = 9;
    plain.render.height = 7;
    Scene tinted = plain;
    const glm::vec3 c(0.25f, 0.5f, 1.0f);
    tinted.materials[0].particleColor = points({{0.0f, c.r, c.g, c.b}, {1.0f, c.r, c.g, c.b}});
    for (Backend backend : {Backend::Cpu, Backend::Gpu}) {
        INFO(backendName(backend));
        const Image a = FrameRenderer(plain, backend).render(0);
        const Image b = FrameRenderer(tinted, backend).render(0);
        REQUIRE(a.pixels.size() == b.pixels.size());
        const glm::vec4 centre = a.at(a.width / 2, a.height / 2);
        REQUIRE(centre.r > 0.01f);  // the slab scatters toward the camera there
        for (size_t i = 0; i < a.pixels.size(); ++i) {
            CHECK(b.pixels[i].a == a.pixels[i].a);
            for (int ch = 0; ch < 3; ++ch)
                CHECK(b.pixels[i][ch] ==
                      Approx(c[ch] * a.pixels[i][ch]).epsilon(1e-5).margin(1e-9));
        }
    }
}

TEST_CASE("A transfer-function material's colour reads its field's own value, not the amount",
          "[particle_color]") {
    // A shell of 0.5 around a core of 1, all of it one tissue (amount 1 above 0.45), emitting 1
    // per unit; its colour goes from red at 0.5 to blue at 1. Along the axis the ray crosses 0.5
    // of shell and 0.5 of core: (0.5, 0, 0.5). Coloured by the amount (1 everywhere) it would be
    // all blue, (0, 0, 1).
    Scene scene = darkProbe();
    eikon::test::addShellAroundCore(scene);
    scene.materials.push_back(
        material("tissue", "density", glm::vec3(0.0f), glm::vec3(0.0f), 0.0f, glm::vec3(1.0f)));
    scene.materials[0].transfer = {{0.0f, 0.0f}, {0.4f, 0.0f}, {0.45f, 1.0f}};
    scene.materials[0].particleColor = points({{0.5f, 1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f, 1.0f}});
    for (Backend backend : {Backend::Cpu, Backend::Gpu}) {
        INFO(backendName(backend));
        const glm::vec3 l = eikon::test::firstPixel(scene, backend);
        CHECK(l.r == Approx(0.5).epsilon(3e-3));
        CHECK(l.g == 0.0f);
        CHECK(l.b == Approx(0.5).epsilon(3e-3));
    }
}

TEST_CASE("A particle colour that needs a fifth field slot is a one-line error",
          "[particle_color]") {
    // Four tissue classes of one field fill the render volume's four slots; the last one's colour
    // would need the field itself in a fifth.
    Scene scene = darkProbe();
    scene.path = "four_classes.json";
    scene.sources.push_back(boxSource("density", glm::vec3(-0.5f), glm::vec3(0.5f), 1.0f));
    for (int k = 0; k < 4; ++k) {
        scene.materials.push_back(
            material("class" + std::to_string(k), "density", glm::vec3(1.0f)));
        const float lo = 0.2f * float(k);
        scene.materials.back().transfer = {{0.0f, 0.0f}, {lo + 0.1f, 0.0f}, {lo + 0.2f, 1.0f}};
    }
    scene.materials[3].particleColor.map = "inferno";
    CHECK_THROWS_WITH(FrameRenderer(scene, Backend::Cpu).render(0),
                      Contains("four_classes.json:/materials/3/particle_color") &&
                          Contains("the 4 field slots of the render volume are taken"));
    scene.materials[3].particleColor = {};  // without it, four slots suffice
    CHECK_NOTHROW(FrameRenderer(scene, Backend::Cpu).render(0));
}

TEST_CASE("Particle colours on the GPU equal the CPU twin", "[particle_color][gpu]") {
    // The lit fog ball, glowing by magma's colours in a second material read through a transfer
    // function: both tables, both kinds of colour slot, every sample.
    Scene scene = litFogBall(24, 16);
    scene.materials.push_back(
        material("glow", "density", glm::vec3(0.0f), glm::vec3(0.0f), 0.0f, glm::vec3(0.5f)));
    scene.materials[1].transfer = {{0.0f, 0.0f}, {0.5f, 0.0f}, {0.8f, 1.0f}};
    scene.materials[1].particleColor.map = "magma";
    const Image cpu = FrameRenderer(scene, Backend::Cpu).render(0);
    const Image gpu = FrameRenderer(scene, Backend::Gpu).render(0);
    REQUIRE(cpu.pixels.size() == gpu.pixels.size());
    float largest = 0.0f, worst = 0.0f;
    for (size_t i = 0; i < cpu.pixels.size(); ++i)
        for (int ch = 0; ch < 4; ++ch) {
            largest = std::max(largest, std::abs(cpu.pixels[i][ch]));
            worst = std::max(worst, std::abs(cpu.pixels[i][ch] - gpu.pixels[i][ch]));
        }
    INFO("largest value " << largest << ", largest difference " << worst);
    CHECK(largest > 0.05f);
    // The same float operations in both; llvmpipe's exp and fused multiply-adds differ from the
    // CPU's in the last bits.
    CHECK(worst <= 1e-5f * largest);
}

TEST_CASE("A new colour map or phase function reruns the view, not the light transport",
          "[particle_color]") {
    Scene scene = litFogBall(12, 8);
    FrameRenderer renderer(scene, Backend::Cpu);
    const Image first = renderer.render(0);
    REQUIRE(renderer.transportRuns("light_volumes") == 1);
    Scene next = renderer.scene();
    next.materials[0].particleColor.map = "viridis";
    next.materials[0].particleColor.range = glm::vec2(0.2f, 0.6f);
    const Image second = renderer.render({0, next});
    CHECK(renderer.transportRuns("light_volumes") == 1);
    size_t differ = 0;
    for (size_t i = 0; i < first.pixels.size(); ++i) differ += first.pixels[i] != second.pixels[i];
    CHECK(differ > first.pixels.size() / 4);  // the fog changed colour
    next.materials[0].g = 0.5f;               // the phase function, which only the view applies
    renderer.render({0, next});
    CHECK(renderer.transportRuns("light_volumes") == 1);
    next.materials[0].scattering *= 2.0f;  // extinction: the light is traced again
    renderer.render({0, next});
    CHECK(renderer.transportRuns("light_volumes") == 2);
}
