// Lighter light transport for previews (FrameRenderer::setPreview, LightTransport::previewPatch):
// a preview whose light must be traced again traces it with the method's lighter settings, and
// is exactly the picture of the scene with those settings; the full run's output stays for the
// refinement, which traces the light as set and is exactly the full render; a camera move traces
// nothing either way. CPU twin: the GPU runs the same code path in FrameRenderer.
#include <catch2/catch.hpp>

#include <string>

#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/image.h"
#include "render/light_transport_registry.h"
#include "support/light_transport_setup.h"
#include "support/scene_builders.h"

using eikon::Backend;
using eikon::FrameInputs;
using eikon::FrameRenderer;
using eikon::Image;
using eikon::Scene;

namespace {

bool sameBits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.pixels == b.pixels;
}

// A fresh renderer's picture of `scene`: what no cache can have touched.
Image freshRender(const Scene& scene) {
    FrameRenderer renderer(scene, Backend::Cpu);
    return renderer.render(0);
}

Scene withPatch(Scene scene, const std::string& patch) {
    eikon::patchLightTransport(scene, patch);
    return scene;
}

}  // namespace

TEST_CASE("a preview traces the light lighter, the refinement as set, a camera move not at all",
          "[light_transport][preview]") {
    struct Case {
        std::string method, setting;
        double value;
        std::string patch;  // the method's preview patch for these settings
    };
    const Case cases[] = {
        {"photons", "per_side", 32, R"({"photons": {"per_side": 16}})"},
        {"wavefront", "split_voxels", 2.5, R"({"wavefront": {"split_voxels": 5}})"},
    };
    for (const Case& c : cases) {
        INFO(c.method);
        Scene scene = eikon::test::glassSphereInFog();
        eikon::test::setVolume(scene, glm::vec3(-1.0f), glm::vec3(1.0f), glm::ivec3(20));
        scene.render.width = 20;
        scene.render.height = 15;
        eikon::test::setTransportMethod(scene, c.method);
        eikon::test::setTransportSetting(scene, c.method, c.setting, c.value);
        if (c.method == "wavefront")  // 16² patches, not 64²: 0.4 s a run here
            eikon::test::setTransportSetting(scene, c.method, "per_side", 16);
        FrameRenderer renderer(scene, Backend::Cpu);
        renderer.render(0);
        REQUIRE(renderer.transportRuns(c.method) == 1);
        CHECK(renderer.lightTransport().previewPatch() == c.patch);

        // The light turns: the preview traces it with the lighter settings, and is that scene's
        // picture bit for bit; the method's own output is not touched.
        Scene turned = scene;
        turned.lights[0].direction = glm::vec3(-0.2f, -1.0f, 0.1f);
        renderer.setPreview(true);
        const Image preview = renderer.render(FrameInputs(0, turned));
        CHECK(renderer.transportRuns(c.method) == 1);
        CHECK(renderer.previewTransportRuns() == 1);
        CHECK(sameBits(preview, freshRender(withPatch(turned, c.patch))));
        CHECK_FALSE(sameBits(preview, freshRender(turned)));  // it is lighter, not the same

        // The camera moves while the light stays turned: the preview's light is reused.
        Scene orbited = turned;
        orbited.camera.position = glm::vec3(0.5f, 0.4f, 3.9f);
        const Image orbitPreview = renderer.render(FrameInputs(0, orbited));
        CHECK(renderer.previewTransportRuns() == 1);
        CHECK(sameBits(orbitPreview, freshRender(withPatch(orbited, c.patch))));

        // The refinement traces the light as set: the full render, bit for bit.
        renderer.setPreview(false);
        const Image refined = renderer.render(FrameInputs(0, orbited));
        CHECK(renderer.transportRuns(c.method) == 2);
        CHECK(sameBits(refined, freshRender(orbited)));

        // A camera move after that is a preview that traces nothing: the full light stays.
        Scene back = orbited;
        back.camera = scene.camera;
        renderer.setPreview(true);
        const Image moved = renderer.render(FrameInputs(0, back));
        CHECK(renderer.transportRuns(c.method) == 2);
        CHECK(renderer.previewTransportRuns() == 1);
        CHECK(sameBits(moved, freshRender(back)));
    }
}

TEST_CASE("a method with nothing lighter previews as set", "[light_transport][preview]") {
    SECTION("light volumes") {
        Scene scene = eikon::test::glassSphereInFog();
        eikon::test::setTransportMethod(scene, "light_volumes");
        FrameRenderer renderer(scene, Backend::Cpu);
        renderer.render(0);
        CHECK(renderer.lightTransport().previewPatch().empty());
        Scene turned = scene;
        turned.lights[0].intensity = 5.0f;
        renderer.setPreview(true);
        const Image preview = renderer.render(FrameInputs(0, turned));
        CHECK(renderer.transportRuns("light_volumes") == 2);
        CHECK(renderer.previewTransportRuns() == 0);
        CHECK(sameBits(preview, freshRender(turned)));
    }
    SECTION("photons at 16 per side or fewer: no fewer for a preview") {
        Scene scene = eikon::test::glassSphereInFog();
        eikon::test::setTransportMethod(scene, "photons");
        eikon::test::setPhotonSetting(scene, "per_side", 16);
        CHECK(eikon::makeLightTransport(scene, {})->previewPatch().empty());
        eikon::test::setPhotonSetting(scene, "per_side", 20);
        CHECK(eikon::makeLightTransport(scene, {})->previewPatch() ==
              R"({"photons": {"per_side": 16}})");
    }
}
