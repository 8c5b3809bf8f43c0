// The particle traces' fixed-point rule (render/transport/fixed_point.h): the inline rounding
// must give std::llround's integer for every double the deposits can produce.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "render/transport/fixed_point.h"

using namespace eikon;

TEST_CASE("roundHalfAwayFromZero is std::llround, halves, binades and limits included",
          "[photons][fixed_point]") {
    // Halves and their neighbours, where the two rules could part.
    for (double whole = -6.0; whole <= 6.0; whole += 1.0)
        for (double x : {whole + 0.5, whole - 0.5, std::nextafter(whole + 0.5, 0.0),
                         std::nextafter(whole + 0.5, 10.0), std::nextafter(whole - 0.5, 0.0),
                         std::nextafter(whole - 0.5, -10.0), whole, -0.0})
            CHECK(roundHalfAwayFromZero(x) == std::llround(x));
    // Every binade from 2^-30 to 4e18, both signs, with fractions of every kind (bit patterns
    // from a hash), and the values that straddle 2^52, 2^53 and the clamp.
    uint64_t h = 0x243F6A8885A308D3ull;
    int mismatches = 0;
    for (int exponent = -30; exponent <= 61; ++exponent)
        for (int k = 0; k < 2000; ++k) {
            h = h * 6364136223846793005ull + 1442695040888963407ull;
            const double x =
                std::ldexp(1.0 + double(h >> 12) * 0x1p-52, exponent) * ((h & 1) ? -1.0 : 1.0);
            if (std::abs(x) > 4.0e18) continue;
            mismatches += roundHalfAwayFromZero(x) != std::llround(x);
        }
    CHECK(mismatches == 0);
    for (double x : {0x1p52 + 0.5, 0x1p52 - 0.5, 0x1p53 - 1.0, 0x1p53 + 2.0, 4.0e18, -4.0e18})
        CHECK(roundHalfAwayFromZero(x) == std::llround(x));
    CHECK(roundHalfAwayFromZero(std::numeric_limits<double>::quiet_NaN()) ==
          std::llround(std::numeric_limits<double>::quiet_NaN()));
    CHECK(toFixedPoint(1e300, 1.0) == int64_t(4.0e18));
    CHECK(toFixedPoint(-2.5, 1.0) == -3);
}
