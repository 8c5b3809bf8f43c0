// Dispersion in the view pass (render/view_params.h channelViewParams, shaders/shared/view_march.h
// renderPixelChannel): each colour channel's rays bend with that channel's n (core/dispersion.h),
// against the closed form of a ray in a linear index gradient, and with equal indices in every
// channel the very bytes of a render without dispersion; the GPU against the CPU twin.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "core/log.h"
#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/image.h"
#include "support/scene_builders.h"

using eikon::Backend;
using eikon::EnvironmentType;
using eikon::FrameRenderer;
using eikon::Image;
using eikon::Scene;
using eikon::test::boxSource;
using eikon::test::cameraAt;
using eikon::test::material;
using eikon::test::setVolume;
using eikon::test::sphereSource;

namespace {

// n_d and the Abbe number of a dense flint glass (Schott N-SF6 has 1.805 and 25.4): a strong
// dispersion on purpose, so that the channels part by far more than the method's error.
constexpr float kIor = 1.5f;
constexpr float kAbbe = 20.0f;
// The field rises linearly with height, f = 1 + kRise·y: n_c(y) = n_c + kRise·(n_c − 1)·y.
constexpr float kRise = 0.3f;

// A prism-like medium filling the volume x, y, z in [-1, 1] (no face inside it): glass whose field
// grows with y, a graded medium, not a surface (fresnel off). The sky is white with a black horizon
// (radiance sqrt(d.y) for a ray leaving along d, going up), so each channel of the one pixel says
// how far up its ray left. The camera looks along +x at y = 0.
Scene prismScene(float abbe) {
    Scene s;
    eikon::SourceSpec ramp = boxSource("n", glm::vec3(-3.0f), glm::vec3(3.0f), 1.0f);
    ramp.profile = eikon::SourceProfile::Ramp;
    ramp.rampAxis = 1;
    ramp.rampFrom = 1.0f - 3.0f * kRise;
    ramp.rampTo = 1.0f + 3.0f * kRise;
    ramp.voxelSize = 0.0625f;
    s.sources.push_back(ramp);
    eikon::MaterialSpec glass = material("flint", "n", glm::vec3(0.0f));
    glass.ior = kIor;
    glass.abbe = abbe;
    glass.fresnel = false;
    s.materials.push_back(glass);
    setVolume(s, glm::vec3(-1.0f), glm::vec3(1.0f), glm::ivec3(32, 32, 4));
    s.environment.type = EnvironmentType::Gradient;
    s.environment.zenith = glm::vec3(1.0f);
    s.environment.horizon = glm::vec3(0.0f);
    s.environment.ground = glm::vec3(0.0f);
    s.camera = cameraAt(glm::vec3(-1.5f, 0.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    s.render.width = s.render.height = 1;
    return s;
}

// sin of the angle above +x at which a ray leaves the medium n(y) = n0 + g·y after running a
// length l along x from y = 0 horizontally: n cos θ = n0 along it (∂n/∂x = 0), so
// y(x) = (n0/g)(cosh(g x/n0) − 1), tan θ = sinh(g l/n0) and sin θ = tanh(g l/n0). It leaves the
// volume through its face x = 1 with that direction (the face is the volume's, not the glass's).
double exitSine(double n0, double g, double l) {
    return std::tanh(g * l / n0);
}

}  // namespace

TEST_CASE(
    "dispersion: each channel's view ray bends by the closed form of a linear index gradient "
    "with its own n, GPU as the CPU twin",
    "[view][dispersion]") {
    const glm::vec3 n = eikon::channelIndices(kIor, kAbbe);
    REQUIRE(n.x < n.y);
    REQUIRE(n.y == kIor);
    REQUIRE(n.y < n.z);
    // Measured (Verlet, 1-voxel steps; n linear, so its trilinear samples and central
    // differences are exact): worst |error| in sin θ 7.9e-7, CPU twin and GPU; the channels part
    // by 6e-3, 600 times the tolerance.
    constexpr double kTolerance = 1e-5;
    Image images[2];
    double worst = 0.0;
    for (Backend backend : {Backend::Cpu, Backend::Gpu}) {
        FrameRenderer renderer(prismScene(kAbbe), backend);
        const Image image = renderer.render(0);
        const glm::vec4 pixel = image.at(0, 0);
        for (int c = 0; c < 3; ++c) {
            const double expected = exitSine(n[c], kRise * (n[c] - 1.0), 2.0);
            const double got = double(pixel[c]) * double(pixel[c]);  // sky radiance sqrt(d.y)
            INFO((backend == Backend::Gpu ? "GPU" : "CPU twin")
                 << ", channel " << c << ": n = " << n[c] << ", sin theta " << got
                 << ", closed form " << expected);
            CHECK(got == Approx(expected).margin(kTolerance));
            worst = std::max(worst, std::abs(got - expected));
        }
        // Red bends least and blue most, as through a prism.
        CHECK(pixel.x < pixel.y);
        CHECK(pixel.y < pixel.z);
        images[backend == Backend::Gpu ? 1 : 0] = image;
    }
    WARN("worst |error| in sin theta, both backends: " << worst);
    const glm::vec4 cpu = images[0].at(0, 0), gpu = images[1].at(0, 0);
    INFO("CPU " << cpu.x << " " << cpu.y << " " << cpu.z << ", GPU " << gpu.x << " " << gpu.y << " "
                << gpu.z);
    for (int c = 0; c < 4; ++c) CHECK(gpu[c] == Approx(cpu[c]).margin(1e-5));

    // Without dispersion every channel takes the green one's path.
    FrameRenderer plain(prismScene(0.0f), Backend::Cpu);
    const glm::vec4 same = plain.render(0).at(0, 0);
    CHECK(same.x == same.y);
    CHECK(same.z == same.y);
    CHECK(same.y == cpu.y);
}

TEST_CASE(
    "dispersion with the same n in every channel renders the bytes of no dispersion, on the "
    "CPU twin and on the GPU",
    "[view][dispersion]") {
    // A glass ball with Fresnel reflection in glowing fog, under the gradient sky: curved rays,
    // the surface walk, kept reflections, emission and absorption all run per channel.
    auto ballScene = [](float abbe) {
        Scene s;
        s.sources.push_back(sphereSource("glass", glm::vec3(0.0f), 0.6f, 1.0f, 0.1f, 0.04f));
        s.sources.push_back(boxSource("fog", glm::vec3(-1.0f), glm::vec3(1.0f), 1.0f));
        eikon::MaterialSpec glass = material("glass", "glass", glm::vec3(0.0f));
        glass.ior = kIor;
        glass.abbe = abbe;
        s.materials.push_back(glass);
        eikon::MaterialSpec fog = material("fog", "fog", glm::vec3(0.3f, 0.2f, 0.1f));
        fog.emission = glm::vec3(0.05f, 0.1f, 0.2f);
        s.materials.push_back(fog);
        setVolume(s, glm::vec3(-1.0f), glm::vec3(1.0f), glm::ivec3(24));
        s.environment.type = EnvironmentType::Gradient;
        s.camera = cameraAt(glm::vec3(0.3f, 0.5f, 3.0f), glm::vec3(0.0f), 40.0f);
        s.render.width = 16;
        s.render.height = 12;
        return s;
    };
    // An Abbe number so large that n_F − n_C rounds away: every channel's n is n_d to the bit,
    // yet the scene disperses (abbe > 0), so each channel is traced on its own.
    const glm::vec3 equal = eikon::channelIndices(kIor, 1e30f);
    REQUIRE(equal == glm::vec3(kIor));
    FrameRenderer plain(ballScene(0.0f), Backend::Cpu);
    FrameRenderer perChannel(ballScene(1e30f), Backend::Cpu);
    const Image a = plain.render(0);
    const Image b = perChannel.render(0);
    REQUIRE(a.pixels.size() == b.pixels.size());
    CHECK(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec4)) == 0);

    // The GPU's three dispatches against its plain pass (the same bytes with equal n) and
    // against the CPU twin. Measured on llvmpipe: 2 of the 192 pixels differ from the twin by more
    // than 1e-4 (by up to 0.02) with and without dispersion alike, and 1 with V_d = 20: silhouette
    // pixels, where the ray grazes the ball and the two sides' last-bit differences in n decide
    // differently whether a surface was crossed; every other pixel within 1e-4.
    Image gpuImages[3];
    const float abbes[3] = {0.0f, 1e30f, kAbbe};
    for (int i = 0; i < 3; ++i) {
        FrameRenderer gpu(ballScene(abbes[i]), Backend::Gpu);
        FrameRenderer cpu(ballScene(abbes[i]), Backend::Cpu);
        gpuImages[i] = gpu.render(0);
        const Image twin = cpu.render(0);
        int over = 0;
        for (size_t p = 0; p < twin.pixels.size(); ++p) {
            float d = 0.0f;
            for (int k = 0; k < 4; ++k)
                d = std::max(d, std::abs(gpuImages[i].pixels[p][k] - twin.pixels[p][k]));
            over += d > 1e-4f ? 1 : 0;
        }
        INFO("abbe " << abbes[i] << ": pixels off the CPU twin by more than 1e-4: " << over);
        CHECK(over <= 4);
    }
    CHECK(std::memcmp(gpuImages[0].pixels.data(), gpuImages[1].pixels.data(),
                      gpuImages[0].pixels.size() * sizeof(glm::vec4)) == 0);
}

// Release only (45 s under the sanitizers): the [dispersion] cases of photons, the plane sweep and
// the wavefront run each method's dispersive passes under ASan + UBSan at a smaller size.
TEST_CASE("every light-transport method renders a dispersive scene without a warning",
          "[view][dispersion][release_only]") {
    // A flint ball in fog under a directional light: photons, the plane sweep and the wavefront
    // disperse its light (their own tests: test_photon_dispersion.cpp,
    // test_plane_sweep_dispersion.cpp, test_wavefront_dispersion.cpp), light volumes carry it
    // straight, where n does not matter: none has anything to warn of.
    auto litBall = [](const char* method) {
        Scene s;
        s.sources.push_back(sphereSource("glass", glm::vec3(0.0f), 0.5f, 1.0f, 0.1f, 0.1f));
        s.sources.push_back(boxSource("fog", glm::vec3(-1.0f), glm::vec3(1.0f), 1.0f));
        eikon::MaterialSpec glass = material("glass", "glass", glm::vec3(0.0f));
        glass.ior = kIor;
        glass.abbe = kAbbe;
        s.materials.push_back(glass);
        s.materials.push_back(material("fog", "fog", glm::vec3(0.01f), glm::vec3(0.2f)));
        s.lights.push_back(eikon::test::directionalLight(glm::vec3(0.0f, -1.0f, 0.0f), 1.0f));
        setVolume(s, glm::vec3(-1.0f), glm::vec3(1.0f), glm::ivec3(16));
        s.render.width = 8;
        s.render.height = 6;
        s.render.lightTransport = std::string("{\"method\": \"") + method + "\"}";
        return s;
    };
    for (const char* method : {"photons", "plane_sweep", "wavefront", "light_volumes"}) {
        INFO(method);
        eikon::ScopedWarningCapture capture;
        FrameRenderer renderer(litBall(method), Backend::Cpu);
        const Image image = renderer.render(0);
        CHECK(capture.warnings().empty());
        CHECK(image.width == 8);
    }
}
