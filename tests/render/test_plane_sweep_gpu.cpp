// The plane sweep on the GPU (shaders/plane_sweep.comp) against its CPU twin on llvmpipe: with
// the twin's rounding (EK_EXACT_MATH) the fluence volumes, the receivers' maps and the counters
// are the same bits; with the driver's own math they agree within float rounding;
// two GPU runs are identical.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "render/gl_context.h"
#include "render/params_buffer.h"
#include "render/refraction_volume.h"
#include "render/transport/plane_sweep/plane_sweep_gpu.h"
#include "render/volume_textures.h"
#include "support/linear_n2_medium.h"
#include "support/photon_scene.h"

using namespace eikon;
using eikon::test::PhotonScene;

namespace {

struct SweepGpuRun {
    explicit SweepGpuRun(bool exactMath) : sweep(exactMath) {}

    VolumeTextures textures;
    ParamsBuffer params;
    RefractionVolumesGpu refraction;
    PlaneSweepGpu sweep;

    PlaneSweepResultCpu run(const PhotonScene& s, const PlaneSweepSettings& settings) {
        textures.update({&s.field});
        params.upload(s.setup.params);
        refraction.compute(s.setup, textures);
        REQUIRE(refraction.downloadGradient() == s.gradient);  // what both sides bend by
        sweep.compute(s.setup, textures, refraction, settings, nullptr);
        return sweep.download();
    }
};

// The lights through the fluence, as the method's configure() sets them.
PhotonScene& allThroughFluence(PhotonScene& s) {
    for (int l = 0; l < shared::lightCount(s.setup.params); ++l)
        shared::setLightInFluence(s.setup.params, l);
    return s;
}

// Empty vectors (no receivers) are equal; memcmp may not see their null data().
bool sameBits(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
}

// The largest difference between two volumes relative to the largest value of the first.
double relativeDifference(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
    double largest = 0.0, difference = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            largest = std::max(largest, std::abs(double(a[i][c])));
            difference = std::max(difference, std::abs(double(a[i][c]) - double(b[i][c])));
        }
    return largest > 0.0 ? difference / largest : difference;
}

int differing(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
    int n = 0;
    for (size_t i = 0; i < a.size() && i < b.size(); ++i) n += a[i] != b[i];
    return n;
}

float softBall(glm::vec3 x) {
    return 0.5f - 0.5f * std::tanh((glm::length(x) - 0.5f) / 0.1f);
}

void requireIdentical(const PlaneSweepResultCpu& gpu, const PlaneSweepResultCpu& cpu) {
    REQUIRE(gpu.fluence.size() == cpu.fluence.size());
    INFO(differing(gpu.fluence, cpu.fluence)
         << " fluence voxels and " << differing(gpu.direction, cpu.direction)
         << " direction voxels differ; relative " << relativeDifference(cpu.fluence, gpu.fluence));
    CHECK(sameBits(gpu.fluence, cpu.fluence));
    CHECK(sameBits(gpu.direction, cpu.direction));
    CHECK(gpu.texels == cpu.texels);
    CHECK(gpu.texelSteps == cpu.texelSteps);
    CHECK(gpu.texelsLost == cpu.texelsLost);
    CHECK(gpu.memory.bufferBytes == cpu.memory.bufferBytes);
    CHECK(gpu.memory.outputBytes == cpu.memory.outputBytes);
    CHECK(sameBits(gpu.receiverMap, cpu.receiverMap));
}

// A floor across the sweep axis and a wall along it, each with its own map resolution.
void addReceivers(PhotonScene& s) {
    ReceiverSpec floor;
    floor.axis = 1;
    floor.position = -0.6f;
    floor.facing = 1;
    floor.texelsPerVoxel = 2;
    floor.jsonPath = "/receivers/0";
    ReceiverSpec wall = floor;
    wall.axis = 0;
    wall.position = 0.7f;
    wall.facing = -1;
    wall.texelsPerVoxel = 1;
    wall.jsonPath = "/receivers/1";
    s.scene.receivers = {floor, wall};
    s.setup = makeViewSetup(s.scene, s.field.volume,
                            makeCameraFrame(s.scene.camera, s.field.volume.bounds, 4, 4));
}

}  // namespace

TEST_CASE("the GPU plane sweep equals the CPU twin bit for bit with the twin's rounding",
          "[plane_sweep][gpu]") {
    auto context = createHeadlessContext();
    SweepGpuRun gpu(true);
    SECTION("a linear n^2 medium, absorbing, an oblique light bent on its way") {
        PhotonScene s(32, 2.0f, glm::vec3(0.4f, 0.8f, 1.6f),
                      glm::normalize(glm::vec3(0.15f, -1.0f, -0.25f)), eikon::test::linearN2Field);
        allThroughFluence(s);
        const PlaneSweepSettings settings;
        requireIdentical(gpu.run(s, settings),
                         sweepLightsCpu(s.setup, {&s.field}, s.gradient, settings));
    }
    SECTION("a ball lens under a spot light, two planes a voxel, two refinements") {
        PhotonScene s(
            32, 1.5f, glm::vec3(0.3f),
            PhotonScene::spotLight(glm::vec3(0.1f, 3.0f, -0.2f), glm::vec3(0.0f, -1.0f, 0.0f),
                                   glm::vec3(4.0f), 20.0f, 5.0f),
            softBall);
        allThroughFluence(s);
        PlaneSweepSettings settings;
        settings.planesPerVoxel = 2;
        settings.backTraceRefinements = 2;
        const PlaneSweepResultCpu cpu = sweepLightsCpu(s.setup, {&s.field}, s.gradient, settings);
        requireIdentical(gpu.run(s, settings), cpu);
        // And a second run on the same GPU objects: the same bits again.
        CHECK(sameBits(gpu.run(s, settings).fluence, cpu.fluence));
    }
    SECTION("a directional light with a disc: the turning kernel of the soft light") {
        LightSpec sun = PhotonScene::directionalLight(
            glm::normalize(glm::vec3(0.15f, -1.0f, -0.25f)), glm::vec3(1.0f));
        sun.angularDiameterDeg = 12.0f;
        PhotonScene s(32, 1.5f, glm::vec3(0.3f), sun, softBall);
        allThroughFluence(s);
        const PlaneSweepSettings settings;
        requireIdentical(gpu.run(s, settings),
                         sweepLightsCpu(s.setup, {&s.field}, s.gradient, settings));
    }
    SECTION("light lost where it turns along the planes is counted alike") {
        PhotonScene s(24, 2.0f, glm::vec3(0.0f), glm::normalize(glm::vec3(1.0f, -0.3f, 0.9f)),
                      softBall);
        allThroughFluence(s);
        PlaneSweepSettings settings;
        settings.minCosine = 0.6f;
        const PlaneSweepResultCpu cpu = sweepLightsCpu(s.setup, {&s.field}, s.gradient, settings);
        CHECK(cpu.texelsLost > 0);
        requireIdentical(gpu.run(s, settings), cpu);
    }
}

TEST_CASE("the GPU plane sweep gathers receivers as the CPU twin does, bit for bit",
          "[plane_sweep][gpu][receivers]") {
    // Fixed-point sums on both sides: the order in which texels add to a map texel, threads on
    // the CPU or invocations on the GPU, changes no bit.
    auto context = createHeadlessContext();
    SweepGpuRun gpu(true);
    PhotonScene s(32, 1.5f, glm::vec3(0.2f), glm::normalize(glm::vec3(0.5f, -1.0f, 0.1f)),
                  softBall);
    addReceivers(s);
    allThroughFluence(s);
    const PlaneSweepSettings settings;
    const PlaneSweepResultCpu cpu = sweepLightsCpu(s.setup, {&s.field}, s.gradient, settings);
    double floorPower = 0.0, wallPower = 0.0;
    const size_t floorTexels = 64 * 64;
    for (size_t i = 0; i < cpu.receiverMap.size(); ++i)
        (i < floorTexels ? floorPower : wallPower) += double(cpu.receiverMap[i].g);
    INFO("floor " << floorPower << ", wall " << wallPower);
    REQUIRE(floorPower > 0.0);  // both receivers gather light for the comparison to mean much
    REQUIRE(wallPower > 0.0);
    requireIdentical(gpu.run(s, settings), cpu);
}

TEST_CASE("with the driver's own math the GPU plane sweep agrees with the twin within rounding",
          "[plane_sweep][gpu]") {
    auto context = createHeadlessContext();
    SweepGpuRun gpu(false);
    PhotonScene s(32, 1.5f, glm::vec3(0.3f), glm::normalize(glm::vec3(0.1f, -1.0f, 0.05f)),
                  softBall);
    allThroughFluence(s);
    const PlaneSweepSettings settings;
    const PlaneSweepResultCpu cpu = sweepLightsCpu(s.setup, {&s.field}, s.gradient, settings);
    const PlaneSweepResultCpu first = gpu.run(s, settings);
    // llvmpipe's exp, length and dot differ from glibc's and glm's in the last bit of some
    // inputs; 32 planes of bilinear lookups carry that to a few float ulps of the largest value
    // (measured on Mesa llvmpipe: 2.0e-6 of the largest fluence, 2.1e-6 of the direction).
    INFO(differing(first.fluence, cpu.fluence) << " voxels differ");
    CHECK(relativeDifference(cpu.fluence, first.fluence) < 1e-5);
    CHECK(relativeDifference(cpu.direction, first.direction) < 1e-5);
    CHECK(sameBits(gpu.run(s, settings).fluence, first.fluence));
}
