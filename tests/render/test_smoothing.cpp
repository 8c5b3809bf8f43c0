// The 3×3×3 binomial smoothing of radiance volumes: its weights, constants preserved at the
// faces, mass preserved inside, and the GPU against the CPU twin.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>

#include <epoxy/gl.h>

#include "render/gl_context.h"
#include "render/smoothing.h"
#include "render/volume_textures.h"

using namespace eikon;

namespace {

size_t at(glm::ivec3 res, int x, int y, int z) {
    return (size_t(z) * size_t(res.y) + size_t(y)) * size_t(res.x) + size_t(x);
}

unsigned makeTexture(glm::ivec3 res, const std::vector<glm::vec4>& data) {
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_3D, tex);
    glTexStorage3D(GL_TEXTURE_3D, 1, GL_RGBA32F, res.x, res.y, res.z);
    setVolumeSampling();
    if (!data.empty())
        glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, res.x, res.y, res.z, GL_RGBA, GL_FLOAT,
                        data.data());
    return tex;
}

}  // namespace

TEST_CASE("an impulse spreads with the binomial 1-2-1 weights, total mass is kept inside",
          "[smoothing]") {
    const glm::ivec3 res(7, 6, 5);
    std::vector<glm::vec4> v(size_t(res.x * res.y * res.z), glm::vec4(0.0f));
    v[at(res, 3, 3, 2)] = glm::vec4(64.0f, 128.0f, 0.0f, 1.0f);
    const auto s = smoothVolumeCpu(v, res);
    CHECK(s[at(res, 3, 3, 2)].x == Approx(8.0f));  // 64 · (2·2·2)/64
    CHECK(s[at(res, 4, 3, 2)].x == Approx(4.0f));  // 64 · (1·2·2)/64
    CHECK(s[at(res, 4, 4, 3)].x == Approx(1.0f));  // 64 · (1·1·1)/64
    CHECK(s[at(res, 5, 3, 2)].x == 0.0f);
    double total = 0.0;
    for (const auto& x : s) total += x.y;
    CHECK(total == Approx(128.0));  // away from the faces nothing is lost
}

TEST_CASE("a constant volume stays constant, faces included", "[smoothing]") {
    const glm::ivec3 res(5, 4, 3);
    const std::vector<glm::vec4> v(size_t(res.x * res.y * res.z),
                                   glm::vec4(0.5f, 1.0f, 2.0f, 3.0f));
    for (const auto& x : smoothVolumeCpu(v, res)) {
        CHECK(x.x == Approx(0.5f));
        CHECK(x.w == Approx(3.0f));
    }
}

TEST_CASE("the twin's interior shortcut gives the shared per-voxel sums, bit for bit",
          "[smoothing]") {
    const glm::ivec3 res(9, 6, 5);
    std::vector<glm::vec4> v(size_t(res.x) * size_t(res.y) * size_t(res.z));
    uint32_t state = 12345u;  // values over many binades, so that the order of the sums shows
    for (glm::vec4& x : v)
        for (int c = 0; c < 4; ++c) {
            state = state * 1664525u + 1013904223u;
            x[c] = float(state >> 8) * std::ldexp(1.0f, int(state % 40u) - 40);
        }
    const std::vector<glm::vec4> fast = smoothVolumeCpu(v, res);
    const std::vector<glm::vec4> perVoxel = smoothVolumePerVoxelCpu(v, res);
    REQUIRE(fast.size() == perVoxel.size());
    size_t differing = 0;
    for (size_t i = 0; i < fast.size(); ++i)
        for (int c = 0; c < 4; ++c)
            if (std::memcmp(&fast[i][c], &perVoxel[i][c], sizeof(float)) != 0) ++differing;
    CHECK(differing == 0);
}

TEST_CASE("GPU smoothing equals the CPU twin", "[smoothing][gpu]") {
    auto context = createHeadlessContext();
    const glm::ivec3 res(13, 9, 11);
    std::vector<glm::vec4> v(size_t(res.x * res.y * res.z));
    for (size_t i = 0; i < v.size(); ++i)  // a deterministic, uneven pattern
        v[i] = glm::vec4(float((i * 37) % 101), float((i * 53) % 97) * 0.01f, float(i % 7), 1.0f);
    const auto cpu = smoothVolumeCpu(v, res);
    const unsigned source = makeTexture(res, v);
    const unsigned target = makeTexture(res, {});
    VolumeSmootherGpu().smooth(source, target, res);
    std::vector<glm::vec4> gpu(v.size());
    glBindTexture(GL_TEXTURE_3D, target);
    glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_FLOAT, gpu.data());
    double worst = 0.0;
    for (size_t i = 0; i < v.size(); ++i)
        for (int c = 0; c < 4; ++c)
            worst = std::max(worst, double(std::abs(gpu[i][c] - cpu[i][c])) /
                                        std::max(1.0, double(std::abs(cpu[i][c]))));
    INFO("max relative |GPU - CPU| " << worst);
    CHECK(worst < 1e-6);
    glDeleteTextures(1, &source);
    glDeleteTextures(1, &target);
}
