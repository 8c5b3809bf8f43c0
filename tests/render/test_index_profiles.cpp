// Optics of the procedural index profiles, rendered: a field that would make n < 1 stops a render
// with an error naming it. CPU twin and GPU.
#include <catch2/catch.hpp>

#include "core/error.h"
#include "core/scene.h"
#include "render/frame_renderer.h"
#include "support/backends.h"
#include "support/scene_builders.h"

using namespace eikon;

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
