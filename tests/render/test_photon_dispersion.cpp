// Dispersion in the photon method (render/transport/photons/photon_tracing.h): under a material
// with an Abbe number the photons are traced once per colour channel, each pass bending with that
// channel's n and depositing that channel alone. Against the closed form of rays in a linear index
// gradient (a prism's), against a glass without dispersion of each channel's n, with equal n in
// every channel against one pass, and the GPU against the CPU twin.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/dispersion.h"
#include "render/gl_context.h"
#include "render/refraction_volume.h"
#include "render/transport/photons/photon_tracing.h"
#include "support/dispersive_prism.h"
#include "support/photon_gpu_compare.h"

using namespace eikon;
using eikon::test::PhotonScene;

namespace {

using eikon::test::kPrismAbbe;
using eikon::test::kPrismIor;
using eikon::test::kPrismRise;

// The prism's photons, 24² of them, quarter-voxel steps at least.
struct Prism : eikon::test::DispersivePrism {
    PhotonSettings settings;

    explicit Prism(float abbe, float ior = kPrismIor) : DispersivePrism(abbe, ior) {
        settings.photonsPerSide = 24;
        settings.minStepVoxels = 0.25f;
    }
    PhotonResultCpu trace(bool disperse = true) const {
        return traceLightPhotonsCpu(s.setup, {&s.field}, s.gradient, s.octree, settings,
                                    disperse ? &channels : nullptr);
    }
};

bool sameBits(const void* a, const void* b, size_t bytes) {
    return std::memcmp(a, b, bytes) == 0;
}

}  // namespace

TEST_CASE(
    "photon dispersion: each channel's photons bend by the closed form of a linear index "
    "gradient with its own n, as the photons of a glass of that n",
    "[photons][dispersion]") {
    const Prism prism(kPrismAbbe);
    REQUIRE(dispersesView(prism.s.setup));
    const PhotonResultCpu result = prism.trace();
    const size_t perPass = result.photons.size() / 3;
    REQUIRE(result.photons.size() == 3 * perPass);
    const glm::vec3 n = channelIndices(kPrismIor, kPrismAbbe);
    // Rays move up by about 0.2 across the box. A ray keeps v_x = n(y0), its entry height's index
    // (∂n/∂x = 0), and crosses the box's 2 units of x with tan θ = sinh(g_c·2/n(y0)), g_c =
    // kPrismRise·(n_c − 1): v_y = v_x·that.
    double worst = 0.0;
    int photons[3] = {0, 0, 0};
    double meanSlope[3] = {0.0, 0.0, 0.0};
    for (size_t i = 0; i < result.photons.size(); ++i) {
        const shared::GpuPhoton& p = result.photons[i];
        const int c = int(i / perPass);
        const glm::vec3 x(p.position);
        const glm::vec3 v(p.direction);
        if (int(p.position.w) != EK_PHOTON_ESCAPED) continue;
        // Left through the far face, having entered above the bottom face's last half voxel (where
        // n is sampled clamped to the voxel centres, flat: those rays bend late, by up to 8e-4).
        if (x.x < 0.999f || x.y < -0.7f || x.y > 0.8f) continue;
        const double g = kPrismRise * (double(n[c]) - 1.0);
        const double expected = double(v.x) * std::sinh(g * 2.0 / double(v.x));
        worst = std::max(worst, std::abs(double(v.y) - expected));
        ++photons[c];
        meanSlope[c] += double(v.y) / double(v.x);
    }
    WARN("worst |v_y - closed form| " << worst << " over " << photons[0] << "/" << photons[1] << "/"
                                      << photons[2] << " photons");
    CHECK(worst < 1e-5);  // measured 1.2e-6; the channels part by 1e-2
    for (int c = 0; c < 3; ++c) {
        REQUIRE(photons[c] > 200);
        meanSlope[c] /= photons[c];
    }
    // Red bends least, blue most.
    CHECK(meanSlope[0] < meanSlope[1] - 2e-3);
    CHECK(meanSlope[1] < meanSlope[2] - 2e-3);
    CHECK(result.photonsTraced == 3 * int64_t(perPass));

    // Each channel's photons, and that channel of the deposits, are bit for bit those of a glass
    // without dispersion whose n is that channel's.
    for (int c = 0; c < 3; ++c) {
        Prism plain(0.0f, n[c]);
        const PhotonResultCpu one = plain.trace();
        INFO("channel " << c << ", n = " << n[c]);
        REQUIRE(one.photons.size() == perPass);
        CHECK(sameBits(one.photons.data(), result.photons.data() + c * perPass,
                       perPass * sizeof(shared::GpuPhoton)));
        REQUIRE(one.radiance.size() == result.radiance.size());
        bool same = true;
        for (size_t v = 0; v < one.radiance.size(); ++v)
            same = same && sameBits(&one.radiance[v][c], &result.radiance[v][c], sizeof(float));
        CHECK(same);
        CHECK(one.totals.escaped[c] == result.totals.escaped[c]);
        CHECK(one.totals.extinguished[c] == result.totals.extinguished[c]);
    }
}

TEST_CASE("photon dispersion with the same n in every channel: three passes deposit one's bytes",
          "[photons][dispersion]") {
    // n_F − n_C rounds to 0 at V_d = 1e30: every channel's n is n_d, yet three passes run.
    const Prism equal(1e30f);
    REQUIRE(dispersesView(equal.s.setup));
    const PhotonResultCpu three = equal.trace();
    const PhotonResultCpu one = equal.trace(false);
    CHECK(three.photonsTraced == 3 * one.photonsTraced);
    CHECK(three.steps == 3 * one.steps);
    REQUIRE(three.radiance.size() == one.radiance.size());
    // Power·length: the fixed-point deposits of each channel are the same integers.
    CHECK(sameBits(three.radiance.data(), one.radiance.data(),
                   one.radiance.size() * sizeof(glm::vec4)));
    CHECK(three.totals.emitted == one.totals.emitted);
    CHECK(three.totals.escaped == one.totals.escaped);
    CHECK(three.totals.extinguished == one.totals.extinguished);
    CHECK(three.totals.dropped == one.totals.dropped);
    // The mean direction sums each channel's luminance share on its own, rounding three times
    // where one pass rounds once: within a few quanta of 2^-40.
    const double difference = eikon::test::relativeVolumeDifference(three.direction, one.direction);
    INFO("direction: max |difference| / max |value| " << difference);
    CHECK(difference <= 1e-6);
}

TEST_CASE("GPU photon dispersion equals the CPU twin", "[photons][dispersion][gpu]") {
    auto context = createHeadlessContext();
    const Prism prism(kPrismAbbe);
    eikon::test::GpuRun gpu;
    gpu.textures.update({&prism.s.field});
    gpu.params.upload(prism.s.setup.params);
    gpu.refraction.compute(prism.s.setup, gpu.textures);
    gpu.refraction.computeChannelGradients(prism.s.setup, gpu.textures, gpu.params, nullptr);
    REQUIRE(gpu.refraction.downloadGradient() == prism.s.gradient);
    gpu.tracer.trace(prism.s.setup, gpu.textures, gpu.refraction, prism.settings, nullptr, true);
    const PhotonResultCpu cpu = prism.trace();
    eikon::test::requireIdentical(gpu.tracer.download(), cpu);
    CHECK(cpu.totals.escaped.x > 0.0);
}
