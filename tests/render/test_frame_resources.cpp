// A long live run holds what its first frames made, and no more: frame after frame of new smoke
// fields (what a live simulation hands the renderer, pipeline/scene_driver.h), rendered on the GPU,
// leave as many GL objects alive and as many fields in the renderer as the first frames did.
// Counts, not memory: `eikon bench soak` measures the memory over thousands of frames; these
// counts are exact, so a GL object or a field made per frame and never freed fails here.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <openvdb/openvdb.h>

#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/gl_context.h"
#include "render/gl_objects.h"

using namespace eikon;

namespace {

// A live smoke scene around a glass ball: both light-transport methods, curved rays, the mesh's
// voxelization, the octree and the photons' buffers all run on it.
std::string liveScene(const std::string& method) {
    return R"({
  "volume": {"bounds": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}, "resolution": 16},
  "sources": [{"type": "simulation"}],
  "materials": [{"name": "smoke", "field": "density", "absorption": [0.5, 0.5, 0.5],
                 "scattering": [8, 8, 8], "g": 0.3}],
  "meshes": [{"name": "glass", "shape": {"type": "icosphere", "radius": 0.15, "subdivisions": 1},
              "translate": [0, 0.6, 0], "ior": 1.5}],
  "lights": [{"type": "directional", "direction": [-0.5, -1, -0.3], "intensity": 3}],
  "camera": {"position": [0, 0.5, 2.5], "look_at": [0, 0.5, 0], "up": [0, 1, 0]},
  "render": {"width": 24, "height": 16,
             "light_transport": {"method": ")" +
           method + R"(", "photons": {"per_side": 16}}},
  "time": {"fps": 24, "frame_start": 1, "frame_end": 100},
  "simulation": {"domain": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}, "resolution": 16}
})";
}

// Frame k's smoke: a blob that rises and grows with k, as a live simulation would publish it.
openvdb::FloatGrid::Ptr smokeOfFrame(int k) {
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->setTransform(openvdb::math::Transform::createLinearTransform(1.0 / 16.0));
    const double cy = 2.0 + 0.4 * k;
    const double r = 2.0 + 0.1 * k;
    auto access = grid->getAccessor();
    for (int x = -8; x < 8; ++x)
        for (int y = 0; y < 16; ++y)
            for (int z = -8; z < 8; ++z) {
                const double d = std::sqrt(x * x + (y - cy) * (y - cy) + z * z);
                if (d < r) access.setValue(openvdb::Coord(x, y, z), float(1.0 - d / r));
            }
    return grid;
}

FrameInputs frameInputs(const Scene& scene, int frame) {
    FrameInputs inputs{frame, scene};
    inputs.fields.set("density", smokeOfFrame(frame), "test smoke frame " + std::to_string(frame));
    return inputs;
}

}  // namespace

TEST_CASE("a live run on the GPU makes no GL object or field per frame", "[gpu][soak]") {
    for (const char* method : {"photons", "light_volumes"}) {
        INFO(method);
        const Scene scene = parseScene(liveScene(method), "live.json");
        FrameRenderer renderer(scene, Backend::Gpu);
        // Warm-up: the first frames make the volumes, buffers and query objects the run keeps.
        for (int frame = 1; frame <= 3; ++frame) {
            renderer.render(frameInputs(scene, frame));
            renderer.takeStats();
        }
        const GlObjectCounts warm = countGlObjects();
        const size_t fields = renderer.fields().names().size();
        CHECK(warm.textures > 0);
        CHECK(warm.programs > 0);
        for (int frame = 4; frame <= 20; ++frame) {
            renderer.render(frameInputs(scene, frame));
            renderer.takeStats();
        }
        CHECK(renderer.transportRuns(method) == 20);  // every frame's new smoke reran it
        const GlObjectCounts after = countGlObjects();
        INFO("after the warm-up: " << warm.describe()
                                   << "\nafter 17 more frames: " << after.describe());
        CHECK(after == warm);
        CHECK(renderer.fields().names().size() == fields);
    }
}

TEST_CASE("the GL object count sees objects made and deleted", "[gpu][soak]") {
    std::unique_ptr<GlContext> gl = createHeadlessContext();
    const GlObjectCounts before = countGlObjects();
    Scene scene = parseScene(liveScene("light_volumes"), "live.json");
    {
        FrameRenderer renderer(scene, Backend::Gpu, gl.get());
        renderer.render(frameInputs(scene, 1));
        const GlObjectCounts during = countGlObjects();
        INFO("before: " << before.describe() << "\nduring: " << during.describe());
        CHECK(during.textures > before.textures);
        CHECK(during.buffers > before.buffers);
        CHECK(during.programs > before.programs);
    }
    // The renderer gone, every GL object it made is gone with it.
    const GlObjectCounts after = countGlObjects();
    INFO("before: " << before.describe() << "\nafter: " << after.describe());
    CHECK(after == before);
}

TEST_CASE("a renderer whose stage times nobody takes keeps a bounded number of GL queries",
          "[gpu][soak]") {
    // `eikon render` and `eikon view` take the stage times every frame; a program that does not
    // (a test, a batch loop) must not make a timer query per stage per frame for ever.
    const Scene scene = parseScene(liveScene("light_volumes"), "live.json");
    FrameRenderer renderer(scene, Backend::Gpu);
    for (int frame = 1; frame <= 20; ++frame) renderer.render(frameInputs(scene, frame));
    const GlObjectCounts warm = countGlObjects();
    for (int frame = 21; frame <= 60; ++frame) renderer.render(frameInputs(scene, frame));
    const GlObjectCounts after = countGlObjects();
    INFO("after 20 frames: " << warm.describe() << "\nafter 60: " << after.describe());
    CHECK(after == warm);
    // The times are still summed, over every frame since the last take.
    const std::vector<StageTime> stats = renderer.takeStats();
    REQUIRE(!stats.empty());
    CHECK(stats.front().calls == 60);
}
