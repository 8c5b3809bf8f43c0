// Dispersion in the wavefront method (render/transport/wavefront/wavefront_tracing.h): under a
// material with an Abbe number each light sends one wavefront per colour channel, carrying that
// channel's power and bending with that channel's n. Against the closed form of particles in a
// linear index gradient (a prism's), and with equal n in every channel against one wavefront.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/camera.h"
#include "render/refraction_volume.h"
#include "render/transport/wavefront/wavefront_tracing.h"
#include "support/dispersive_prism.h"
#include "support/photon_scene.h"

using namespace eikon;
using eikon::test::PhotonScene;

namespace {

constexpr float kIor = 1.5f;    // n_d
constexpr float kAbbe = 20.0f;  // a dense flint's dispersion, strong on purpose
constexpr float kRise = 0.3f;   // the field is 1 + kRise·y: n_c(y) = n_c + kRise·(n_c − 1)·y

// Light along +x through the whole box [-1, 1]³ filled with the graded medium (no surface).
struct Prism {
    PhotonScene s;
    ChannelGradientsCpu channels;
    float stepVoxels = 1.0f;

    explicit Prism(float abbe, float ior = kIor)
        : s(32, ior, glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f),
            [](glm::vec3 p) { return 1.0f + kRise * p.y; }) {
        s.scene.materials[0].abbe = abbe;
        s.markGraded();
        channels = computeChannelGradientsCpu(s.setup, {&s.field});
    }
    WavefrontResultCpu trace(bool keepPatches, bool disperse = true) const {
        WavefrontSettings settings;
        settings.patchesPerSide = 16;
        settings.stepVoxels = stepVoxels;
        return traceWavefrontsCpu(s.setup, {&s.field}, s.gradient, settings, keepPatches,
                                  disperse ? &channels : nullptr);
    }
};

}  // namespace

TEST_CASE(
    "dispersion: each channel's wavefront bends by the closed form of a linear index gradient "
    "with its own n, as one wavefront of that n",
    "[wavefront][dispersion]") {
    Prism prism(kAbbe);
    REQUIRE(dispersesView(prism.s.setup));
    // Quarter-voxel steps: a step that straddles a face of the box, past which ∇n is 0, bends by
    // a cut-off force there, an error of first order in the step (measured worst |v_y error|
    // 2.2e-3, 1.0e-3, 5.3e-4, 2.7e-4 at 1, 1/2, 1/4, 1/8 voxel); the channels part by 1.5e-2.
    prism.stepVoxels = 0.25f;
    const WavefrontResultCpu result = prism.trace(true);
    const glm::vec3 n = channelIndices(kIor, kAbbe);
    // Each particle keeps v_x = n(y0), its entry height's index (∂n/∂x = 0), and crosses the
    // box's 2 units of x with tan θ = sinh(g_c·2/n(y0)), g_c = kRise·(n_c − 1): v_y = v_x·that.
    // Outside the box ∇n = 0 and it goes on straight.
    double worst = 0.0;
    int particles[3] = {0, 0, 0};
    double meanSlope[3] = {0.0, 0.0, 0.0};
    std::vector<shared::GpuWavefrontPatch> byChannel[3];
    for (const shared::GpuWavefrontPatch& p : result.patches) {
        const glm::vec3 power(p.power);
        const int c = power.x > 0.0f ? 0 : power.y > 0.0f ? 1 : 2;
        // One channel per wavefront.
        REQUIRE(power[(c + 1) % 3] == 0.0f);
        REQUIRE(power[(c + 2) % 3] == 0.0f);
        byChannel[c].push_back(p);
        if (int(p.state.x) != EK_PHOTON_ESCAPED) continue;
        for (int k = 0; k < 4; ++k) {
            const glm::vec3 x(p.corner[k]);
            const glm::vec3 v(p.velocity[k]);
            if (x.x < 1.0f || std::abs(x.y) > 0.8f) continue;  // left through the far face only
            const double g = kRise * (double(n[c]) - 1.0);
            const double expected = double(v.x) * std::sinh(g * 2.0 / double(v.x));
            worst = std::max(worst, std::abs(double(v.y) - expected));
            ++particles[c];
            meanSlope[c] += double(v.y) / double(v.x);
        }
    }
    WARN("worst |v_y - closed form| " << worst << " over " << particles[0] << "/" << particles[1]
                                      << "/" << particles[2] << " particles");
    CHECK(worst < 6e-4);
    for (int c = 0; c < 3; ++c) {
        REQUIRE(particles[c] > 100);
        meanSlope[c] /= particles[c];
    }
    // Red bends least, blue most.
    CHECK(meanSlope[0] < meanSlope[1] - 2e-3);
    CHECK(meanSlope[1] < meanSlope[2] - 2e-3);

    // Each channel's wavefront is, patch for patch and bit for bit, the wavefront of a glass
    // without dispersion whose n is that channel's.
    for (int c = 0; c < 3; ++c) {
        Prism plain(0.0f, n[c]);
        plain.stepVoxels = prism.stepVoxels;
        const WavefrontResultCpu one = plain.trace(true);
        REQUIRE(one.patches.size() == byChannel[c].size());
        bool same = true;
        for (size_t i = 0; i < one.patches.size(); ++i) {
            const shared::GpuWavefrontPatch& a = one.patches[i];
            const shared::GpuWavefrontPatch& b = byChannel[c][i];
            same = same && std::memcmp(a.corner, b.corner, sizeof(a.corner)) == 0 &&
                   std::memcmp(a.velocity, b.velocity, sizeof(a.velocity)) == 0 &&
                   a.power[c] == b.power[c] && a.state == b.state;
        }
        INFO("channel " << c << ", n = " << n[c]);
        CHECK(same);
    }
}

TEST_CASE("dispersion with the same n in every channel: three wavefronts deposit the bytes of one",
          "[wavefront][dispersion]") {
    // n_F − n_C rounds to 0 at V_d = 1e30: every channel's n is n_d, yet three passes run.
    const Prism equal(1e30f);
    REQUIRE(dispersesView(equal.s.setup));
    const WavefrontResultCpu three = equal.trace(false);
    const WavefrontResultCpu one = equal.trace(false, false);
    CHECK(three.startingPatches == 3 * one.startingPatches);
    REQUIRE(three.radiance.size() == one.radiance.size());
    // Power·length: the fixed-point deposits of each channel are the same integers.
    CHECK(std::memcmp(three.radiance.data(), one.radiance.data(),
                      one.radiance.size() * sizeof(glm::vec4)) == 0);
    CHECK(three.totals.emitted == one.totals.emitted);
    // The mean direction sums each channel's luminance share on its own, rounding three times
    // where one pass rounds once: within a few quanta of 2^-40.
    const double difference = eikon::test::relativeVolumeDifference(three.direction, one.direction);
    INFO("direction: max |difference| / max |value| " << difference);
    CHECK(difference <= 1e-6);
}
