// The image metrics of eikon regress (render/image_metrics.h) against closed forms: SSIM of flat
// images is its luminance term alone, (2ab + C1) / (a² + b² + C1); PSNR of a uniform difference d
// is 10 log10(peak² / d²); and PNGs read back as written.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "render/image.h"
#include "render/image_metrics.h"
#include "support/test_paths.h"

using eikon::Image;

namespace {

Image flat(int w, int h, float value) {
    Image image(w, h);
    for (glm::vec4& p : image.pixels) p = glm::vec4(value, value, value, 1.0f);
    return image;
}

// A pattern with structure at several scales, in [0, 1].
Image pattern(int w, int h) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float v = 0.5f + 0.25f * std::sin(0.7f * x) * std::cos(0.3f * y) +
                            0.2f * float((x / 4 + y / 4) % 2);
            image.at(x, y) = glm::vec4(v, 0.8f * v, 0.6f * v, 1.0f);
        }
    return image;
}

}  // namespace

TEST_CASE("SSIM of flat images is the closed-form luminance term", "[image_metrics]") {
    const double c1 = 0.01 * 0.01;
    for (auto [a, b] : {std::pair{0.5f, 0.5f}, std::pair{0.5f, 0.4f}, std::pair{0.9f, 0.1f}}) {
        const double expected = (2.0 * a * b + c1) / (double(a) * a + double(b) * b + c1);
        CHECK(eikon::ssim(flat(20, 12, a), flat(20, 12, b)) == Approx(expected).epsilon(1e-6));
    }
}

TEST_CASE("SSIM is 1 for equal images, symmetric, and falls with noise", "[image_metrics]") {
    const Image a = pattern(40, 30);
    CHECK(eikon::ssim(a, a) == Approx(1.0).epsilon(1e-12));
    Image slight = a, strong = a;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const float noise = float((i * 7919u) % 13u) / 13.0f - 0.5f;
        slight.pixels[i] += glm::vec4(glm::vec3(0.02f * noise), 0.0f);
        strong.pixels[i] += glm::vec4(glm::vec3(0.3f * noise), 0.0f);
    }
    const double s1 = eikon::ssim(slight, a), s2 = eikon::ssim(strong, a);
    CHECK(s1 == Approx(eikon::ssim(a, slight)).epsilon(1e-12));
    CHECK(s1 < 1.0);
    CHECK(s2 < s1);
    CHECK(s1 > 0.9);
    CHECK(s2 < 0.85);
}

TEST_CASE("PSNR of a uniform difference is 10 log10(peak^2 / d^2)", "[image_metrics]") {
    CHECK(eikon::psnr(flat(8, 8, 0.6f), flat(8, 8, 0.5f), 1.0) ==
          Approx(20.0 * std::log10(1.0 / 0.1)).epsilon(1e-5));
    CHECK(eikon::psnr(flat(8, 8, 2.2f), flat(8, 8, 2.0f), 4.0) ==
          Approx(20.0 * std::log10(4.0 / 0.2)).epsilon(1e-5));
    CHECK(std::isinf(eikon::psnr(flat(8, 8, 0.5f), flat(8, 8, 0.5f), 1.0)));
    CHECK_THROWS_AS(eikon::psnr(flat(8, 8, 0.5f), flat(8, 6, 0.5f), 1.0), eikon::Error);
}

TEST_CASE("the difference heat map is black where equal and white at the largest difference",
          "[image_metrics]") {
    Image a = flat(4, 2, 0.5f), b = flat(4, 2, 0.5f);
    b.at(3, 1) = glm::vec4(0.9f, 0.5f, 0.5f, 1.0f);
    b.at(1, 0) = glm::vec4(0.5f, 0.3f, 0.5f, 1.0f);
    double largest = 0.0;
    const std::vector<unsigned char> rgb = eikon::differenceHeatMap(b, a, largest);
    CHECK(largest == Approx(0.4).epsilon(1e-6));
    CHECK(rgb[0] == 0);
    CHECK(rgb[(1 * 4 + 3) * 3] == 255);
    CHECK(rgb[(1 * 4 + 3) * 3 + 2] == 255);  // white
    CHECK(rgb[(0 * 4 + 1) * 3] == 255);      // half the largest: red, some yellow
    CHECK(rgb[(0 * 4 + 1) * 3 + 2] == 0);
}

TEST_CASE("a written PNG reads back as its 8-bit display values", "[image_metrics]") {
    const std::string dir = eikon::test::scratchDir("image_metrics_png");
    const Image a = pattern(17, 9);
    eikon::writePng(dir + "/a.png", a, 0.0f, eikon::ToneCurve::Linear);
    const Image back = eikon::readPng(dir + "/a.png");
    REQUIRE(back.width == 17);
    REQUIRE(back.height == 9);
    const std::vector<unsigned char> rgb = eikon::toneMapToSrgb8(a, 0.0f, eikon::ToneCurve::Linear);
    for (size_t i = 0; i < back.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) REQUIRE(back.pixels[i][c] == rgb[3 * i + size_t(c)] / 255.0f);
    CHECK_THROWS_WITH(eikon::readPng(dir + "/missing.png"), Catch::Contains("cannot open"));
    eikon::writePngRgb8(dir + "/b.png", 2, 1, {1, 2, 3, 4, 5, 6});
    std::string bytes;
    {
        std::FILE* f = std::fopen((dir + "/b.png").c_str(), "rb");
        char buf[4096];
        const size_t n = std::fread(buf, 1, sizeof buf, f);
        std::fclose(f);
        bytes.assign(buf, n / 2);  // cut in half
    }
    std::FILE* f = std::fopen((dir + "/cut.png").c_str(), "wb");
    std::fwrite(bytes.data(), 1, bytes.size(), f);
    std::fclose(f);
    CHECK_THROWS_WITH(eikon::readPng(dir + "/cut.png"), Catch::Contains("cannot read as PNG"));
}
