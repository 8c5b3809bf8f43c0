#include "core/bspline_edge.h"

namespace eikon {
namespace {

// Σ_k (−1)^k C(4, k) (x + 2 − k)₊^p: B is this for p = 3 over 3!, its integrals for p = 4, 5
// over 4!, 5! (the truncated-power form of the cardinal B-spline).
double truncatedPowerSum(double x, int p) {
    constexpr double kBinomial[5] = {1.0, -4.0, 6.0, -4.0, 1.0};
    double sum = 0.0;
    for (int k = 0; k < 5; ++k) {
        const double t = x + 2.0 - double(k);
        if (t <= 0.0) break;
        double power = 1.0;
        for (int i = 0; i < p; ++i) power *= t;
        sum += kBinomial[k] * power;
    }
    return sum;
}

}  // namespace

double cubicBSplineCdf(double x) {
    if (x <= -2.0) return 0.0;
    if (x >= 2.0) return 1.0;
    // Symmetric about 0; the left half keeps the sum's terms few and its cancellation small.
    if (x > 0.0) return 1.0 - cubicBSplineCdf(-x);
    return truncatedPowerSum(x, 4) / 24.0;
}

double cubicBSplineRamp(double x) {
    if (x <= -2.0) return 0.0;
    if (x >= 2.0) return x;
    // ramp(x) − ramp(−x) = x for any filter with mean 0.
    if (x > 0.0) return x + cubicBSplineRamp(-x);
    return truncatedPowerSum(x, 5) / 120.0;
}

}  // namespace eikon
