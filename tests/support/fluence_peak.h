#pragma once
// Where a sampled profile peaks, to a fraction of a sample: the brightest point of a caustic
// along a column of voxels. Shared by the lens tests.
#include <functional>

namespace eikon::test {

// The position, in samples, of the maximum of at(i) over i in [lo, hi], refined by the parabola
// through it and its neighbours (a smooth peak, as the 3×3×3 photon smoothing leaves it). The
// maximum must lie strictly inside the range: `interior` is set false otherwise and the integer
// index returned.
inline double refinedPeak(const std::function<double(int)>& at, int lo, int hi, bool& interior) {
    int best = lo;
    for (int i = lo; i <= hi; ++i)
        if (at(i) > at(best)) best = i;
    interior = best > lo && best < hi;
    if (!interior) return double(best);
    const double a = at(best - 1), b = at(best), c = at(best + 1);
    return double(best) + 0.5 * (a - c) / (a - 2.0 * b + c);  // offset within ±0.5
}

}  // namespace eikon::test
