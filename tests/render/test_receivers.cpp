// Receivers (shaders/shared/receivers.h): a diffuse floor across the volume that photons land on
// and view rays stop at. Closed forms for a floor under an oblique directional light through all
// three ways it can be lit (plane map, voxel photon volumes, straight light volume), the energy
// balance with the received flux, GPU = CPU twin, and how sharp a shadow edge each photon method
// draws.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/camera.h"
#include "core/error.h"
#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/gl_context.h"
#include "render/image.h"
#include "render/receiver_map.h"
#include "render/view_params.h"
#include "render/volume_kernels_cpu.h"
#include "support/backends.h"
#include "support/light_transport_setup.h"
#include "support/scene_builders.h"

using eikon::Backend;
using eikon::FrameRenderer;
using eikon::Image;
using eikon::PhotonVolumes;
using eikon::ReceiverMethod;
using eikon::ReceiverSpec;
using eikon::Scene;
using eikon::test::backendName;
using eikon::test::boxSource;
using eikon::test::cameraAt;
using eikon::test::directionalLight;
using eikon::test::kPi;
using eikon::test::material;
using eikon::test::relativeError;
using eikon::test::setVolume;

namespace {

constexpr float kFloorY = -0.5f;  // on a voxel face of the 32³ volume over [−1, 1]³
constexpr float kAlbedo = 0.7f;
constexpr float kIrradiance = 2.0f;
constexpr double kLightTilt = 30.0 * kPi / 180.0;  // from the vertical, toward +x

ReceiverSpec floorReceiver(ReceiverMethod method) {
    ReceiverSpec r;
    r.axis = 1;
    r.position = kFloorY;
    r.facing = 1;
    r.albedo = glm::vec3(kAlbedo);
    r.method = method;
    r.texelsPerVoxel = 2;
    r.jsonPath = "/receivers/0";
    return r;
}

// A clear volume (a material that does nothing) over a floor, lit by a directional light tilted
// 30° from the vertical: the floor's irradiance is E cos 30° everywhere the light reaches it.
// `method`: the light-transport method, "photons" or "light_volumes".
Scene litFloor(ReceiverMethod method, const std::string& transport) {
    Scene scene;
    scene.sources.push_back(
        boxSource("density", glm::vec3(-1.0f), glm::vec3(1.0f), 1.0f, 0.0f, 0.0625f));
    scene.materials.push_back(material("air", "density", glm::vec3(0.0f)));
    scene.lights.push_back(directionalLight(
        glm::vec3(float(std::sin(kLightTilt)), -float(std::cos(kLightTilt)), 0.0f), kIrradiance));
    scene.receivers.push_back(floorReceiver(method));
    setVolume(scene, glm::vec3(-1.0f), glm::vec3(1.0f), glm::ivec3(32));
    // Odd sizes: the centre pixel's ray goes through look_at, the floor's centre.
    scene.camera = cameraAt(glm::vec3(0.0f, 2.5f, 1.2f), glm::vec3(0.0f, kFloorY, 0.0f), 40.0f);
    scene.render.width = 21;
    scene.render.height = 15;
    eikon::test::setTransportMethod(scene, transport);
    eikon::test::setPhotonSetting(scene, "per_side", 256);
    return scene;
}

double floorIrradiance() {
    return kIrradiance * std::cos(kLightTilt);
}

// The central texels of receiver 0's map (a margin of a quarter of the map on each side, where
// photons of the tilted light arrive whole from above, never through the box's side faces).
std::vector<double> centralTexels(const eikon::shared::GpuViewParams& p,
                                  const std::vector<glm::vec4>& map) {
    const glm::ivec4 t = p.receivers[0].texels;
    std::vector<double> values;
    for (int j = t.y / 4; j < 3 * t.y / 4; ++j)
        for (int i = t.x / 4; i < 3 * t.x / 4; ++i)
            values.push_back(map[size_t(t.z + j * t.x + i)].g);
    return values;
}

eikon::ViewSetup setupOf(const Scene& scene, const FrameRenderer& renderer) {
    return eikon::makeConfiguredViewSetup(
        scene, renderer.volume(),
        eikon::makeCameraFrame(scene.camera, renderer.volume().bounds, scene.render.width,
                               scene.render.height));
}

}  // namespace

TEST_CASE("receivers: a floor under a tilted light gets E cos θ through every method",
          "[receivers]") {
    const double expected = kAlbedo / kPi * floorIrradiance();
    struct Case {
        const char* name;
        ReceiverMethod method;
        const char* transport;
    };
    for (const Case& c :
         {Case{"plane map", ReceiverMethod::Plane, "photons"},
          Case{"voxel photon volumes", ReceiverMethod::Voxels, "photons"},
          Case{"light volume, no photons", ReceiverMethod::Plane, "light_volumes"}}) {
        for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
            INFO(c.name << ", " << backendName(backend));
            const Scene scene = litFloor(c.method, c.transport);
            FrameRenderer renderer(scene, backend);
            const Image image = renderer.render(0);
            CHECK(renderer.transportRuns("photons") ==
                  (std::string(c.transport) == "photons" ? 1 : 0));
            const glm::vec4 centre = image.at(image.width / 2, image.height / 2);
            INFO("centre pixel " << centre.g << ", expected albedo/π · E cos θ = " << expected);
            // Photons: the jittered grid's noise, a few tenths of a percent over the bilinear
            // footprint (measured 1e-3 and below). Straight: exact up to float rounding.
            CHECK(relativeError(centre.g, expected) < 1e-2);
            // Nothing shows through the opaque floor: the corner pixels look at the floor too,
            // and no pixel is brighter than the lit floor.
            for (const glm::vec4& px : image.pixels) CHECK(px.g < 1.05 * expected);
        }
    }
}

TEST_CASE("receivers: the plane map is flat, sums to the received flux and balances energy",
          "[receivers][photons]") {
    const Scene scene = litFloor(ReceiverMethod::Plane, "photons");
    FrameRenderer renderer(scene, Backend::Cpu);
    renderer.render(0);
    const PhotonVolumes photons = eikon::test::photonVolumesOf(renderer);
    const eikon::ViewSetup setup = setupOf(scene, renderer);
    REQUIRE(photons.receiverMap.size() == eikon::receiverMapTexels(setup.params));
    REQUIRE(photons.receiverMap.size() == 64u * 64u);

    const std::vector<double> centre = centralTexels(setup.params, photons.receiverMap);
    double mean = 0.0, sq = 0.0;
    for (double v : centre) mean += v;
    mean /= double(centre.size());
    for (double v : centre) sq += (v - mean) * (v - mean);
    const double rms = std::sqrt(sq / double(centre.size())) / mean;
    INFO("mean " << mean << " vs E cos θ " << floorIrradiance() << ", texel RMS " << rms);
    CHECK(relativeError(mean, floorIrradiance()) < 2e-3);
    CHECK(rms < 0.05);

    // Σ texel irradiance × texel area is the flux the floor received (all from the front here).
    eikon::shared::VolumeAccessCpu volume{setup.params};
    const double area = volume.receiverTexelArea(0);
    glm::dvec3 mapFlux(0.0);
    for (const glm::vec4& t : photons.receiverMap) mapFlux += glm::dvec3(glm::vec3(t)) * area;
    const eikon::PhotonTotals& totals = photons.totals;
    for (int c = 0; c < 3; ++c) {
        INFO("channel " << c);
        CHECK(totals.received[c] > 0.5 * totals.emitted[c]);
        CHECK(relativeError(mapFlux[c], totals.received[c]) < 1e-6);
        const double balance =
            totals.escaped[c] + totals.extinguished[c] + totals.dropped[c] + totals.received[c];
        CHECK(relativeError(balance, totals.emitted[c]) < 1e-6);
    }
}

TEST_CASE("receivers: GPU map and image equal the CPU twin's", "[receivers][gpu]") {
    Scene scene = litFloor(ReceiverMethod::Plane, "photons");
    // Something to bend and shadow: a glass ball over the floor, in thin fog.
    scene.sources.push_back(
        eikon::test::sphereSource("n", glm::vec3(0.0f, 0.2f, 0.0f), 0.4f, 1.0f, 0.1f));
    eikon::MaterialSpec glass = material("glass", "n", glm::vec3(0.1f, 0.2f, 0.4f));
    glass.ior = 1.5f;
    scene.materials.push_back(glass);
    scene.materials[0].scattering = glm::vec3(0.05f);
    FrameRenderer gpu(scene, Backend::Gpu);
    FrameRenderer cpu(scene, Backend::Cpu);
    const Image gpuImage = gpu.render(0);
    const Image cpuImage = cpu.render(0);
    const PhotonVolumes g = eikon::test::photonVolumesOf(gpu);
    const PhotonVolumes c = eikon::test::photonVolumesOf(cpu);
    REQUIRE(c.receiverMap.size() == g.receiverMap.size());
    REQUIRE_FALSE(c.receiverMap.empty());
    for (int ch = 0; ch < 3; ++ch) CHECK(g.totals.received[ch] == c.totals.received[ch]);
    if (gpu.context() && eikon::isSoftwareRenderer(gpu.context()->rendererName())) {
        CHECK(std::memcmp(g.receiverMap.data(), c.receiverMap.data(),
                          c.receiverMap.size() * sizeof(glm::vec4)) == 0);
    }
    const eikon::ImageDifference d = eikon::compareImages(gpuImage, cpuImage);
    INFO("max |GPU - CPU| " << d.maxAbs << " of " << d.referenceMax);
    CHECK(d.referenceMax > 0.05);
    CHECK(d.maxAbs < 1e-4 * d.referenceMax);
}

namespace {

// 10 %–90 % width of a rising edge sampled at positions xs (ascending), values ys.
double edgeWidth(const std::vector<double>& xs, const std::vector<double>& ys) {
    const double lo = *std::min_element(ys.begin(), ys.end());
    const double hi = *std::max_element(ys.begin(), ys.end());
    auto crossing = [&](double level) {
        for (size_t i = 1; i < ys.size(); ++i)
            if (ys[i - 1] < level && ys[i] >= level)
                return xs[i - 1] + (level - ys[i - 1]) / (ys[i] - ys[i - 1]) * (xs[i] - xs[i - 1]);
        return xs.back();
    };
    return crossing(lo + 0.9 * (hi - lo)) - crossing(lo + 0.1 * (hi - lo));
}

}  // namespace

TEST_CASE("receivers: the plane map draws a shadow edge sharper than the voxel floor",
          "[receivers][photons]") {
    // A thick absorbing block over x < 0 under a light straight down: its shadow's edge on the
    // floor lies at x = 0, geometrically sharp.
    Scene scene = litFloor(ReceiverMethod::Plane, "photons");
    scene.lights[0] = directionalLight(glm::vec3(0.0f, -1.0f, 0.0f), kIrradiance);
    scene.sources.push_back(boxSource("kappa", glm::vec3(-1.0f, 0.0f, -1.0f),
                                      glm::vec3(0.0f, 0.75f, 1.0f), 1.0f, 0.0f, 0.0625f));
    scene.materials.push_back(material("block", "kappa", glm::vec3(20.0f)));
    FrameRenderer renderer(scene, Backend::Cpu);
    renderer.render(0);
    const PhotonVolumes photons = eikon::test::photonVolumesOf(renderer);
    eikon::ViewSetup setup = setupOf(scene, renderer);

    // Both methods through the view pass's own function, on the same photons.
    eikon::shared::ViewKernelCpu kernel{{setup.params}};
    kernel.fluence = photons.radiance.data();
    kernel.fluenceDirection = photons.direction.data();
    kernel.receiverMap = photons.receiverMap.data();
    const double h = 2.0 / 32.0;
    std::vector<double> xs, plane, voxels;
    for (double x = -4.0 * h; x <= 4.0 * h + 1e-9; x += h / 16.0) {
        const glm::vec3 at(float(x), kFloorY, 0.0f);
        setup.params.receivers[0].plane.w = EK_RECEIVER_PLANE;
        xs.push_back(x / h);
        plane.push_back(kernel.receiverFluenceIrradiance(0, at).g);
        setup.params.receivers[0].plane.w = EK_RECEIVER_VOXELS;
        voxels.push_back(kernel.receiverFluenceIrradiance(0, at).g);
    }
    const double planeWidth = edgeWidth(xs, plane);
    const double voxelWidth = edgeWidth(xs, voxels);
    INFO("10-90% shadow edge width in voxels: plane map " << planeWidth << ", voxel floor "
                                                          << voxelWidth);
    // Lit side: both read E (the light is normal to the floor).
    CHECK(relativeError(plane.back(), kIrradiance) < 1e-2);
    CHECK(relativeError(voxels.back(), kIrradiance) < 1e-2);
    CHECK(plane.front() < 1e-2 * kIrradiance);
    CHECK(planeWidth < 1.5);  // measured 1.25 (the resampled block itself ramps over a voxel)
    CHECK(voxelWidth > 1.5 * planeWidth);
}

TEST_CASE("receivers: a plane outside the render volume is an error naming it", "[receivers]") {
    Scene scene = litFloor(ReceiverMethod::Plane, "photons");
    scene.path = "floor.json";
    scene.receivers[0].position = -1.0f;  // on the volume's face: nothing could reach it
    try {
        FrameRenderer renderer(scene, Backend::Cpu);
        renderer.render(0);
        FAIL("expected an error");
    } catch (const eikon::Error& e) {
        CHECK(e.where() == "floor.json:/receivers/0/position");
        CHECK_THAT(e.reason(), Catch::Matchers::Contains("strictly inside"));
    }
}
