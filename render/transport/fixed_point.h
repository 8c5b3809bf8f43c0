#pragma once
// The fixed-point rule for deposits and totals that particle methods sum as 64-bit integers, so
// that any order of additions, on any thread count or GPU schedule, gives the same bits
// (render/transport/photons/photon_tracing.h says why the range is 2^40).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

namespace eikon {

// One quantum is 2^-40 of the emitted power crossing one voxel edge.
constexpr double kFixedPointRange = 1099511627776.0;  // 2^40

// The scale for sums of `power` × `length`; 0 where nothing was emitted.
inline double fixedPointScaleFor(double power, double length) {
    return power > 0.0 ? kFixedPointRange / (power * length) : 0.0;
}

// std::llround(x) for |x| ≤ 4e18 (and NaN), inline. The photon march converts six values a voxel
// it crosses, and the library call was 6 % of its time at 128³. Exact: int64_t(x) truncates
// toward zero; below 2^53 the fraction x − trunc(x) is exact in double, above it x is whole.
inline int64_t roundHalfAwayFromZero(double x) {
    if (!(std::abs(x) <= 4.0e18)) return std::llround(x);  // NaN and beyond: the library's answer
    const int64_t whole = int64_t(x);
    const double fraction = x - double(whole);
    return whole + (fraction >= 0.5 ? 1 : 0) - (fraction <= -0.5 ? 1 : 0);
}

// value · scale as a fixed-point integer, rounded half away from zero; clamped so that no input
// can make the conversion undefined (at the documented scale a single deposit never comes near
// it). shaders/fixed_point.glsl gives the GPU the same integer, bit for bit.
inline int64_t toFixedPoint(double value, double scale) {
    const double limit = 4.0e18;
    return roundHalfAwayFromZero(std::clamp(value * scale, -limit, limit));
}

inline double fromFixedPoint(int64_t q, double scale) {
    return scale > 0.0 ? double(q) / scale : 0.0;
}

// An int64 a shader kept as two's complement (low, high) uint words (shaders/fixed_point.glsl).
inline int64_t joinFixedWords(const uint32_t* words) {
    return int64_t(uint64_t(words[0]) | (uint64_t(words[1]) << 32));
}

// Rec. 709 luminance: the weight of the mean-direction channels.
inline double rec709Luminance(glm::dvec3 c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

}  // namespace eikon
