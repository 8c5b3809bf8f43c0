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

// The centre, in samples, of the run of samples around the maximum of at(i) over [lo, hi] that
// lie within `fraction` of it (0.005: half a percent), its ends interpolated linearly between
// samples. A narrow beam's focus is a plateau several samples long whose top differs by parts
// in 10⁴ from sample to sample; its highest sample is then noise, its centre is not. `interior`
// is false when the run touches the range's ends.
inline double plateauCentre(const std::function<double(int)>& at, int lo, int hi, double fraction,
                            bool& interior) {
    int best = lo;
    for (int i = lo; i <= hi; ++i)
        if (at(i) > at(best)) best = i;
    const double level = (1.0 - fraction) * at(best);
    int left = best, right = best;
    while (left > lo && at(left - 1) >= level) --left;
    while (right < hi && at(right + 1) >= level) ++right;
    interior = left > lo && right < hi;
    if (!interior) return 0.5 * double(left + right);
    // Where the profile crosses `level` between the run's ends and their outer neighbours.
    const double l = double(left) - (at(left) - level) / (at(left) - at(left - 1));
    const double r = double(right) + (at(right) - level) / (at(right) - at(right + 1));
    return 0.5 * (l + r);
}

}  // namespace eikon::test
