// Transfer functions rendered (core/transfer_function.h): Beer–Lambert through a slab read
// through a function, two tissue classes of one field kept apart, a function that doubles the
// field giving the bytes of a material twice as dense, on the CPU twin and the GPU.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/image.h"
#include "support/backends.h"
#include "support/scene_builders.h"

using eikon::Backend;
using eikon::FrameRenderer;
using eikon::Image;
using eikon::Scene;
using eikon::test::backendName;
using eikon::test::boxSource;
using eikon::test::cameraAt;
using eikon::test::material;

namespace {

// Boxes of field "density" seen along −z by one pixel: the environment times exp(−∫κ).
Scene slabScene() {
    return eikon::test::transmittanceProbe();
}

glm::vec3 pixel(const Scene& scene, Backend backend) {
    return eikon::test::firstPixel(scene, backend);
}

}  // namespace

TEST_CASE("A slab read through a transfer function attenuates by the amount it maps to",
          "[transfer]") {
    // Value 0.5 maps to 1.5 on [[0, 0], [0.4, 0], [0.6, 3]]; a unit-thick slab of absorption 1
    // per unit amount passes exp(−1.5).
    Scene scene = slabScene();
    scene.sources.push_back(
        boxSource("density", glm::vec3(-0.5f), glm::vec3(0.5f), 0.5f, 0.0f, 0.125f));
    scene.materials.push_back(material("slab", "density", glm::vec3(1.0f, 0.5f, 0.25f)));
    scene.materials[0].transfer = {{0.0f, 0.0f}, {0.4f, 0.0f}, {0.6f, 3.0f}};
    for (Backend backend : {Backend::Cpu, Backend::Gpu}) {
        INFO(backendName(backend));
        const glm::vec3 t = pixel(scene, backend);
        CHECK(t.r == Approx(std::exp(-1.5)).epsilon(2e-3));
        CHECK(t.g == Approx(std::exp(-0.75)).epsilon(2e-3));
        CHECK(t.b == Approx(std::exp(-0.375)).epsilon(2e-3));
    }
}

TEST_CASE("Two classes of one field, each through its own function, each in its own slot",
          "[transfer]") {
    // Dentin (values 0.45-0.7) absorbs red, enamel (above 0.85) blue. A shell of 0.5 around a
    // core of 1: the ray crosses 0.5 of dentin and 0.5 of enamel.
    Scene scene = slabScene();
    eikon::test::addShellAroundCore(scene);
    scene.materials.push_back(material("dentin", "density", glm::vec3(2.0f, 0.0f, 0.0f)));
    scene.materials[0].transfer = {
        {0.0f, 0.0f}, {0.4f, 0.0f}, {0.45f, 1.0f}, {0.7f, 1.0f}, {0.75f, 0.0f}};
    scene.materials.push_back(material("enamel", "density", glm::vec3(0.0f, 0.0f, 3.0f)));
    scene.materials[1].transfer = {{0.0f, 0.0f}, {0.8f, 0.0f}, {0.85f, 1.0f}};
    for (Backend backend : {Backend::Cpu, Backend::Gpu}) {
        INFO(backendName(backend));
        const glm::vec3 t = pixel(scene, backend);
        CHECK(t.r == Approx(std::exp(-2.0 * 0.5)).epsilon(3e-3));
        CHECK(t.g == 1.0f);
        CHECK(t.b == Approx(std::exp(-3.0 * 0.5)).epsilon(3e-3));
    }
}

TEST_CASE("A function that doubles the field renders a material twice as dense, byte for byte",
          "[transfer]") {
    Scene lit = slabScene();
    lit.render.width = 24;
    lit.render.height = 16;
    lit.camera = cameraAt(glm::vec3(1.5f, 1.0f, 4.0f), glm::vec3(0.0f), 40.0f);
    lit.sources.push_back(
        eikon::test::sphereSource("density", glm::vec3(0.1f), 0.6f, 0.8f, 0.2f, 0.1f));
    lit.lights.push_back(eikon::test::directionalLight(glm::vec3(-1.0f, -2.0f, -0.5f), 3.0f));
    Scene doubled = lit;
    lit.materials.push_back(
        material("fog", "density", glm::vec3(0.6f, 0.8f, 1.0f), glm::vec3(2.0f, 1.5f, 1.0f), 0.3f));
    doubled.materials.push_back(material("fog", "density", glm::vec3(0.3f, 0.4f, 0.5f),
                                         glm::vec3(1.0f, 0.75f, 0.5f), 0.3f));
    doubled.materials[0].transfer = {{0.0f, 0.0f}, {1.0f, 2.0f}};  // 0.8 at most: 2f everywhere
    for (Backend backend : {Backend::Cpu, Backend::Gpu}) {
        INFO(backendName(backend));
        FrameRenderer a(lit, backend), b(doubled, backend);
        const Image ia = a.render(0), ib = b.render(0);
        REQUIRE(ia.pixels.size() == ib.pixels.size());
        size_t differ = 0;
        for (size_t i = 0; i < ia.pixels.size(); ++i) differ += ia.pixels[i] != ib.pixels[i];
        CHECK(differ == 0);
        const glm::vec4 centre = ia.at(ia.width / 2, ia.height / 2);
        INFO(centre.r << " " << centre.g << " " << centre.b << " " << centre.a);
        CHECK(centre.a < 0.5f);  // the fog is in view
    }
}
