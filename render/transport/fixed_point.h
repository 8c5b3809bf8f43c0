#pragma once
// The fixed-point rule for deposits and totals that particle methods sum as 64-bit integers, so
// that any order of additions, on any thread count or GPU schedule, gives the same bits
// (render/transport/photons/photon_tracing.h says why the range is 2^40).
#include <cstdint>

#include <glm/vec3.hpp>

namespace eikon {

// One quantum is 2^-40 of the emitted power crossing one voxel edge.
constexpr double kFixedPointRange = 1099511627776.0;  // 2^40

// The scale for sums of `power` × `length`; 0 where nothing was emitted.
inline double fixedPointScaleFor(double power, double length) {
    return power > 0.0 ? kFixedPointRange / (power * length) : 0.0;
}

inline double fromFixedPoint(int64_t q, double scale) {
    return scale > 0.0 ? double(q) / scale : 0.0;
}

// Rec. 709 luminance: the weight of the mean-direction channels.
inline double rec709Luminance(glm::dvec3 c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

}  // namespace eikon
