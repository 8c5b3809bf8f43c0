// The tone map (shaders/shared/tone_map.h) through the PNG writer's entry point.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "render/image.h"

using eikon::Image;
using eikon::ToneCurve;

namespace {

// One pixel of grey value v through the tone map: the 8-bit sRGB red channel.
int toneMapped(float v, ToneCurve curve, float exposure = 0.0f) {
    Image image(1, 1);
    image.at(0, 0) = glm::vec4(v, v, v, 1.0f);
    return eikon::toneMapToSrgb8(image, exposure, curve)[0];
}

double srgb(double x) {
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

}  // namespace

TEST_CASE("linear tone map: exposure, clamp, sRGB", "[tone]") {
    CHECK(toneMapped(0.0f, ToneCurve::Linear) == 0);
    CHECK(toneMapped(0.5f, ToneCurve::Linear) == std::lround(255.0 * srgb(0.5)));  // 188
    CHECK(toneMapped(0.25f, ToneCurve::Linear, 1.0f) == toneMapped(0.5f, ToneCurve::Linear));
    CHECK(toneMapped(1.0f, ToneCurve::Linear) == 255);
    CHECK(toneMapped(7.0f, ToneCurve::Linear) == 255);  // clipped
}

TEST_CASE("filmic tone map: the ACES fit, monotonic, highlights roll off", "[tone]") {
    // Narkowicz's fit at x = 1: (2.51 + 0.03) / (2.43 + 0.59 + 0.14) = 0.8038.
    const double atOne = 2.54 / 3.16;
    CHECK(toneMapped(1.0f, ToneCurve::Filmic) == std::lround(255.0 * srgb(atOne)));
    CHECK(toneMapped(0.0f, ToneCurve::Filmic) == 0);
    // Highlights that the linear curve clips stay apart up to the fit's white point, x ≈ 7.24.
    CHECK(toneMapped(2.0f, ToneCurve::Filmic) < toneMapped(6.0f, ToneCurve::Filmic));
    CHECK(toneMapped(6.0f, ToneCurve::Filmic) < 255);
    CHECK(toneMapped(8.0f, ToneCurve::Filmic) == 255);
    int previous = -1;
    for (float v = 0.0f; v < 64.0f; v = v * 1.25f + 0.001f) {
        const int t = toneMapped(v, ToneCurve::Filmic);
        CHECK(t >= previous);
        previous = t;
    }
}

TEST_CASE("tone map: NaN and negative radiance show black", "[tone]") {
    for (ToneCurve curve : {ToneCurve::Linear, ToneCurve::Filmic}) {
        CHECK(toneMapped(std::numeric_limits<float>::quiet_NaN(), curve) == 0);
        CHECK(toneMapped(-3.0f, curve) == 0);
    }
}
