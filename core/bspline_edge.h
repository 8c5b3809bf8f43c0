#pragma once
// The centred cubic B-spline B(x) (support [−2, 2], variance 1/3, its integer shifts sum to 1)
// as an edge filter: a curved surface's step, averaged along the normal with weight B(s/h)/h,
// sampled at voxel centres, is nearly band-limited, so trilinear ∇n of the samples does not
// alias into rings and crosses the way the voxel's box average (coverage) does (issue 15).
namespace eikon {

// ∫ B over (−∞, x]: 0 for x <= −2, 1/2 at 0, 1 for x >= 2.
double cubicBSplineCdf(double x);

// ∫ cubicBSplineCdf over (−∞, x] = ∫ max(x − s, 0) B(s) ds: 0 for x <= −2, x for x >= 2 (B's
// mean is 0). The response of the filter to a unit ramp, from which any piecewise-linear edge's
// filtered value follows.
double cubicBSplineRamp(double x);

}  // namespace eikon
