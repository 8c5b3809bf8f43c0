// Scene meshes through the pipeline (render/mesh_fields.h): the scene's "meshes" become two
// fields each, voxelized only when the mesh, its placement or the volume change; overlaps are
// resolved by the stated rule; the GPU backend renders what the CPU twin renders.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/mesh_primitives.h"
#include "core/resample.h"
#include "render/frame_renderer.h"
#include "render/mesh_fields.h"

using namespace eikon;

namespace {

const char* const kBallScene = R"({
    "meshes": [{"name": "ball", "shape": {"type": "icosphere", "radius": 0.5, "subdivisions": 3},
                "ior": 1.5, "absorption": [0.5, 1.0, 2.0], "scattering": [0.3, 0.3, 0.3]}],
    "lights": [{"type": "directional", "direction": [0.3, -1, 0.2], "intensity": 2}],
    "environment": {"type": "gradient", "zenith": [0.2, 0.3, 0.6], "horizon": [0.9, 0.9, 0.8],
                    "ground": [0.3, 0.25, 0.2]},
    "volume": {"resolution": 32},
    "render": {"width": 40, "height": 30, "light_transport": {"method": "light_volumes"}}
})";

}  // namespace

TEST_CASE("a mesh-only scene frames its mesh with room for the index blur", "[meshes]") {
    const Scene scene = parseScene(kBallScene, "ball.json");
    FieldRegistry fields;
    MeshFields meshes(scene);
    const RenderVolume v = chooseRenderVolume(scene, fields, meshes.worldBounds(scene));
    // Blur radius 4 + 2 voxels each side of 32: 1.0 / (1 − 12/32) = 1.6 across.
    CHECK(v.bounds.size().x == Approx(1.6).epsilon(1e-5));
    CHECK(v.bounds.center().y == Approx(0.0).margin(1e-6));
    CHECK(v.resolution == glm::ivec3(32));

    Scene automatic = scene;
    automatic.volume.autoResolution = true;
    const RenderVolume a = chooseRenderVolume(automatic, fields, meshes.worldBounds(automatic));
    CHECK(a.resolution == glm::ivec3(kMeshVoxelsAcross));
    CHECK(a.voxelSize().x * float(kMeshVoxelsAcross - 12) == Approx(1.0).epsilon(1e-5));
}

TEST_CASE("a later mesh displaces an earlier one where they overlap", "[meshes]") {
    const Scene scene = parseScene(R"({
        "meshes": [
            {"name": "first", "shape": {"type": "box", "min": [-0.5, -0.5, -0.5], "max": [0.25, 0.5, 0.5]}, "ior": 1.5},
            {"name": "second", "shape": {"type": "box", "min": [-0.25, -0.5, -0.5], "max": [0.5, 0.5, 0.5]}, "ior": 1.33, "absorption": [1, 1, 1]}],
        "volume": {"bounds": {"min": [-1.5, -1.5, -1.5], "max": [1.5, 1.5, 1.5]}, "resolution": 24}
    })",
                                   "overlap.json");
    REQUIRE(scene.materials.size() == 3);  // first.n, second, second.n
    CHECK(scene.materials[0].field == "mesh:first:n");
    CHECK(scene.materials[1].field == "mesh:second");
    CHECK(scene.materials[1].ior == 1.0f);
    CHECK(scene.materials[2].ior == 1.33f);
    MeshFields meshes(scene);
    FieldRegistry fields;
    const RenderVolume volume = chooseRenderVolume(scene, fields, meshes.worldBounds(scene));
    std::map<std::string, DenseGrid> dense;
    meshes.update(scene, volume, nullptr, dense);
    const DenseGrid& first = dense.at("mesh:first");
    const DenseGrid& second = dense.at("mesh:second");
    double worstSum = 0.0;
    for (size_t v = 0; v < first.values.size(); ++v)
        worstSum = std::max(worstSum, double(first.values[v]) + double(second.values[v]));
    CHECK(worstSum == 1.0);
    // x = 0 lies in both boxes: the second has it.
    const glm::ivec3 mid(12, 12, 12);  // voxel centre (0.0625, 0.0625, 0.0625)
    CHECK(first.at(mid.x, mid.y, mid.z) == 0.0f);
    CHECK(second.at(mid.x, mid.y, mid.z) == 1.0f);
    CHECK(first.at(9, 12, 12) == 1.0f);  // x = −0.3125: only the first
    // The index field is the coverage blurred: the same total where the blur stays clear of the
    // volume's faces (8 voxels of room for a radius of 4).
    double sharp = 0.0, blurred = 0.0;
    for (size_t v = 0; v < first.values.size(); ++v) {
        sharp += first.values[v];
        blurred += dense.at("mesh:first:n").values[v];
    }
    CHECK(blurred == Approx(sharp).epsilon(1e-5));
    CHECK(meshes.voxelizations() == 2);
    meshes.update(scene, volume, nullptr, dense);
    CHECK(meshes.voxelizations() == 2);  // nothing changed
}

TEST_CASE("meshes are voxelized again only when they move", "[meshes]") {
    FrameRenderer renderer(parseScene(kBallScene, "ball.json"), Backend::Cpu);
    renderer.render(0);
    CHECK(renderer.voxelizations() == 1);
    Scene next = renderer.scene();  // the next frames' scene, as the test changes it
    next.camera.automatic = false;
    next.camera.position = glm::vec3(1.5f, 0.5f, 2.0f);
    renderer.render({0, next});
    CHECK(renderer.voxelizations() == 1);  // a camera move
    next.lights[0].intensity = 3.0f;
    renderer.render({0, next});
    CHECK(renderer.voxelizations() == 1);  // a light change
    next.meshes[0].translation = glm::vec3(0.05f, 0.0f, 0.0f);
    renderer.render({0, next});
    CHECK(renderer.voxelizations() == 2);  // the mesh moved (and the volume with it)
    FrameInputs newTriangles{0, next};
    newTriangles.meshes.emplace_back(0, icosphere(glm::vec3(0.0f), 0.45f, 2));
    renderer.render(newTriangles);
    CHECK(renderer.voxelizations() == 3);  // new triangles
    renderer.render({0, next});            // given no mesh: the renderer keeps the last
    CHECK(renderer.voxelizations() == 3);
}

TEST_CASE("a mesh from a file that nobody loaded is an error naming it", "[meshes]") {
    const Scene scene = parseScene(R"({
        "meshes": [{"name": "glass", "file": "glass.obj", "ior": 1.5}]
    })",
                                   "/scenes/wine.json");
    FrameRenderer renderer(scene, Backend::Cpu);
    CHECK_THROWS_WITH(renderer.render(0), Catch::Contains("/scenes/wine.json:/meshes/0/file") &&
                                              Catch::Contains("mesh 'glass'") &&
                                              Catch::Contains("was not loaded"));
    TriangleMesh bad = boxMesh(glm::vec3(0.0f), glm::vec3(1.0f));
    bad.positions[2].x = INFINITY;
    FrameInputs badMesh{0, scene};
    badMesh.meshes.emplace_back(0, bad);
    CHECK_THROWS_WITH(renderer.render(badMesh),
                      Catch::Contains("/meshes/0") && Catch::Contains("vertex 2 is not finite"));
    FrameInputs noSuchMesh{0, scene};
    noSuchMesh.meshes.emplace_back(3, boxMesh(glm::vec3(0.0f), glm::vec3(1.0f)));
    CHECK_THROWS_WITH(renderer.render(noSuchMesh), Catch::Contains("mesh 3 does not exist"));
}

TEST_CASE("a mesh scene renders the same on the GPU as on the CPU twin", "[meshes][gpu]") {
    const Scene scene = parseScene(kBallScene, "ball.json");
    FrameRenderer cpu(scene, Backend::Cpu);
    FrameRenderer gpu(scene, Backend::Gpu);
    const Image a = cpu.render(0);
    const Image b = gpu.render(0);
    REQUIRE(a.pixels.size() == b.pixels.size());
    double worst = 0.0, brightest = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            worst = std::max(worst, double(std::abs(a.pixels[i][c] - b.pixels[i][c])));
            brightest = std::max(brightest, double(a.pixels[i][c]));
        }
    INFO("max |GPU - CPU| " << worst << " of " << brightest);
    CHECK(worst < 1e-4 * brightest);
    CHECK(gpu.voxelizations() == 1);
}

TEST_CASE("a water mesh frames the volume on its room and waits to be stepped", "[meshes]") {
    const Scene scene = parseScene(R"({
        "meshes": [{"name": "pool", "shape": {"type": "water", "size": [2, 1], "depth": 0.3,
                    "droplets": [{"time": 0.5, "position": [0.2, 0.1], "depth": 0.05},
                                 {"time": 0.7, "position": [-0.2, 0.1], "depth": -0.02}]},
                    "ior": 1.33}],
        "volume": {"resolution": 16}
    })",
                                   "/s/pool.json");
    MeshFields meshes(scene);
    const std::vector<Bounds3> bounds = meshes.worldBounds(scene);
    CHECK(bounds[0].min == glm::vec3(-1.0f, 0.0f, -0.5f));
    CHECK(bounds[0].max.y == Approx(0.37f));  // depth + the droplets' 0.05 + 0.02 of headroom
    FrameRenderer renderer(scene, Backend::Cpu);
    CHECK_THROWS_WITH(renderer.render(0), Catch::Contains("/s/pool.json:/meshes/0/shape") &&
                                              Catch::Contains("never stepped"));
}

TEST_CASE("a liquid is placed by its container and waits to be made", "[meshes]") {
    Scene scene = parseScene(R"({
        "meshes": [{"name": "cup", "shape": {"type": "box", "min": [-1, 0, -1], "max": [1, 2, 1]},
                    "translate": [3, 0, 0], "scale": 0.5, "ior": 1.5},
                   {"name": "tea", "shape": {"type": "liquid", "container": "cup", "fill": 0.5},
                    "absorption": [1, 1, 1]}],
        "volume": {"resolution": 16}
    })",
                             "/s/tea.json");
    MeshFields meshes(scene);
    CHECK_THROWS_WITH(meshes.worldBounds(scene), Catch::Contains("/s/tea.json:/meshes/1/shape") &&
                                                     Catch::Contains("never made"));
    // The liquid's object-space mesh (what sim/container_fill.h makes) goes where the cup goes.
    meshes.setMesh(scene, 1, boxMesh(glm::vec3(-0.5f, 0.2f, -0.5f), glm::vec3(0.5f, 1.0f, 0.5f)));
    Bounds3 tea = meshes.worldBounds(scene)[1];
    CHECK(tea.min == glm::vec3(2.75f, 0.1f, -0.25f));
    CHECK(tea.max == glm::vec3(3.25f, 0.5f, 0.25f));
    scene.meshes[0].translation = glm::vec3(0.0f, 1.0f, 0.0f);  // as a track would move the cup
    tea = meshes.worldBounds(scene)[1];
    CHECK(tea.min == glm::vec3(-0.25f, 1.1f, -0.25f));
}
