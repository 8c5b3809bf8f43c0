// resizeBilinear (render/image_resize.h), which enlarges the viewer's previews: a plane through
// the source's pixel centres comes back that plane at the output's centres (clamped to the
// outermost source centres), a constant comes back bit for bit, and bad sizes are refused.
#include <catch2/catch.hpp>

#include <algorithm>

#include "core/error.h"
#include "render/image_resize.h"

using eikon::Image;
using eikon::resizeBilinear;

namespace {

// A plane in image space (x, y in source pixels, centres at i + 0.5), different in each channel.
glm::vec4 plane(float x, float y) {
    return {0.25f + 0.5f * x - 0.125f * y, 2.0f - 0.25f * x + 0.75f * y, x + y, 1.0f - 0.0625f * x};
}

}  // namespace

TEST_CASE("resizeBilinear reproduces a plane between the outermost source centres",
          "[image][resize]") {
    const int w = 7, h = 5;
    Image source(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) source.at(x, y) = plane(float(x) + 0.5f, float(y) + 0.5f);
    // 4 times larger (the viewer's default preview), and a size that is not a multiple.
    for (const auto& [W, H] : {std::pair{28, 20}, std::pair{17, 11}}) {
        const Image out = resizeBilinear(source, W, H);
        REQUIRE(out.width == W);
        REQUIRE(out.height == H);
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                // The output centre in source pixels, held within the outermost centres.
                const float sx =
                    std::clamp((float(x) + 0.5f) * float(w) / float(W), 0.5f, float(w) - 0.5f);
                const float sy =
                    std::clamp((float(y) + 0.5f) * float(h) / float(H), 0.5f, float(h) - 0.5f);
                const glm::vec4 expected = plane(sx, sy), got = out.at(x, y);
                for (int c = 0; c < 4; ++c) CHECK(got[c] == Approx(expected[c]).margin(1e-5));
            }
    }
}

TEST_CASE("resizeBilinear keeps a constant and the same size bit for bit", "[image][resize]") {
    Image constant(3, 2);
    std::fill(constant.pixels.begin(), constant.pixels.end(), glm::vec4(0.1f, 0.2f, 0.3f, 0.7f));
    const Image larger = resizeBilinear(constant, 13, 9);
    for (const glm::vec4& p : larger.pixels) CHECK(p == constant.pixels[0]);
    Image ramp(4, 3);
    for (size_t i = 0; i < ramp.pixels.size(); ++i) ramp.pixels[i] = glm::vec4(float(i) * 0.1f);
    CHECK(resizeBilinear(ramp, 4, 3).pixels == ramp.pixels);
    // Down as well as up: a 1x1 output is the source's centre, bilinearly.
    CHECK(resizeBilinear(constant, 1, 1).pixels[0] == constant.pixels[0]);
}

TEST_CASE("resizeBilinear refuses an empty source or an empty size", "[image][resize]") {
    CHECK_THROWS_AS(resizeBilinear(Image(), 4, 4), eikon::Error);
    CHECK_THROWS_AS(resizeBilinear(Image(2, 2), 0, 4), eikon::Error);
    CHECK_THROWS_WITH(resizeBilinear(Image(2, 2), 3, -1), "resize: a size of 3x-1 has no pixels");
}
