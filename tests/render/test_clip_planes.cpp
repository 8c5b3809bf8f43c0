// Clip planes (core/scene.h ClipPlaneSpec, shaders/shared/optics.h clipWeight): they cut opacity
// and keep refraction. Beer–Lambert through a clipped slab, a glass ball cut away whole that
// renders the bytes of clear glass, the octree's extinction bounds holding between voxel centres
// where the weight is not trilinear, and every light-transport method carrying light unattenuated
// through what a plane cut, on the CPU twin and the GPU.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/image.h"
#include "render/light_transport_registry.h"
#include "render/volume_kernels_cpu.h"
#include "support/backends.h"
#include "support/light_transport_setup.h"
#include "support/scene_builders.h"

using eikon::Backend;
using eikon::ClipPlaneSpec;
using eikon::FrameRenderer;
using eikon::Image;
using eikon::Scene;
using eikon::test::backendName;
using eikon::test::boxSource;
using eikon::test::cameraAt;
using eikon::test::material;
using eikon::test::setVolume;

namespace {

ClipPlaneSpec clipPlane(glm::vec3 point, glm::vec3 normal,
                        std::vector<std::string> materials = {}) {
    ClipPlaneSpec c;
    c.point = point;
    c.normal = glm::normalize(normal);
    c.materials = std::move(materials);
    return c;
}

// A unit slab of field "density" (value 1) seen along −z by one pixel: the pixel is the
// transmittance exp(−∫κ).
Scene slabScene() {
    Scene s = eikon::test::transmittanceProbe();
    // Quarter-voxel view steps: a tilted plane's ramp spans 1.8 voxels along the ray, and the
    // midpoint rule at whole voxels misses 0.4 % of τ at its kinks (0.03 % at a quarter).
    s.render.stepVoxels = 0.25f;
    s.sources.push_back(
        boxSource("density", glm::vec3(-0.5f), glm::vec3(0.5f), 1.0f, 0.0f, 0.125f));
    s.materials.push_back(material("slab", "density", glm::vec3(1.0f, 0.5f, 0.25f)));
    return s;
}

glm::vec3 pixel(const Scene& scene, Backend backend) {
    return eikon::test::firstPixel(scene, backend);
}

size_t differingPixels(const Image& a, const Image& b) {
    REQUIRE(a.pixels.size() == b.pixels.size());
    size_t differ = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) differ += a.pixels[i] != b.pixels[i];
    return differ;
}

}  // namespace

TEST_CASE("A clip plane takes a slab's absorption away on its far side, not on the near one",
          "[clip]") {
    // The ray crosses the slab from z = 0.5 to −0.5. Keeping z < 0.2 (the normal points to what
    // stays) leaves 0.7 of it; with the plane tilted 40° about x the ray still meets it at z = 0.2.
    // The tolerance: 2e-3 relative, Beer–Lambert's for the slab itself (test_transfer_render).
    const float tilt = glm::radians(40.0f);
    for (const glm::vec3 normal :
         {glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, std::sin(tilt), -std::cos(tilt))}) {
        Scene scene = slabScene();
        scene.clipPlanes.push_back(clipPlane(glm::vec3(0.0f, 0.0f, 0.2f), normal));
        for (Backend backend : {Backend::Cpu, Backend::Gpu}) {
            INFO(backendName(backend) << ", normal " << normal.y << " " << normal.z);
            const glm::vec3 t = pixel(scene, backend);
            CHECK(t.r == Approx(std::exp(-0.7)).epsilon(2e-3));
            CHECK(t.g == Approx(std::exp(-0.35)).epsilon(2e-3));
            CHECK(t.b == Approx(std::exp(-0.175)).epsilon(2e-3));
        }
    }
    // Two planes keep what both keep: z < 0.2 and z > −0.1 leave 0.3.
    Scene both = slabScene();
    both.clipPlanes.push_back(clipPlane(glm::vec3(0.0f, 0.0f, 0.2f), glm::vec3(0, 0, -1)));
    both.clipPlanes.push_back(clipPlane(glm::vec3(0.0f, 0.0f, -0.1f), glm::vec3(0, 0, 1)));
    CHECK(pixel(both, Backend::Cpu).r == Approx(std::exp(-0.3)).epsilon(2e-3));
    // A scene built in code with a zero normal: one line at the plane, no picture of NaNs.
    Scene zero = slabScene();
    zero.clipPlanes.push_back(clipPlane(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f)));
    zero.clipPlanes[0].normal = glm::vec3(0.0f);
    CHECK_THROWS_WITH(pixel(zero, Backend::Cpu),
                      Catch::Matchers::Contains(":/clip_planes: the normal is zero"));
    // A plane that lists another material leaves this one whole.
    Scene other = slabScene();
    other.materials.push_back(material("air", "density", glm::vec3(0.0f)));
    other.clipPlanes.push_back(
        clipPlane(glm::vec3(0.0f, 0.0f, 0.2f), glm::vec3(0, 0, -1), {"air"}));
    CHECK(pixel(other, Backend::Cpu).r == Approx(std::exp(-1.0)).epsilon(2e-3));
}

TEST_CASE("What a clip plane cuts away still refracts: the bytes of the same glass made clear",
          "[clip]") {
    // A coloured glass ball in glowing fog under a spot light; a plane whose kept side misses the
    // volume cuts all of the glass's opacity. The picture must be, byte for byte, that of the
    // glass with no absorption, scattering or emission but the same n: n, ∇n and the Fresnel
    // surfaces read the field uncut. And it must not be the picture of no glass at all.
    Scene cut;
    setVolume(cut, glm::vec3(-1.0f), glm::vec3(1.0f), glm::ivec3(24));
    cut.camera = cameraAt(glm::vec3(0.6f, 0.4f, 4.0f), glm::vec3(0.0f), 36.0f);
    cut.environment.type = eikon::EnvironmentType::Gradient;
    cut.render.width = 32;
    cut.render.height = 24;
    cut.sources.push_back(boxSource("fog", glm::vec3(-1.0f), glm::vec3(1.0f), 1.0f, 0.0f, 0.125f));
    cut.sources.push_back(
        eikon::test::sphereSource("glass", glm::vec3(0.0f), 0.55f, 1.0f, 0.1f, 0.0625f));
    cut.materials.push_back(material("fog", "fog", glm::vec3(0.05f), glm::vec3(0.3f), 0.2f,
                                     glm::vec3(0.05f, 0.02f, 0.0f)));
    cut.materials.push_back(material("glass", "glass", glm::vec3(2.0f, 0.5f, 0.1f), glm::vec3(0.4f),
                                     0.0f, glm::vec3(0.0f, 0.1f, 0.0f)));
    cut.materials[1].ior = 1.5f;
    cut.lights.push_back(eikon::test::directionalLight(glm::vec3(-0.3f, -1.0f, -0.2f), 4.0f));
    cut.clipPlanes.push_back(
        clipPlane(glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0, 0, -1), {"glass"}));
    Scene clear = cut;
    clear.clipPlanes.clear();
    clear.materials[1].absorption = clear.materials[1].scattering = glm::vec3(0.0f);
    clear.materials[1].emission = glm::vec3(0.0f);
    Scene gone = clear;
    gone.materials[1].ior = 1.0f;
    for (const std::string method : {"light_volumes", "photons"}) {
        eikon::test::setTransportMethod(cut, method);
        eikon::test::setTransportMethod(clear, method);
        eikon::test::setTransportMethod(gone, method);
        for (Scene* s : {&cut, &clear, &gone}) eikon::test::setPhotonSetting(*s, "per_side", 48);
        // The GPU once, with one renderer for all three (its shaders compile once): llvmpipe
        // takes half a minute a picture of curved rays with Fresnel.
        const std::vector<Backend> backends = method == "light_volumes"
                                                  ? std::vector<Backend>{Backend::Cpu, Backend::Gpu}
                                                  : std::vector<Backend>{Backend::Cpu};
        for (Backend backend : backends) {
            INFO(method << ", " << backendName(backend));
            FrameRenderer renderer(cut, backend);
            const Image ia = renderer.render(0);
            const Image ib = renderer.render(eikon::FrameInputs(0, clear));
            const Image ic = renderer.render(eikon::FrameInputs(0, gone));
            CHECK(differingPixels(ia, ib) == 0);
            CHECK(differingPixels(ia, ic) > ia.pixels.size() / 20);  // the ball bends the view
        }
    }
}

TEST_CASE("The octree's extinction bounds hold between voxel centres across a clip plane",
          "[clip][octree]") {
    // κ at a sample is the field's trilinear blend times the plane's weight at the sample, not
    // the blend of κ at the centres: the bounds each voxel gives (optics.h voxelExtinctionRange,
    // the weight taken a voxel either way) must contain κ anywhere among its trilinear corners.
    // Random fields and tilted planes; the centre values alone must fail somewhere, or the bounds
    // are not what keeps the octree safe.
    constexpr int n = 8;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    eikon::shared::GpuViewParams p{};
    p.volumeMin = glm::vec4(0.0f);
    p.volumeMax = glm::vec4(float(n), float(n), float(n), 0.0f);
    p.resolution = glm::ivec4(n, n, n, 0);
    eikon::shared::setMaterialCount(p, 2);
    p.materials[0].absorption = glm::vec4(1.0f, 0.5f, 0.2f, 0.0f);
    p.materials[0].slot = glm::ivec4(0, 0, 1, 0);  // clipped by plane 0
    p.materials[1].scattering = glm::vec4(0.3f, 0.6f, 0.9f, 0.0f);
    p.materials[1].slot = glm::ivec4(1, 0, 3, 0);  // by planes 0 and 1
    std::vector<float> a(n * n * n), b(n * n * n);
    for (float& v : a) v = unit(rng) < 0.5f ? 0.0f : unit(rng);
    for (float& v : b) v = unit(rng) < 0.5f ? 0.0f : 2.0f * unit(rng);
    int centreMisses = 0;
    for (int trial = 0; trial < 20; ++trial) {
        // Index-space ramps with Σ|c_i| = 1, as view_params.cpp packs them.
        for (int k = 0; k < 2; ++k) {
            glm::vec3 c(unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f);
            c /= std::abs(c.x) + std::abs(c.y) + std::abs(c.z);
            p.clipPlanes[k] = glm::vec4(c, 0.5f - glm::dot(c, glm::vec3(n * unit(rng))));
        }
        eikon::shared::VolumeAccessCpu kernel{p};
        kernel.fields[0] = a.data();
        kernel.fields[1] = b.data();
        for (int s = 0; s < 2000; ++s) {
            const glm::vec3 q(0.5f + (n - 1) * unit(rng), 0.5f + (n - 1) * unit(rng),
                              0.5f + (n - 1) * unit(rng));
            const glm::vec3 kappa = kernel.extinctionAt(q);
            const float largest = std::max(kappa.x, std::max(kappa.y, kappa.z));
            const glm::ivec3 base =
                glm::clamp(glm::ivec3(glm::floor(q - 0.5f)), glm::ivec3(0), glm::ivec3(n - 2));
            float lo = 1e30f, hi = -1e30f, centreHi = -1e30f;
            for (int corner = 0; corner < 8; ++corner) {
                const glm::ivec3 v = base + glm::ivec3(corner & 1, (corner >> 1) & 1, corner >> 2);
                const glm::vec2 range = kernel.voxelExtinctionRange(v);
                lo = std::min(lo, range.x);
                hi = std::max(hi, range.y);
                const glm::vec3 centre = kernel.extinctionAt(glm::vec3(v) + 0.5f);
                centreHi = std::max(centreHi, std::max(centre.x, std::max(centre.y, centre.z)));
            }
            INFO("trial " << trial << " at " << q.x << " " << q.y << " " << q.z);
            REQUIRE(largest <= hi * (1.0f + 1e-5f) + 1e-6f);
            REQUIRE(largest >= lo * (1.0f - 1e-5f) - 1e-6f);
            centreMisses += largest > centreHi * (1.0f + 1e-5f) + 1e-6f;
        }
    }
    INFO(centreMisses << " samples above every centre's κ");
    CHECK(centreMisses > 0);
}

TEST_CASE("Every light-transport method carries light unattenuated through what a plane cut",
          "[clip][light_transport]") {
    // An absorbing roof (τ = 3 × 0.4) over weakly scattering fog, a light straight down; a plane
    // keeps the roof only at x < 0. Seen from the front below the roof, the fog at x ≈ +0.45 is lit
    // as if there were no roof and the fog at x ≈ −0.45 lies in its shadow: their radiances part
    // by e^−1.2 (the fog and the view are the same on both sides). Tolerances: 2 % for the
    // deterministic methods, 6 % for the photons' density estimate at 64² photons.
    Scene scene;
    setVolume(scene, glm::vec3(-1.0f), glm::vec3(1.0f), glm::ivec3(20));
    scene.camera = cameraAt(glm::vec3(0.0f, -0.5f, 4.0f), glm::vec3(0.0f, -0.5f, 0.0f), 40.0f);
    scene.render.width = 16;
    scene.render.height = 4;
    scene.sources.push_back(boxSource("roof", glm::vec3(-1.0f, 0.3f, -1.0f),
                                      glm::vec3(1.0f, 0.7f, 1.0f), 1.0f, 0.0f, 0.1f));
    scene.sources.push_back(boxSource("fog", glm::vec3(-1.0f), glm::vec3(1.0f), 1.0f, 0.0f, 0.1f));
    scene.materials.push_back(material("roof", "roof", glm::vec3(3.0f)));
    scene.materials.push_back(material("fog", "fog", glm::vec3(0.0f), glm::vec3(0.05f)));
    scene.lights.push_back(eikon::test::directionalLight(glm::vec3(0.0f, -1.0f, 0.0f), 2.0f));
    scene.clipPlanes.push_back(clipPlane(glm::vec3(0.0f), glm::vec3(-1, 0, 0), {"roof"}));
    const double expected = std::exp(-1.2);
    for (const eikon::LightTransportMethod& method : eikon::lightTransportMethods()) {
        Scene s = scene;
        eikon::test::setTransportMethod(s, method.name);
        eikon::test::setPhotonSetting(s, "per_side", 64);
        FrameRenderer renderer(s, Backend::Cpu);
        const Image image = renderer.render(0);
        const auto radiance = [&](int column) {
            return 0.5 * (double(image.at(column, 1).g) + double(image.at(column, 2).g));
        };
        const double lit = radiance(10), shadowed = radiance(5);
        INFO(method.name << ": lit " << lit << ", shadowed " << shadowed);
        REQUIRE(lit > 0.0);
        const double tolerance = method.name == std::string("photons") ? 0.06 : 0.02;
        CHECK(shadowed / lit == Approx(expected).epsilon(tolerance));
    }
}
