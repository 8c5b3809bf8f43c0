// The environment view rays see where they leave the volume (shaders/shared/environment.h):
// the gradient sky's three colours in their directions, the equirectangular image's regions in
// theirs (and turned by rotation_deg), the GPU equal to the CPU twin, a glass sphere inverting the
// image behind it, the image read once per path, and the errors of bad input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/scene.h"
#include "render/environment_map.h"
#include "render/frame_renderer.h"
#include "render/image.h"
#include "render/volume_kernels_cpu.h"
#include "support/fresnel_exact.h"
#include "support/scene_builders.h"
#include "support/test_paths.h"

using Catch::Matchers::Contains;
using eikon::Backend;
using eikon::EnvironmentType;
using eikon::FrameRenderer;
using eikon::Image;
using eikon::Scene;
using eikon::test::boxSource;
using eikon::test::cameraAt;
using eikon::test::material;
using eikon::test::scratchDir;
using eikon::test::setVolume;
using eikon::test::sphereSource;

namespace {

const char* backendName(Backend b) {
    return b == Backend::Gpu ? "GPU" : "CPU twin";
}

const glm::vec3 kZenith(0.1f, 0.3f, 0.9f);
const glm::vec3 kHorizon(0.7f, 0.8f, 0.95f);
const glm::vec3 kGround(0.2f, 0.15f, 0.1f);

// A transparent box (absorption 0) around the origin: rays through it or past it see only the
// environment. One pixel, whose ray is exactly the camera's forward direction.
Scene emptyScene() {
    Scene s;
    s.sources.push_back(boxSource("density", glm::vec3(-0.5f), glm::vec3(0.5f), 1.0f));
    s.materials.push_back(material("clear", "density", glm::vec3(0.0f)));
    setVolume(s, glm::vec3(-1.0f), glm::vec3(1.0f), glm::ivec3(8));
    s.render.width = 1;
    s.render.height = 1;
    return s;
}

// A camera at (0, 0, 5) looking along unit axis `dir`.
eikon::CameraSpec lookAlong(glm::vec3 dir) {
    const glm::vec3 eye(0.0f, 0.0f, 5.0f);
    eikon::CameraSpec c = cameraAt(eye, eye + 10.0f * dir);
    if (dir.y != 0.0f) c.up = glm::vec3(0.0f, 0.0f, -1.0f);  // up must not be parallel to dir
    return c;
}

// The scene the renderer last rendered, seen along `dir`.
glm::vec3 seenAlong(FrameRenderer& renderer, glm::vec3 dir) {
    eikon::FrameInputs inputs{0, renderer.scene()};
    inputs.scene.camera = lookAlong(dir);
    const Image image = renderer.render(inputs);
    return glm::vec3(image.at(0, 0));
}

// The colours of the test image: one per horizontal quarter, centred on −z, +x, +z, −x (u = 0.5,
// 0.75, 0, 0.25), and a row each for straight up and straight down.
const glm::vec3 kMinusZ(1.0f, 0.0f, 0.0f);
const glm::vec3 kPlusX(0.0f, 1.0f, 0.0f);
const glm::vec3 kPlusZ(0.0f, 0.0f, 1.0f);
const glm::vec3 kMinusX(1.0f, 1.0f, 0.0f);
const glm::vec3 kUp(0.5f, 0.5f, 0.5f);
const glm::vec3 kDown(0.0f, 1.0f, 1.0f);

// 16×8 texels: columns 6-9 (u ∈ [0.375, 0.625)) are −z, 10-13 +x, 14-1 +z, 2-5 −x; row 0 is the
// top (up), row 7 the bottom (down).
Image quartersImage() {
    Image image(16, 8);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const int quarter = ((x + 2) / 4) % 4;  // 0: +z, 1: −x, 2: −z, 3: +x
            const glm::vec3 colours[4] = {kPlusZ, kMinusX, kMinusZ, kPlusX};
            glm::vec3 c = colours[quarter];
            if (y == 0) c = kUp;
            if (y == image.height - 1) c = kDown;
            image.at(x, y) = glm::vec4(c, 1.0f);
        }
    }
    return image;
}

void checkNear(glm::vec3 seen, glm::vec3 expected, double margin) {
    INFO("seen " << seen.x << " " << seen.y << " " << seen.z << ", expected " << expected.x << " "
                 << expected.y << " " << expected.z);
    for (int c = 0; c < 3; ++c) CHECK(seen[c] == Approx(expected[c]).margin(margin));
}

// Largest |a − b| over rgb, relative to b's largest value.
double maxRelativeDifference(const Image& a, const Image& b) {
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    double maxAbs = 0.0, maxRef = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            maxAbs = std::max(maxAbs, std::abs(double(a.pixels[i][c]) - double(b.pixels[i][c])));
            maxRef = std::max(maxRef, std::abs(double(b.pixels[i][c])));
        }
    }
    return maxAbs / maxRef;
}

}  // namespace

TEST_CASE("gradient environment: the shared function gives zenith, horizon and ground exactly",
          "[environment]") {
    eikon::shared::GpuViewParams p{};
    p.environment = glm::ivec4(EK_ENVIRONMENT_GRADIENT, 0, 0, 0);
    p.environmentSky = glm::vec4(kZenith, 0.0f);
    p.environmentHorizon = glm::vec4(kHorizon, 0.0f);
    p.environmentGround = glm::vec4(kGround, 0.0f);
    eikon::shared::ViewKernelCpu kernel{{p}};
    CHECK(kernel.environmentRadiance(glm::vec3(0, 1, 0)) == kZenith);
    CHECK(kernel.environmentRadiance(glm::vec3(0, -1, 0)) == kGround);
    CHECK(kernel.environmentRadiance(glm::vec3(1, 0, 0)) == kHorizon);
    CHECK(kernel.environmentRadiance(glm::vec3(0, 0, -1)) == kHorizon);
    // Past the short blend below the horizon it is all ground; half way up, sqrt(0.5) of zenith.
    CHECK(kernel.environmentRadiance(glm::normalize(glm::vec3(1, -0.05f, 0))) == kGround);
    const glm::vec3 halfway = kernel.environmentRadiance(glm::vec3(0.0f, 0.5f, std::sqrt(0.75f)));
    const float t = std::sqrt(0.5f);
    checkNear(halfway, kHorizon * (1.0f - t) + kZenith * t, 1e-6);
}

TEST_CASE("gradient environment: rays up, down and level see zenith, ground and horizon",
          "[environment]") {
    Scene scene = emptyScene();
    scene.environment.type = EnvironmentType::Gradient;
    scene.environment.zenith = kZenith;
    scene.environment.horizon = kHorizon;
    scene.environment.ground = kGround;
    for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
        INFO(backendName(backend));
        FrameRenderer renderer(scene, backend);
        CHECK(seenAlong(renderer, glm::vec3(0, 1, 0)) == kZenith);
        CHECK(seenAlong(renderer, glm::vec3(0, -1, 0)) == kGround);
        CHECK(seenAlong(renderer, glm::vec3(0, 0, 1)) == kHorizon);
        CHECK(seenAlong(renderer, glm::vec3(0, 0, -1)) == kHorizon);  // through the clear box
        CHECK(seenAlong(renderer, glm::vec3(1, 0, 0)) == kHorizon);
    }
}

TEST_CASE("image environment: known directions see their regions, rotation turns them",
          "[environment]") {
    const std::string file = scratchDir("environment_quarters") + "/quarters.exr";
    eikon::writeExr(file, quartersImage());
    Scene scene = emptyScene();
    scene.environment.type = EnvironmentType::Image;
    scene.environment.file = file;
    scene.environment.intensity = 2.0f;
    for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
        INFO(backendName(backend));
        FrameRenderer renderer(scene, backend);
        checkNear(seenAlong(renderer, glm::vec3(0, 0, -1)), 2.0f * kMinusZ, 1e-5);
        checkNear(seenAlong(renderer, glm::vec3(1, 0, 0)), 2.0f * kPlusX, 1e-5);
        checkNear(seenAlong(renderer, glm::vec3(0, 0, 1)), 2.0f * kPlusZ, 1e-5);
        checkNear(seenAlong(renderer, glm::vec3(-1, 0, 0)), 2.0f * kMinusX, 1e-5);
        checkNear(seenAlong(renderer, glm::vec3(0, 1, 0)), 2.0f * kUp, 1e-5);
        checkNear(seenAlong(renderer, glm::vec3(0, -1, 0)), 2.0f * kDown, 1e-5);
        // 90 degrees counter-clockwise seen from above: what was at −z is now at −x, −x at +z.
        Scene rotated = renderer.scene();
        rotated.environment.rotationDeg = 90.0f;
        renderer.render({0, rotated});  // the views below start from this scene
        checkNear(seenAlong(renderer, glm::vec3(-1, 0, 0)), 2.0f * kMinusZ, 1e-5);
        checkNear(seenAlong(renderer, glm::vec3(0, 0, 1)), 2.0f * kMinusX, 1e-5);
        checkNear(seenAlong(renderer, glm::vec3(1, 0, 0)), 2.0f * kPlusZ, 1e-5);
        checkNear(seenAlong(renderer, glm::vec3(0, 1, 0)), 2.0f * kUp, 1e-5);
        // Read once, whatever changed since: the path did not.
        CHECK(renderer.environmentLoads() == 1);
    }
}

TEST_CASE("image environment: the GPU equals the CPU twin", "[environment]") {
    // Smooth random colours (bilinear filtering between every texel) seen through a wide lens that
    // takes in the seam at +z and the pole.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    Image texels(48, 24);
    for (glm::vec4& t : texels.pixels) t = glm::vec4(unit(rng), unit(rng), unit(rng), 1.0f);
    const std::string file = scratchDir("environment_twin") + "/random.exr";
    eikon::writeExr(file, texels);
    Scene scene = emptyScene();
    scene.environment.type = EnvironmentType::Image;
    scene.environment.file = file;
    scene.environment.intensity = 3.0f;
    scene.environment.rotationDeg = 30.0f;
    scene.camera = cameraAt(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.3f, 3.0f, 10.0f), 150.0f);
    scene.render.width = 64;
    scene.render.height = 48;
    FrameRenderer gpu(scene, Backend::Gpu);
    FrameRenderer cpu(scene, Backend::Cpu);
    const Image a = gpu.render(0);
    const Image b = cpu.render(0);
    const double relative = maxRelativeDifference(a, b);
    // Measured on llvmpipe: 2.1e-6 (the built-in atan and acos gave 1.1e-3 near the pole and
    // 1.7e-5 elsewhere, hence the shared environmentAtan2).
    INFO("GPU vs CPU twin, max |difference| / max value: " << relative);
    CHECK(relative < 1e-5);
}

TEST_CASE("image environment: a glass sphere shows the image behind it inverted, and reflects",
          "[environment]") {
    // Red where d.x < 0, blue where d.x > 0, for every elevation (u < 0.5 and u ≥ 0.5).
    Image halves(32, 16);
    for (int y = 0; y < halves.height; ++y)
        for (int x = 0; x < halves.width; ++x)
            halves.at(x, y) = x < halves.width / 2 ? glm::vec4(1, 0, 0, 1) : glm::vec4(0, 0, 1, 1);
    const std::string file = scratchDir("environment_glass") + "/halves.exr";
    eikon::writeExr(file, halves);
    Scene scene;
    scene.sources.push_back(sphereSource("n", glm::vec3(0.0f), 0.6f, 1.0f, 0.1f, 0.04f));
    eikon::MaterialSpec glass = material("glass", "n", glm::vec3(0.0f));
    glass.ior = 1.5f;
    scene.materials.push_back(glass);
    setVolume(scene, glm::vec3(-1.0f), glm::vec3(1.0f), glm::ivec3(40));
    scene.environment.type = EnvironmentType::Image;
    scene.environment.file = file;
    // The unpolarized Fresnel reflectance of n = 1.5 at 30°.
    const double kReflectance30 = eikon::test::fresnelExact(1.0, 1.5, std::acos(-1.0) / 6.0);
    // Looking along −z with +x to the right: without the sphere the left half is red, the right
    // half blue. A ball lens (n = 1.5, focal length 1.5 R from its centre) bends rays across the
    // axis, so through the sphere the left sees blue and the right red.
    scene.camera = cameraAt(glm::vec3(0.0f, 0.0f, 4.0f), glm::vec3(0.0f), 30.0f);
    scene.render.width = 33;
    scene.render.height = 25;
    Image images[2];
    for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
        INFO(backendName(backend));
        FrameRenderer renderer(scene, backend);
        const Image image = renderer.render(0);
        const int cy = image.height / 2;
        // x = ±0.3 at the sphere's centre plane is pixel 16 ± 5; x = ±0.9 is 16 ± 14.
        const glm::vec4 leftIn = image.at(11, cy), rightIn = image.at(21, cy);
        const glm::vec4 leftOut = image.at(2, cy), rightOut = image.at(30, cy);
        INFO("through the sphere: left " << leftIn.r << " " << leftIn.b << ", right " << rightIn.r
                                         << " " << rightIn.b);
        // What goes through shows the other half, 1 − R of it (R at the ray's entry, lost there;
        // at the exit the inside reflection of the same R goes the other half's way too, so the
        // channels add to 1): R(30°) = 0.0422 for a ray meeting the sphere at x = ±0.3 = R/2.
        // The reflection off the front face, R, shows the same half.
        CHECK(leftIn.b == Approx(1.0 - kReflectance30).margin(3e-3));
        CHECK(leftIn.r == Approx(kReflectance30).margin(3e-3));
        CHECK(rightIn.r == Approx(1.0 - kReflectance30).margin(3e-3));
        CHECK(rightIn.b == Approx(kReflectance30).margin(3e-3));
        CHECK(leftIn.r + leftIn.b == Approx(1.0).margin(1e-4));
        CHECK(rightIn.r + rightIn.b == Approx(1.0).margin(1e-4));
        CHECK(leftOut.r > 0.99f);
        CHECK(rightOut.b > 0.99f);
        images[backend == Backend::Gpu ? 0 : 1] = image;
    }
    const double relative = maxRelativeDifference(images[0], images[1]);
    // Measured on llvmpipe: 1.9e-6 without Fresnel; 2.2e-4 with it, at the silhouette, where
    // rays graze the sphere and R and the reflected ray's path change fast with the angle: the
    // GPU's normalize and length (inverse square roots) leave the momentum 1e-7 from the CPU
    // twin's, and there the CPU's own mirror-symmetric pixels differ by 2e-4 too.
    INFO("GPU vs CPU twin through the sphere: " << relative);
    CHECK(relative < 5e-4);
}

TEST_CASE("image environment: read once per change of path", "[environment]") {
    const std::string dir = scratchDir("environment_reload");
    eikon::writeExr(dir + "/a.exr", quartersImage());
    Image plain(4, 2);
    for (glm::vec4& t : plain.pixels) t = glm::vec4(0.25f, 0.5f, 0.75f, 1.0f);
    eikon::writeExr(dir + "/b.exr", plain);
    Scene scene = emptyScene();
    scene.environment.type = EnvironmentType::Image;
    scene.environment.file = dir + "/a.exr";
    FrameRenderer renderer(scene, Backend::Cpu);
    renderer.render(0);
    Scene next = renderer.scene();  // the next frames' scene, as the test changes it
    next.camera = lookAlong(glm::vec3(1, 0, 0));
    renderer.render({0, next});
    CHECK(renderer.environmentLoads() == 1);
    next.environment.file = dir + "/b.exr";
    checkNear(glm::vec3(renderer.render({0, next}).at(0, 0)), glm::vec3(0.25f, 0.5f, 0.75f), 1e-6);
    CHECK(renderer.environmentLoads() == 2);
    // Another type and back: the colour needs no file; the image is read again.
    next.environment.type = EnvironmentType::Color;
    next.environment.color = glm::vec3(0.125f);
    checkNear(glm::vec3(renderer.render({0, next}).at(0, 0)), glm::vec3(0.125f), 0.0);
    next.environment.type = EnvironmentType::Image;
    renderer.render({0, next});
    CHECK(renderer.environmentLoads() == 3);
}

TEST_CASE("image environment: a missing or non-EXR file names the file and the JSON path",
          "[environment]") {
    const std::string dir = scratchDir("environment_bad");
    const std::string notExr = dir + "/sky.exr";
    std::ofstream(notExr) << "this is not an EXR image\n";
    const std::string missing = dir + "/missing.exr";
    for (const std::string& file : {missing, notExr, dir}) {
        for (Backend backend : {Backend::Cpu, Backend::Gpu}) {
            INFO(backendName(backend) << ", " << file);
            Scene scene = emptyScene();
            scene.path = "scene.json";
            scene.environment.type = EnvironmentType::Image;
            scene.environment.file = file;
            FrameRenderer renderer(scene, backend);
            try {
                renderer.render(0);
                FAIL("expected an eikon::Error");
            } catch (const eikon::Error& e) {
                CHECK(e.where() == "scene.json:/environment/file");
                CHECK_THAT(e.reason(), Contains("'" + file + "'"));
                if (file == missing) CHECK_THAT(e.reason(), Contains("no such file"));
                if (file == notExr) CHECK_THAT(e.reason(), Contains("not an equirectangular EXR"));
            }
        }
    }
}

TEST_CASE("environment: the parser takes the three types and rejects bad values by JSON path",
          "[environment]") {
    const std::string body = R"("sources": [{"type": "sphere"}], "materials": [{"name": "m"}])";
    auto parse = [&](const std::string& environment) {
        return eikon::parseScene("{" + body + R"(, "environment": )" + environment + "}",
                                 "/scenes/scene.json");
    };
    auto failure = [&](const std::string& environment) {
        try {
            parse(environment);
        } catch (const eikon::Error& e) {
            return e;
        }
        FAIL("expected an eikon::Error for " << environment);
        return eikon::Error("", "");
    };

    const Scene color = parse(R"({"color": [0.1, 0.2, 0.3]})");
    CHECK(color.environment.type == EnvironmentType::Color);
    CHECK(color.environment.color == glm::vec3(0.1f, 0.2f, 0.3f));
    const Scene gradient = parse(
        R"({"type": "gradient", "zenith": [0, 0, 1], "horizon": [1, 1, 1], "ground": [0.5, 0.4, 0.3]})");
    CHECK(gradient.environment.type == EnvironmentType::Gradient);
    CHECK(gradient.environment.zenith == glm::vec3(0, 0, 1));
    CHECK(gradient.environment.horizon == glm::vec3(1, 1, 1));
    CHECK(gradient.environment.ground == glm::vec3(0.5f, 0.4f, 0.3f));
    const Scene image =
        parse(R"({"type": "image", "file": "maps/sky.exr", "intensity": 2, "rotation_deg": -45})");
    CHECK(image.environment.type == EnvironmentType::Image);
    CHECK(image.environment.file == "/scenes/maps/sky.exr");  // against the scene's folder
    CHECK(image.environment.intensity == 2.0f);
    CHECK(image.environment.rotationDeg == -45.0f);

    const eikon::Error type = failure(R"({"type": "sky"})");
    CHECK(type.where() == "/scenes/scene.json:/environment/type");
    CHECK_THAT(type.reason(), Contains("\"color\", \"gradient\", \"image\""));
    const eikon::Error intensity =
        failure(R"({"type": "image", "file": "a.exr", "intensity": -1})");
    CHECK(intensity.where() == "/scenes/scene.json:/environment/intensity");
    const eikon::Error noFile = failure(R"({"type": "image"})");
    CHECK(noFile.where() == "/scenes/scene.json:/environment/file");
    CHECK_THAT(noFile.reason(), Contains("file"));
    const eikon::Error noZenith = failure(R"({"type": "gradient", "horizon": [1, 1, 1]})");
    CHECK_THAT(noZenith.reason(), Contains("zenith"));
    // A key of another type is unknown here.
    const eikon::Error wrongKey = failure(R"({"color": [1, 1, 1], "file": "a.exr"})");
    CHECK(wrongKey.where() == "/scenes/scene.json:/environment/file");
}
