// The CPU twins' shortcuts that must not move a float: constant bricks (render/constant_bricks.h,
// sampling.h EK_CONSTANT_BRICKS), one exp for a grey κ (optics.h channelDecay, view_march.h
// stepWeights, photons.h photonDecayIntegrals) and the isotropic phase function (optics.h
// phaseHG). Each is held to what the GPU's code computes, to the bit.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "render/constant_bricks.h"
#include "render/transport/photons/photon_kernel_cpu.h"
#include "render/volume_kernels_cpu.h"
#include "support/cpu_view_variants.h"

using eikon::ConstantBricks;

namespace {

template <typename T>
bool sameBits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

size_t voxelAt(glm::ivec3 res, int x, int y, int z) {
    return (size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) + size_t(x);
}

bool constantAt(const ConstantBricks& b, int slot, int bx, int by, int bz) {
    return (b.mask[b.brickIndex(glm::ivec3(bx, by, bz) * 4)] >> slot & 1) != 0;
}

}  // namespace

TEST_CASE("constant bricks: a brick is constant where every voxel its samples read holds one value",
          "[constant_bricks]") {
    const glm::ivec3 res(10, 8, 9);  // bricks 3 × 2 × 3, the last ones short
    std::vector<float> field(size_t(res.x) * size_t(res.y) * size_t(res.z), 1.5f);
    const auto bricks = [&] {
        ConstantBricks b(res);
        b.addField(0, field.data());
        return b;
    };
    SECTION("one value everywhere: every brick, with that value") {
        const ConstantBricks b = bricks();
        CHECK(b.count == glm::ivec3(3, 2, 3));
        CHECK(b.constantCount(0) == 18);
        CHECK(b.constantCount(1) == 0);  // not added
        CHECK(sameBits(b.values[b.brickIndex(glm::ivec3(9, 7, 8))], glm::vec4(1.5f, 0, 0, 0)));
    }
    SECTION("a sample reads its corner's voxel and the next: a brick reaches one voxel up") {
        field[voxelAt(res, 4, 1, 1)] = 2.0f;  // the first voxel of brick (1, 0, 0) along x
        ConstantBricks b = bricks();
        CHECK(!constantAt(b, 0, 0, 0, 0));  // its corners at x = 3 read x = 4
        CHECK(!constantAt(b, 0, 1, 0, 0));
        CHECK(b.constantCount(0) == 16);
        field[voxelAt(res, 4, 1, 1)] = 1.5f;
        field[voxelAt(res, 3, 1, 1)] = 2.0f;  // the last voxel of brick (0, 0, 0)
        b = bricks();
        CHECK(!constantAt(b, 0, 0, 0, 0));
        CHECK(constantAt(b, 0, 1, 0, 0));  // its samples read from x = 4 up
        CHECK(b.constantCount(0) == 17);
    }
    SECTION("values compare by their bits: +0 and −0 differ") {
        std::fill(field.begin(), field.end(), 0.0f);
        field[voxelAt(res, 9, 7, 8)] = -0.0f;  // the last voxel, read from z = 4 up
        const ConstantBricks b = bricks();
        CHECK(!constantAt(b, 0, 2, 1, 1));
        CHECK(!constantAt(b, 0, 2, 1, 2));
        CHECK(b.constantCount(0) == 16);
    }
    SECTION("bricks left out are never constant; the others are found as before") {
        std::vector<uint8_t> leftOut(18, 0);
        leftOut[5] = leftOut[17] = 1;
        ConstantBricks b(res);
        b.leaveOut(leftOut);
        b.addField(0, field.data());
        CHECK(b.constantCount(0) == 16);
        CHECK(!constantAt(b, 0, 2, 1, 0));  // brick 5
        CHECK(!constantAt(b, 0, 2, 1, 2));  // brick 17
        CHECK(constantAt(b, 0, 1, 1, 0));
        // Only before a slot is added, and only for a volume of as many bricks.
        CHECK_THROWS(b.leaveOut(leftOut));
        ConstantBricks other(res);
        CHECK_THROWS(other.leaveOut(std::vector<uint8_t>(17, 0)));
    }
    SECTION("NaN and infinities are never constant") {
        std::fill(field.begin(), field.end(), std::numeric_limits<float>::quiet_NaN());
        CHECK(bricks().constantCount(0) == 0);
        std::fill(field.begin(), field.end(), std::numeric_limits<float>::infinity());
        CHECK(bricks().constantCount(0) == 0);
    }
    SECTION("a volume of vec4 is constant where all four components are") {
        std::vector<glm::vec4> volume(field.size(), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        volume[voxelAt(res, 1, 5, 6)].w = 1.0001f;  // brick (0, 1, 1)
        ConstantBricks b(res);
        b.addVolume(EK_GRADIENT_SLOT, volume.data());
        CHECK(b.constantCount(EK_GRADIENT_SLOT) == 17);
        CHECK(!constantAt(b, EK_GRADIENT_SLOT, 0, 1, 1));
        CHECK_THROWS(b.addVolume(EK_GRADIENT_SLOT, volume.data()));  // each slot once
    }
}

TEST_CASE("a sample in a constant brick is the sample of its eight corners, to the bit",
          "[constant_bricks]") {
    const glm::ivec3 res(21, 14, 17);
    const size_t voxels = size_t(res.x) * size_t(res.y) * size_t(res.z);
    // Blocks of 6 voxels an edge, each of one value, some of them noise: constant bricks inside
    // the blocks, and bricks across their faces and in the noise that are not.
    std::mt19937 random(7);
    std::uniform_real_distribution<float> value(-2.0f, 2.0f);
    std::vector<float> field(voxels);
    std::vector<glm::vec4> gradient(voxels);
    std::vector<float> blockValue(64);
    for (float& v : blockValue) v = value(random);
    for (int z = 0; z < res.z; ++z)
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x) {
                const int block = (x / 6 + 4 * (y / 6) + 16 * (z / 6)) % 64;
                const bool noise = block % 5 == 0;
                const float v = noise ? value(random) : blockValue[size_t(block)];
                field[voxelAt(res, x, y, z)] = v;
                gradient[voxelAt(res, x, y, z)] =
                    noise ? glm::vec4(value(random)) : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f + v * v);
            }
    eikon::shared::GpuViewParams params{};
    params.resolution = glm::ivec4(res, 0);
    eikon::shared::VolumeAccessCpu fetched{params};
    fetched.fields[0] = field.data();
    fetched.gradient = gradient.data();
    eikon::shared::VolumeAccessCpu shortcut = fetched;
    ConstantBricks bricks(res);
    bricks.addField(0, field.data());
    bricks.addVolume(EK_GRADIENT_SLOT, gradient.data());
    shortcut.constantBricks = &bricks;
    REQUIRE(bricks.constantCount(0) > 0);
    REQUIRE(bricks.constantCount(0) < bricks.mask.size());

    // Anywhere in the volume and a little around it (clamped to its faces), and on voxel centres.
    std::uniform_real_distribution<float> px(-2.0f, float(res.x) + 2.0f);
    std::uniform_real_distribution<float> py(-2.0f, float(res.y) + 2.0f);
    std::uniform_real_distribution<float> pz(-2.0f, float(res.z) + 2.0f);
    int mismatches = 0;
    int taken = 0;
    for (int i = 0; i < 200000; ++i) {
        glm::vec3 p(px(random), py(random), pz(random));
        if (i % 4 == 0) p = glm::floor(p) + glm::vec3(0.5f);
        for (const int slot : {0, EK_GRADIENT_SLOT}) {
            const glm::vec4 full = fetched.sampleVolume(slot, p);
            const glm::vec4 fast = shortcut.sampleVolume(slot, p);
            if (!sameBits(full, fast)) ++mismatches;
            glm::vec4 c;
            const glm::ivec3 corner = glm::clamp(glm::ivec3(glm::floor(p - glm::vec3(0.5f))),
                                                 glm::ivec3(0), res - glm::ivec3(1));
            if (shortcut.constantBrickValue(slot, corner, c)) ++taken;
        }
    }
    CHECK(mismatches == 0);
    CHECK(taken > 20000);  // the shortcut was taken, tens of thousands of times
}

TEST_CASE("a grey κ's one exp and the isotropic phase function give the per-channel floats",
          "[constant_bricks]") {
    eikon::shared::GpuViewParams params{};
    eikon::shared::ViewKernelCpu view{{params}};
    eikon::shared::PhotonKernelCpu photons{{params}};
    std::vector<float> kappas = {0.0f, -0.0f, 1e-30f, 1e-7f, 1e-5f, 0.3f, 1.75f, 40.0f, 1e6f};
    std::vector<float> lengths = {0.0f, 1e-6f, 0.01875f, 0.5f, 3.0f, 1e4f};
    std::mt19937 random(11);
    std::uniform_real_distribution<float> spread(0.0f, 8.0f);
    for (int i = 0; i < 2000; ++i) {
        kappas.push_back(std::exp2(spread(random) * 4.0f - 24.0f));
        lengths.push_back(std::exp2(spread(random) * 2.0f - 10.0f));
    }
    int mismatches = 0;
    for (size_t i = 0; i < kappas.size(); ++i) {
        const float k = kappas[i];
        const glm::vec3 kappa(k);
        for (size_t j = i % 7; j < lengths.size(); j += 7) {
            const float s = lengths[j];
            // What the GPU computes (the #else paths): each channel on its own. The step's
            // weight is (1 − e^(−κs)) / κ with its own exp, as it was written before it took the
            // step's decay.
            const glm::vec3 decay = glm::exp(-kappa * s);
            const float weight =
                k * s > 1e-5f ? (1.0f - std::exp(-k * s)) / k : s * (1.0f - 0.5f * k * s);
            const glm::vec3 weights(weight);
            const glm::vec3 integrals(photons.photonDecayIntegral(k, s),
                                      photons.photonDecayIntegral(k, s),
                                      photons.photonDecayIntegral(k, s));
            if (!sameBits(view.channelDecay(kappa, s), decay)) ++mismatches;
            if (!sameBits(view.stepWeights(kappa, s, view.channelDecay(kappa, s)), weights))
                ++mismatches;
            if (!sameBits(photons.photonDecayIntegrals(kappa, s), integrals)) ++mismatches;
        }
    }
    CHECK(mismatches == 0);
    // Not grey: each channel its own, as on the GPU.
    const glm::vec3 coloured(1.8f, 1.75f, 1.7f);
    CHECK(sameBits(view.channelDecay(coloured, 0.3f), glm::exp(-coloured * 0.3f)));
    glm::vec3 colouredWeights;
    for (int c = 0; c < 3; ++c)
        colouredWeights[c] = (1.0f - std::exp(-coloured[c] * 0.3f)) / coloured[c];
    CHECK(sameBits(view.stepWeights(coloured, 0.3f, view.channelDecay(coloured, 0.3f)),
                   colouredWeights));

    // phaseHG as the GPU computes it, for g = ±0 and every cosine.
    const auto phaseAsWritten = [](float g, float cosTheta) {
        const float d = 1.0f + g * g - 2.0f * g * cosTheta;
        return (1.0f - g * g) / (4.0f * eikon::shared::VolumeAccessCpu::EK_PI * d * std::sqrt(d));
    };
    int phaseMismatches = 0;
    for (const float g : {0.0f, -0.0f}) {
        for (int i = -1000; i <= 1000; ++i) {
            const float c = float(i) / 1000.0f;
            if (!sameBits(view.phaseHG(g, c), phaseAsWritten(g, c))) ++phaseMismatches;
        }
        CHECK(std::isnan(view.phaseHG(g, std::numeric_limits<float>::quiet_NaN())));
        // 2 × 0 × ∞ is a NaN in the formula: the shortcut must not hide it.
        CHECK(std::isnan(view.phaseHG(g, std::numeric_limits<float>::infinity())));
    }
    CHECK(phaseMismatches == 0);
    CHECK(sameBits(view.phaseHG(0.3f, 0.25f), phaseAsWritten(0.3f, 0.25f)));
}

TEST_CASE("constant bricks give the pictures and the photons of every corner fetched, to the bit",
          "[constant_bricks][view]") {
    CHECK(eikon::test::casesChangedBySwitch("EIKON_CONSTANT_BRICKS") == std::vector<std::string>{});
}
