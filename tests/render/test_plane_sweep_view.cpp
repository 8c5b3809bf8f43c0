// The plane sweep's interleaved view (render/transport/plane_sweep/plane_sweep_view.h): the view
// rays advance with the light planes and read only the last few slices swept, so no fluence volume
// is kept. Where the planes are the same as the volume path's (the light and the camera along one
// axis) and no view ray turns back against the sweep, the frame is the volume path's, bit for
// bit: with straight rays, with rays bent by a smooth lens, after a light move, on any thread
// count. What it holds grows with a plane and the image, not with the volume. Rays that turn
// back are counted; what it cannot do is refused in one line.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <tbb/global_control.h>

#include "core/error.h"
#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/image.h"
#include "render/light_transport_registry.h"
#include "render/transport/plane_sweep/plane_sweep_transport.h"
#include "support/light_transport_setup.h"
#include "support/scene_builders.h"
#include "support/test_paths.h"

using namespace eikon;

namespace {

// A fog box with a refracting sphere (glassSphereInFog), lit along −z from the camera's side
// (the camera at z = 4 looks along −z too): the light's planes and the view's are the same.
// The sphere's index is graded (no sharp surface: the volume path would trace its reflections
// back toward the camera, which the sweep cannot) and low enough that no view ray turns back.
Scene lensInFog(int resolution, bool refracting = true) {
    Scene scene = test::glassSphereInFog();
    scene.lights[0].direction = glm::normalize(glm::vec3(0.15f, -0.3f, -1.0f));
    scene.materials[1].ior = 1.2f;
    scene.materials[1].fresnel = false;
    if (!refracting) scene.materials.pop_back();
    test::setVolume(scene, glm::vec3(-1.0f), glm::vec3(1.0f), glm::ivec3(resolution));
    scene.render.width = 40;
    scene.render.height = 30;
    test::setTransportMethod(scene, "plane_sweep");
    return scene;
}

Scene interleaved(Scene scene) {
    patchLightTransport(scene, R"({"plane_sweep": {"view": "interleaved"}})");
    return scene;
}

Image render(const Scene& scene) {
    FrameRenderer renderer(scene, Backend::Cpu);
    return renderer.render(0);
}

bool sameBits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.pixels == b.pixels;
}

const PlaneSweepTransport& sweepOf(const FrameRenderer& renderer) {
    return dynamic_cast<const PlaneSweepTransport&>(renderer.lightTransport());
}

}  // namespace

TEST_CASE("interleaved view: straight rays give the volume path's frame, bit for bit",
          "[plane_sweep][interleaved]") {
    const Scene scene = lensInFog(20, false);
    FrameRenderer renderer(interleaved(scene), Backend::Cpu);
    const Image image = renderer.render(0);
    CHECK(sameBits(image, render(scene)));
    const TransportStats stats = renderer.lastTransportStats();
    CHECK(stats.viewSteps > 0);
    CHECK(stats.viewSamplesBehind == 0);
    CHECK(stats.steps == int64_t(20) * 20 * 20);  // one texel step a plane, no planes between
}

TEST_CASE("interleaved view: rays bent by a lens, and a light move, give the volume path's frames",
          "[plane_sweep][interleaved]") {
    Scene scene = lensInFog(24);
    FrameRenderer renderer(interleaved(scene), Backend::Cpu);
    CHECK(sameBits(renderer.render(0), render(scene)));
    CHECK(renderer.lastTransportStats().viewSamplesBehind == 0);
    CHECK(renderer.transportRuns("plane_sweep") == 1);

    // The light moves: the next frame sweeps it again, as a camera move would.
    scene.lights[0].direction = glm::normalize(glm::vec3(-0.2f, -0.4f, -1.0f));
    const Scene moved = interleaved(scene);
    CHECK(sameBits(renderer.render(FrameInputs(0, moved)), render(scene)));
    CHECK(renderer.transportRuns("plane_sweep") == 2);
}

TEST_CASE("interleaved view: a CT scan lit from the camera's side gives the volume path's frame",
          "[plane_sweep][interleaved]") {
    // data/scenes/ct_tooth.json (the shared tooth scan, a refracting tissue class) with its light
    // turned to the camera's side, which looks along +y: the sweeps cross the same y planes.
    Scene scene = loadScene(test::sourcePath("data/scenes/ct_tooth.json"));
    scene.lights[0].direction = glm::normalize(glm::vec3(-0.5f, 0.77f, -0.4f));
    scene.render.width = 40;
    scene.render.height = 50;
    test::setTransportMethod(scene, "plane_sweep");
    FrameRenderer renderer(interleaved(scene), Backend::Cpu);
    CHECK(sameBits(renderer.render(0), render(scene)));
    CHECK(renderer.lastTransportStats().viewSamplesBehind == 0);
}

TEST_CASE("interleaved view: a wall behind the fog, plane or voxel receiver, as the volume path",
          "[plane_sweep][interleaved]") {
    // A receiver across z behind the lens, facing the camera and the light: the rays that meet it
    // keep the hit until its light is complete (a plane receiver's map after the last plane, a
    // voxel receiver's slices in front of it), then add what the view pass adds at the hit.
    for (const ReceiverMethod method : {ReceiverMethod::Plane, ReceiverMethod::Voxels})
        for (const bool refracting : {true, false}) {
            CAPTURE(int(method), refracting);
            Scene scene = lensInFog(20, refracting);
            ReceiverSpec wall;
            wall.axis = 2;
            wall.position = -0.7f;
            wall.facing = 1;
            wall.albedo = glm::vec3(0.7f, 0.6f, 0.5f);
            wall.method = method;
            scene.receivers.push_back(wall);
            FrameRenderer renderer(interleaved(scene), Backend::Cpu);
            const Image image = renderer.render(0);
            CHECK(sameBits(image, render(scene)));
            CHECK(renderer.lastTransportStats().viewSamplesBehind == 0);
            // The wall shows: the middle of the picture is brighter than without it.
            scene.receivers.clear();
            const Image bare = render(interleaved(scene));
            CHECK(image.at(20, 15).x > bare.at(20, 15).x + 0.01f);
        }
}

TEST_CASE("interleaved view: a dispersing lens gives the volume path's frame, bit for bit",
          "[plane_sweep][interleaved]") {
    // The lens of a dense flint's spread (abbe 20): each light is swept once a channel, each
    // channel's light and view rays bending with its own n, as the volume path does.
    Scene scene = lensInFog(24);
    scene.materials[1].abbe = 20.0f;
    FrameRenderer renderer(interleaved(scene), Backend::Cpu);
    const Image image = renderer.render(0);
    CHECK(sameBits(image, render(scene)));
    CHECK(renderer.lastTransportStats().viewSamplesBehind == 0);
    // Three sweeps of each plane's texels, and a picture the spread changes.
    scene.materials[1].abbe = 0.0f;
    FrameRenderer plain(interleaved(scene), Backend::Cpu);
    const Image unspread = plain.render(0);
    CHECK(renderer.lastTransportStats().steps == 3 * plain.lastTransportStats().steps);
    CHECK_FALSE(sameBits(image, unspread));
}

TEST_CASE("interleaved view: the same bytes on one thread as on all",
          "[plane_sweep][interleaved]") {
    const Scene scene = interleaved(lensInFog(20));
    const Image all = render(scene);
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    CHECK(sameBits(render(scene), all));
}

TEST_CASE(
    "interleaved view: no fluence volume, its planes grow with a slice, its rays with the "
    "image",
    "[plane_sweep][interleaved]") {
    const auto memoryAt = [](int resolution, bool interleave) {
        const Scene scene = lensInFog(resolution);
        FrameRenderer renderer(interleave ? interleaved(scene) : scene, Backend::Cpu);
        renderer.render(0);
        return sweepOf(renderer).memory();
    };
    const PlaneSweepMemory volume16 = memoryAt(16, false), volume32 = memoryAt(32, false);
    const PlaneSweepMemory view16 = memoryAt(16, true), view32 = memoryAt(32, true);
    CHECK(volume32.outputBytes == 8 * volume16.outputBytes);  // the volume path's, ∝ voxels
    CHECK(view16.outputBytes == 0);
    CHECK(view32.outputBytes == 0);
    // A few slices of fluence and direction (16 B a texel each) and one state a pixel: from 16³
    // to 32³ the slices take 4× and the rays the same.
    const size_t slices16 = (view32.viewBytes - view16.viewBytes) / 3;
    const size_t slice16 = 2 * 16 * 16 * sizeof(glm::vec4);
    CHECK(slices16 % slice16 == 0);
    CHECK(slices16 / slice16 >= 2);
    CHECK(slices16 / slice16 <= 8);
    CHECK((view16.viewBytes - slices16) % (40 * 30) == 0);  // the rays: one state a pixel
    CHECK(view32.bufferBytes == 4 * view16.bufferBytes);    // a light's buffers: planes
    // At 32³ the rays and planes together take less than the volume path's volumes.
    CHECK(view32.viewBytes < volume32.outputBytes);
}

TEST_CASE("interleaved view: view rays that turn back through a sharp ball are counted",
          "[plane_sweep][interleaved]") {
    // A sharp ball of n = 1.5 turns the rays that graze it by up to 96 degrees: they travel back
    // against the sweep and read the nearest light plane still held.
    Scene scene = lensInFog(24);
    scene.materials[1].ior = 1.5f;
    scene.sources[1].falloff = 0.02f;
    FrameRenderer renderer(interleaved(scene), Backend::Cpu);
    const Image image = renderer.render(0);
    CHECK(renderer.lastTransportStats().viewSamplesBehind > 0);
    for (const glm::vec4& pixel : image.pixels)
        REQUIRE((std::isfinite(pixel.x) && std::isfinite(pixel.y) && std::isfinite(pixel.z)));
}

TEST_CASE("interleaved view: what it cannot do is refused in one line at its setting",
          "[plane_sweep][interleaved]") {
    const auto refusal = [](const Scene& scene) {
        try {
            render(scene);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    SECTION("a light from another side than the camera's") {
        Scene scene = lensInFog(16);
        // The camera looks along −x: the light, along −z mostly, crosses x planes backward.
        scene.camera = test::cameraAt(glm::vec3(4.0f, 0.0f, 0.5f), glm::vec3(0.0f));
        const std::string message = refusal(interleaved(scene));
        CHECK_THAT(message, Catch::Contains("/plane_sweep/view"));
        CHECK_THAT(message, Catch::Contains("light 0"));
        // Light along the planes.
        scene.lights[0].direction = glm::normalize(glm::vec3(-1.0f, -0.3f, 0.0f));
        scene.camera = test::cameraAt(glm::vec3(0.0f, 0.0f, 4.0f), glm::vec3(0.0f, 0.0f, 0.8f));
        CHECK_THAT(refusal(interleaved(scene)), Catch::Contains("light 0"));
    }
    SECTION("a camera inside the slab of planes") {
        Scene scene = lensInFog(16);
        scene.camera = test::cameraAt(glm::vec3(0.3f, 0.2f, 0.5f), glm::vec3(0.3f, 0.2f, -1.0f));
        CHECK_THAT(refusal(interleaved(scene)), Catch::Contains("camera outside"));
    }
}

TEST_CASE("interleaved view: the GPU equals the CPU twin, reruns are byte-identical",
          "[plane_sweep][interleaved][gpu]") {
    // The lens in fog with curved rays, a sharp ball whose grazing rays turn back against the
    // sweep, the lens dispersing (three rays a pixel), and a receiver wall behind the fog with
    // straight rays: the sweeps in lockstep on the GPU, the rays in buffers between dispatches.
    Scene curved = interleaved(lensInFog(20));
    Scene sharp = lensInFog(20);
    sharp.materials[1].ior = 1.5f;
    sharp.sources[1].falloff = 0.02f;
    sharp = interleaved(sharp);
    Scene dispersing = lensInFog(20);
    dispersing.materials[1].abbe = 20.0f;
    dispersing = interleaved(dispersing);
    Scene straight = lensInFog(20, false);
    ReceiverSpec wall;
    wall.axis = 2;
    wall.position = -0.7f;
    wall.albedo = glm::vec3(0.7f, 0.6f, 0.5f);
    straight.receivers.push_back(wall);
    straight = interleaved(straight);
    for (const Scene* scene : {&curved, &sharp, &dispersing, &straight}) {
        FrameRenderer cpu(*scene, Backend::Cpu);
        const Image twin = cpu.render(0);
        FrameRenderer gpu(*scene, Backend::Gpu);
        const Image first = gpu.render(0);
        const ImageDifference d = compareImages(first, twin);
        INFO("max |GPU - CPU| " << d.maxAbs << " of " << d.referenceMax);
        CHECK(d.referenceMax > 0.01);
        CHECK(d.maxAbs < 1e-5 * d.referenceMax);
        const TransportStats stats = gpu.lastTransportStats();
        CHECK(stats.steps == cpu.lastTransportStats().steps);
        CHECK(std::abs(
                  double(stats.viewSamplesBehind - cpu.lastTransportStats().viewSamplesBehind)) <=
              1e-2 * double(cpu.lastTransportStats().viewSamplesBehind));
        CHECK(std::abs(double(stats.viewSteps - cpu.lastTransportStats().viewSteps)) <=
              1e-3 * double(cpu.lastTransportStats().viewSteps));
        CHECK(sweepOf(gpu).memory().outputBytes == 0);
        CHECK(sweepOf(gpu).memory().viewBytes > 0);
        // The scene moved on and back: the same bytes.
        CHECK(sameBits(gpu.render(0), first));
    }
}
