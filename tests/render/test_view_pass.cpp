// The viewing pass end to end through FrameRenderer, on the GPU (Mesa llvmpipe headless in CI)
// and on the CPU twin: closed forms (Beer-Lambert through a homogeneous cube, single scattering
// in a slab), shadowing, GPU = CPU twin, byte-identical output, and uploads only of what changed.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/procedural.h"
#include "core/scene.h"
#include "core/vdb_import.h"
#include "render/frame_renderer.h"
#include "render/image.h"
#include "support/backends.h"
#include "support/light_transport_setup.h"
#include "support/scene_builders.h"
#include "support/test_paths.h"

// Names brought in one by one: this file's helpers must not collide with the library's.
using eikon::Backend;
using eikon::CameraSpec;
using eikon::FrameRenderer;
using eikon::Image;
using eikon::LightSpec;
using eikon::LightType;
using eikon::MaterialSpec;
using eikon::Scene;
using eikon::ShadowMode;
using eikon::SourceSpec;
using eikon::SourceType;
using eikon::test::backendName;
using eikon::test::boxSource;
using eikon::test::cameraAt;
using eikon::test::directionalLight;
using eikon::test::material;
using eikon::test::relativeError;
using eikon::test::scratchDir;
using eikon::test::setVolume;
using eikon::test::shadowName;
using eikon::test::sphereSource;

namespace {

// Box [-1, 1]^3 of density 1 on a 0.05 grid, absorbing kappa per unit (grey), in front of a white
// background, seen along −z from the +z axis. Odd image sizes put a pixel centre on the axis.
Scene homogeneousCube(float kappa) {
    Scene s;
    s.sources.push_back(boxSource("density", glm::vec3(-1), glm::vec3(1), 1.0f));
    s.materials.push_back(material("absorber", "density", glm::vec3(kappa)));
    s.environment.color = glm::vec3(1.0f);
    setVolume(s, glm::vec3(-1), glm::vec3(1), glm::ivec3(40));
    s.camera = cameraAt(glm::vec3(0, 0, 6), glm::vec3(0));
    s.render.width = 65;
    s.render.height = 49;
    return s;
}

// A soft scattering, emitting sphere lit by a spot, a point and a directional light: every term
// of the source function and every light type.
Scene litSphere() {
    Scene s;
    s.sources.push_back(sphereSource("density", glm::vec3(0.0f), 0.8f, 1.0f, 0.3f));
    s.materials.push_back(material("smoke", "density", glm::vec3(0.3f, 0.35f, 0.4f),
                                   glm::vec3(2.0f, 1.6f, 1.2f), 0.3f,
                                   glm::vec3(0.3f, 0.15f, 0.05f)));
    LightSpec spot;
    spot.type = LightType::Spot;
    spot.position = glm::vec3(0.5f, 3.0f, 1.0f);
    spot.direction = glm::normalize(glm::vec3(-0.5f, -3.0f, -1.0f));
    spot.intensity = 20.0f;
    spot.color = glm::vec3(1.0f, 0.9f, 0.8f);
    spot.coneAngleDeg = 20.0f;
    spot.coneSoftnessDeg = 6.0f;
    s.lights.push_back(spot);
    LightSpec point;
    point.type = LightType::Point;
    point.position = glm::vec3(2.0f, 0.5f, 1.5f);
    point.intensity = 8.0f;
    point.color = glm::vec3(0.5f, 0.7f, 1.0f);
    s.lights.push_back(point);
    s.lights.push_back(directionalLight(glm::vec3(-0.6f, -0.3f, -0.75f), 1.5f));
    s.environment.color = glm::vec3(0.02f, 0.03f, 0.05f);
    s.camera = cameraAt(glm::vec3(0.3f, 0.4f, 4.0f), glm::vec3(0.0f), 50.0f);
    s.render.width = 64;
    s.render.height = 48;
    return s;
}

Image renderFrame(const Scene& scene, Backend backend) {
    FrameRenderer renderer(scene, backend);
    return renderer.render(0);
}

glm::vec4 centrePixel(const Image& image) {
    return image.at(image.width / 2, image.height / 2);
}

std::vector<char> fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    REQUIRE(in.good());
    return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct TwinDifference {
    double maxAbsRgb = 0;   // largest |a − b| over all pixels and rgb channels
    double maxRgb = 0;      // largest rgb value of b, the scale for the relative figure
    double meanAbsRgb = 0;  // mean |a − b| over all pixels and rgb channels
    double maxAbsAlpha = 0;
    double maxRelative() const { return maxAbsRgb / maxRgb; }
};

TwinDifference measureDifference(const Image& a, const Image& b) {
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    TwinDifference d;
    double sum = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double diff = std::abs(double(a.pixels[i][c]) - double(b.pixels[i][c]));
            d.maxAbsRgb = std::max(d.maxAbsRgb, diff);
            d.maxRgb = std::max(d.maxRgb, double(b.pixels[i][c]));
            sum += diff;
        }
        d.maxAbsAlpha =
            std::max(d.maxAbsAlpha, std::abs(double(a.pixels[i].a) - double(b.pixels[i].a)));
    }
    d.meanAbsRgb = sum / double(3 * a.pixels.size());
    return d;
}

}  // namespace

TEST_CASE("homogeneous cube: the centre pixel is exp(-kappa d) on both backends", "[view]") {
    const double d = 2.0;  // side of the cube, along the view ray
    for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
        for (float kappa : {0.7f, 2.0f}) {
            INFO(backendName(backend) << ", kappa " << kappa);
            const Image image = renderFrame(homogeneousCube(kappa), backend);
            REQUIRE(image.width == 65);
            REQUIRE(image.height == 49);
            const glm::vec4 p = centrePixel(image);
            const double expected = std::exp(-double(kappa) * d);
            INFO("centre pixel " << p.r << " " << p.g << " " << p.b << " alpha " << p.a
                                 << ", expected " << expected);
            // The requirement: within 0.5 %. Measured on llvmpipe: GPU 8e-6 (kappa 0.7)
            // and 1.1e-5 (kappa 2), CPU twin < 1e-6; float rounding of 40 exact steps.
            for (int c = 0; c < 3; ++c) CHECK(relativeError(p[c], expected) < 0.005);
            // Alpha is the ray's mean transmittance, the same number here.
            CHECK(relativeError(p.a, expected) < 0.005);
            // The check can fail: the other kappa's answer is far outside the tolerance.
            const double other = std::exp(-(kappa == 2.0f ? 0.7 : 2.0) * d);
            CHECK(relativeError(p.r, other) > 0.5);
            // Corner pixels miss the cube: the white background, fully transmitted.
            const glm::vec4 corner = image.at(0, 0);
            CHECK(corner.r == Approx(1.0f).margin(1e-6));
            CHECK(corner.a == Approx(1.0f).margin(1e-6));
        }
    }
}

TEST_CASE("GPU image equals the CPU twin's on a lit, scattering, emitting sphere", "[view]") {
    for (ShadowMode mode : {ShadowMode::Volume, ShadowMode::Swept, ShadowMode::Marched}) {
        Scene scene = litSphere();
        eikon::test::setShadows(scene, shadowName(mode));
        const Image gpu = renderFrame(scene, Backend::Gpu);
        const Image cpu = renderFrame(scene, Backend::Cpu);
        const TwinDifference diff = measureDifference(gpu, cpu);
        INFO("shadows " << shadowName(mode) << ": max |GPU - CPU| " << diff.maxAbsRgb
                        << " (relative to the image max " << diff.maxRgb << ": "
                        << diff.maxRelative() << "), mean " << diff.meanAbsRgb << ", alpha max "
                        << diff.maxAbsAlpha);
        // The image must show something for the comparison to mean anything.
        REQUIRE(diff.maxRgb > 0.1);
        // Same shared code, same inputs; only float contraction and transcendental functions
        // differ. Measured on Mesa llvmpipe (both shadow modes): max |GPU - CPU| / image max
        // 1.3e-6, mean |GPU - CPU| 3.1e-8 (1.1e-7 of the max), alpha max 1.0e-6. The bounds
        // below leave a factor ~100.
        CHECK(diff.maxRelative() < 1e-4);
        CHECK(diff.meanAbsRgb < 1e-5 * diff.maxRgb);
        CHECK(diff.maxAbsAlpha < 1e-5);
    }
}

TEST_CASE("rendering twice gives byte-identical PNG and EXR files", "[view]") {
    const std::string dir = scratchDir("view_determinism");
    const Scene scene = litSphere();
    for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
        INFO(backendName(backend));
        const std::string prefix = dir + "/" + (backend == Backend::Gpu ? "gpu" : "cpu");
        FrameRenderer first(scene, backend);
        const Image a = first.render(0);
        const Image again = first.render(0);          // the same renderer, nothing changed
        const Image b = renderFrame(scene, backend);  // a fresh renderer
        CHECK(a.pixels == again.pixels);
        CHECK(a.pixels == b.pixels);
        int n = 0;
        for (const Image* image : {&a, &again, &b}) {
            eikon::writePng(prefix + "_" + std::to_string(n) + ".png", *image, 0.0f);
            eikon::writeExr(prefix + "_" + std::to_string(n) + ".exr", *image);
            ++n;
        }
        for (const char* ext : {".png", ".exr"}) {
            INFO(ext);
            const std::vector<char> reference = fileBytes(prefix + "_0" + ext);
            CHECK(reference.size() > 100);
            CHECK(fileBytes(prefix + "_1" + ext) == reference);
            CHECK(fileBytes(prefix + "_2" + ext) == reference);
        }
    }
}

TEST_CASE("only what changed is resampled and uploaded", "[view]") {
    const std::string dir = scratchDir("view_uploads");
    Scene scene = litSphere();
    scene.render.width = 32;  // each section reruns the case from here: keep it small
    scene.render.height = 24;
    FrameRenderer renderer(scene, Backend::Gpu);
    const Image first = renderer.render(0);
    const int uploads = renderer.uploads();
    const int resamples = renderer.resamples();
    CHECK(uploads == 1);  // one field, one slot
    CHECK(resamples == 1);

    SECTION("the same frame again: nothing") {
        renderer.render(0);
        CHECK(renderer.uploads() == uploads);
        CHECK(renderer.resamples() == resamples);
    }
    SECTION("a camera move: no resample, no upload, a different image") {
        Scene next = renderer.scene();  // the next frames' scene, as the test changes it
        next.camera.position = glm::vec3(-1.0f, 0.2f, 3.5f);
        const Image moved = renderer.render({0, next});
        CHECK(renderer.uploads() == uploads);
        CHECK(renderer.resamples() == resamples);
        CHECK(moved.pixels != first.pixels);
    }
    SECTION("a material's absorption (a uniform): no resample, no upload") {
        Scene next = renderer.scene();  // the next frames' scene, as the test changes it
        next.materials[0].absorption = glm::vec3(3.0f);
        const Image darker = renderer.render({0, next});
        CHECK(renderer.uploads() == uploads);
        CHECK(renderer.resamples() == resamples);
        CHECK(darker.pixels != first.pixels);
    }
    SECTION("a light change: no resample, no upload") {
        Scene next = renderer.scene();  // the next frames' scene, as the test changes it
        next.lights[1].intensity = 30.0f;
        next.lights[2].direction = glm::normalize(glm::vec3(0.6f, -0.3f, -0.75f));
        const Image relit = renderer.render({0, next});
        CHECK(renderer.uploads() == uploads);
        CHECK(renderer.resamples() == resamples);
        CHECK(relit.pixels != first.pixels);
    }
    SECTION("a new render volume: one resample, one upload") {
        Scene next = renderer.scene();  // the next frames' scene, as the test changes it
        Scene& s = next;
        setVolume(s, glm::vec3(-1.2f), glm::vec3(1.2f), glm::ivec3(32));
        renderer.render({0, next});
        CHECK(renderer.uploads() == uploads + 1);
        CHECK(renderer.resamples() == resamples + 1);
        renderer.render({0, next});  // and then nothing again
        CHECK(renderer.uploads() == uploads + 1);
        CHECK(renderer.resamples() == resamples + 1);
    }
    SECTION("the field replaced (a new source file): one resample, one upload") {
        eikon::ensureOpenVdbInitialized();
        openvdb::FloatGrid::Ptr grid =
            eikon::makeSphereField(glm::vec3(0.2f, 0.0f, 0.0f), 0.5f, 2.0f, 0.2f, 0.05f);
        grid->setName("density");
        const std::string file = dir + "/replacement.vdb";
        openvdb::io::File(file).write({grid});
        SourceSpec vdb;
        vdb.type = SourceType::Vdb;
        vdb.file = file;
        vdb.jsonPath = "/sources/0";
        Scene next = renderer.scene();  // the next frames' scene, as the test changes it
        next.sources[0] = vdb;
        const Image replaced = renderer.render({0, next});
        CHECK(renderer.uploads() == uploads + 1);
        CHECK(renderer.resamples() == resamples + 1);
        CHECK(replaced.pixels != first.pixels);
    }
}

TEST_CASE("a camera move on the CPU twin resamples nothing", "[view]") {
    FrameRenderer renderer(litSphere(), Backend::Cpu);
    renderer.render(0);
    CHECK(renderer.resamples() == 1);
    CHECK(renderer.uploads() == 0);  // no GPU, nothing to upload
    Scene next = renderer.scene();   // the next frames' scene, as the test changes it
    next.camera.position = glm::vec3(1.0f, 1.0f, 3.0f);
    next.materials[0].scattering = glm::vec3(0.5f);
    renderer.render({0, next});
    CHECK(renderer.resamples() == 1);
}

TEST_CASE("an opaque blocker between the light and a scattering sphere shadows it", "[view]") {
    // A scattering sphere at the origin, lit by a directional light travelling −x. A box of a
    // second field ("flame") between the light and the sphere, beside the view rays, absorbs
    // e^-24 of the light when its material absorbs 40 per unit, nothing when it absorbs 0.
    Scene scene;
    scene.sources.push_back(sphereSource("density", glm::vec3(0.0f), 0.6f, 1.0f, 0.0f));
    scene.sources.push_back(
        boxSource("flame", glm::vec3(0.9f, -1.0f, -1.0f), glm::vec3(1.5f, 1.0f, 1.0f), 1.0f));
    scene.materials.push_back(material("smoke", "density", glm::vec3(0.0f), glm::vec3(2.0f)));
    scene.materials.push_back(material("blocker", "flame", glm::vec3(40.0f)));
    scene.lights.push_back(directionalLight(glm::vec3(-1.0f, 0.0f, 0.0f), 3.0f));
    scene.camera = cameraAt(glm::vec3(0.0f, 0.0f, 4.0f), glm::vec3(0.0f), 40.0f);
    scene.render.width = 33;
    scene.render.height = 25;

    for (ShadowMode mode : {ShadowMode::Volume, ShadowMode::Swept, ShadowMode::Marched}) {
        for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
            INFO(backendName(backend) << ", shadows " << shadowName(mode));
            eikon::test::setShadows(scene, shadowName(mode));
            FrameRenderer renderer(scene, backend);
            const Image blocked = renderer.render(0);
            Scene next = renderer.scene();  // the next frames' scene, as the test changes it
            next.materials[1].absorption = glm::vec3(0.0f);
            const Image open = renderer.render({0, next});
            CHECK(renderer.resamples() == 2);  // two fields, once each
            // Sum a 5x5 block of pixels around the centre, all of them on the sphere.
            double litSum = 0, shadowSum = 0;
            for (int y = 10; y <= 14; ++y)
                for (int x = 14; x <= 18; ++x) {
                    litSum += open.at(x, y).r;
                    shadowSum += blocked.at(x, y).r;
                    CHECK(open.at(x, y).a < 0.5f);  // the ray does cross the sphere
                }
            INFO("sphere radiance lit " << litSum << ", shadowed " << shadowSum);
            CHECK(litSum > 0.5);
            CHECK(shadowSum < 1e-3 * litSum);
            // The view rays to these pixels do not cross the blocker: same transmittance.
            CHECK(blocked.at(16, 12).a == Approx(open.at(16, 12).a).margin(1e-6));
        }
    }
}

TEST_CASE("single scattering in a slab lit from behind matches the closed form", "[view]") {
    // The closed form is in tests/support/scene_builders.h (scatteringSlab).
    const double E = 2.0;
    const glm::vec3 sigma(0.5f, 1.5f, 3.0f);
    Scene scene = eikon::test::scatteringSlab(sigma, float(E));
    for (ShadowMode mode : {ShadowMode::Volume, ShadowMode::Swept, ShadowMode::Marched}) {
        for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
            INFO(backendName(backend) << ", shadows " << shadowName(mode));
            eikon::test::setShadows(scene, shadowName(mode));
            const glm::vec4 p = centrePixel(renderFrame(scene, backend));
            double meanT = 0;
            for (int c = 0; c < 3; ++c) {
                const double s = sigma[c];
                const double expected = eikon::test::slabCentrePixel(s, E);
                INFO("channel " << c << ": sigma " << s << ", got " << p[c] << ", expected "
                                << expected << ", relative error "
                                << relativeError(p[c], expected));
                // Measured, both backends and shadow modes: 2.7e-5, 2.4e-4, 9.4e-4 for sigma
                // 0.5, 1.5, 3: the midpoint rule's 2 sinh(sigma h / 2) / (sigma h) − 1
                // = (sigma h)² / 24 with h = 0.05 (the shadow lookups sit at step midpoints).
                CHECK(relativeError(p[c], expected) < 0.01);
                meanT += std::exp(-s) / 3.0;  // L = 1
            }
            CHECK(relativeError(p.a, meanT) < 0.005);
        }
    }
}
