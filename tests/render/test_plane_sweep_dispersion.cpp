// Dispersion in the plane sweep (render/transport/plane_sweep/plane_sweep_cpu.h): under a
// material with an Abbe number each light is swept once per colour channel, through that
// channel's ∇n volume, its source sending that channel alone. Against a glass without dispersion
// of each channel's n, with equal n in every channel against one sweep, and the GPU against the
// CPU twin.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/dispersion.h"
#include "render/gl_context.h"
#include "render/params_buffer.h"
#include "render/transport/plane_sweep/plane_sweep_cpu.h"
#include "render/transport/plane_sweep/plane_sweep_gpu.h"
#include "render/volume_textures.h"
#include "support/dispersive_prism.h"

using namespace eikon;
using eikon::test::DispersivePrism;
using eikon::test::kPrismAbbe;
using eikon::test::kPrismIor;

namespace {

// The light's mean v_y / v_x over the lit texels of the last plane (the volume's far slice),
// per pass of the sweep (the observer sees each pass in turn, red, green, blue).
struct LastPlaneSlopes {
    std::vector<double> slopes;
    PlaneSweepObserver observer() {
        return [this](int, const PlaneSweepPlan& plan, int slice, const std::vector<glm::vec4>&,
                      const std::vector<glm::vec4>& direction) {
            if (slice != plan.depth - 1) return;
            double sum = 0.0;
            int lit = 0;
            for (const glm::vec4& v : direction)
                if (v.w > 0.0f && v.x > 0.0f) {
                    sum += double(v.y) / double(v.x);
                    ++lit;
                }
            slopes.push_back(lit > 0 ? sum / lit : 0.0);
        };
    }
};

PlaneSweepResultCpu sweep(const DispersivePrism& prism, bool disperse,
                          const PlaneSweepObserver& observer = {}) {
    return sweepLightsCpu(prism.s.setup, {&prism.s.field}, prism.s.gradient, PlaneSweepSettings{},
                          observer, disperse ? &prism.channels : nullptr);
}

bool sameFloat(float a, float b) {
    return std::memcmp(&a, &b, sizeof(float)) == 0;
}

}  // namespace

TEST_CASE(
    "plane-sweep dispersion: each channel's light bends with its own n, as the sweep of a glass "
    "of that n",
    "[plane_sweep][dispersion]") {
    const DispersivePrism prism(kPrismAbbe);
    REQUIRE(dispersesView(prism.s.setup));
    LastPlaneSlopes seen;
    const PlaneSweepResultCpu result = sweep(prism, true, seen.observer());
    REQUIRE(seen.slopes.size() == 3);
    // Red bends least, blue most (the channels' n part by n_F − n_C = 0.025; measured mean
    // slopes 0.1904, 0.1923, 0.1968: Cauchy's law parts blue from green more than green from red).
    INFO("mean slope on the far plane: " << seen.slopes[0] << ", " << seen.slopes[1] << ", "
                                         << seen.slopes[2]);
    CHECK(seen.slopes[0] < seen.slopes[1] - 1e-3);
    CHECK(seen.slopes[1] < seen.slopes[2] - 1e-3);

    const glm::vec3 n = channelIndices(kPrismIor, kPrismAbbe);
    int64_t texelSteps = 0;
    for (int c = 0; c < 3; ++c) {
        const DispersivePrism plain(0.0f, n[c]);
        LastPlaneSlopes plainSeen;
        const PlaneSweepResultCpu one = sweep(plain, true, plainSeen.observer());
        texelSteps += one.texelSteps;
        INFO("channel " << c << ", n = " << n[c]);
        REQUIRE(plainSeen.slopes.size() == 1);  // no dispersion: one sweep
        CHECK(plainSeen.slopes[0] == seen.slopes[size_t(c)]);
        REQUIRE(one.fluence.size() == result.fluence.size());
        bool same = true;
        for (size_t v = 0; v < one.fluence.size(); ++v)
            same = same && sameFloat(one.fluence[v][c], result.fluence[v][c]);
        CHECK(same);
    }
    CHECK(result.texelSteps == texelSteps);
}

TEST_CASE(
    "plane-sweep dispersion with the same n in every channel: three sweeps give one's fluence",
    "[plane_sweep][dispersion]") {
    // n_F − n_C rounds to 0 at V_d = 1e30: every channel's n is n_d, yet three sweeps run.
    const DispersivePrism equal(1e30f);
    REQUIRE(dispersesView(equal.s.setup));
    const PlaneSweepResultCpu three = sweep(equal, true);
    const PlaneSweepResultCpu one = sweep(equal, false);
    CHECK(three.texelSteps == 3 * one.texelSteps);
    REQUIRE(three.fluence.size() == one.fluence.size());
    // Each channel's fluence is added to zeros of the other passes: the same floats.
    CHECK(std::memcmp(three.fluence.data(), one.fluence.data(),
                      one.fluence.size() * sizeof(glm::vec4)) == 0);
    // The mean direction sums each channel's luminance share on its own (float sums, rounded
    // three times where one sweep rounds once).
    const double difference = eikon::test::relativeVolumeDifference(three.direction, one.direction);
    INFO("direction: max |difference| / max |value| " << difference);
    CHECK(difference <= 1e-6);
}

TEST_CASE("GPU plane-sweep dispersion equals the CPU twin", "[plane_sweep][dispersion][gpu]") {
    auto context = createHeadlessContext();
    const DispersivePrism prism(kPrismAbbe);
    VolumeTextures textures;
    ParamsBuffer params;
    RefractionVolumesGpu refraction;
    PlaneSweepGpu gpu(true);
    textures.update({&prism.s.field});
    params.upload(prism.s.setup.params);
    refraction.compute(prism.s.setup, textures);
    refraction.computeChannelGradients(prism.s.setup, textures, params, nullptr);
    gpu.compute(prism.s.setup, textures, refraction, PlaneSweepSettings{}, nullptr, true);
    const PlaneSweepResultCpu g = gpu.download();
    const PlaneSweepResultCpu c = sweep(prism, true);
    CHECK(g.texelSteps == c.texelSteps);
    CHECK(g.texelsLost == c.texelsLost);
    REQUIRE(g.fluence.size() == c.fluence.size());
    CHECK(std::memcmp(g.fluence.data(), c.fluence.data(), c.fluence.size() * sizeof(glm::vec4)) ==
          0);
    CHECK(std::memcmp(g.direction.data(), c.direction.data(),
                      c.direction.size() * sizeof(glm::vec4)) == 0);
    double red = 0.0;
    for (const glm::vec4& f : c.fluence) red += f.x;
    CHECK(red > 0.0);
}
