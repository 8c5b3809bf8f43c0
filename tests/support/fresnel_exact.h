#pragma once
// The unpolarized Fresnel reflectance in double, as a reference for shaders/shared/fresnel.h:
// Snell's law and Fresnel's equations in their sine and tangent forms (not the cosine form the
// shared code uses), so that the two share no formula.
#include <cmath>

namespace eikon::test {

// R for unpolarized light from index n1 into n2 at incidence θi (radians); 1 past the critical
// angle.
inline double fresnelExact(double n1, double n2, double thetaI) {
    if (thetaI == 0.0) return std::pow((n1 - n2) / (n1 + n2), 2);
    const double sinT = n1 / n2 * std::sin(thetaI);
    if (sinT >= 1.0) return 1.0;
    const double thetaT = std::asin(sinT);
    const double rs = std::sin(thetaI - thetaT) / std::sin(thetaI + thetaT);
    const double rp = std::tan(thetaI - thetaT) / std::tan(thetaI + thetaT);
    return 0.5 * (rs * rs + rp * rp);
}

}  // namespace eikon::test
