// Optics of the procedural index profiles, rendered: the shipped scenes that use them render,
// and a field that would make n < 1 stops a render with an error naming it.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/scene.h"
#include "render/frame_renderer.h"
#include "support/backends.h"
#include "support/scene_builders.h"
#include "support/test_paths.h"

using namespace eikon;

TEST_CASE("the index-profile scenes render on the CPU twin", "[profiles][scenes]") {
    for (const char* name : {"luneburg_lens", "mirage_slab", "three_glass_cube",
                             "glass_sphere_floor_spot", "houdini_smoke_glass"}) {
        Scene scene = loadScene(test::sourcePath("data/scenes/" + std::string(name) + ".json"));
        scene.render.width = 40;
        scene.render.height = 30;
        scene.render.photons.perSide = 32;
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
        renderer.scene().materials[0].ior = 1.0f;
        CHECK_NOTHROW(renderer.render(0));
    }
}
