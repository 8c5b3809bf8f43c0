#pragma once
// The medium whose paths are known in closed form (docs/methods.md, "Closed forms"): n² linear in
// y, n² = kN0² + kAlpha (y + 1) on the box [-1, 1]³. With the optical parameter dτ = ds/n a path is
// the parabola x(τ) = x0 + p0 τ + (∇n²/4) τ², p0 = n(x0)·dir. Shared by the curved view ray and
// photon tests.
#include <cmath>
#include <functional>

#include <glm/vec3.hpp>

namespace eikon::test {

// The parameter where a closed-form path at(t), starting inside the box [-1, 1]³ at t = 0, first
// leaves it: marched in steps of 1e-3 to the first point outside, then bisected to double
// precision. Shared by the closed-form media of the curved-ray tests.
inline double boxExitParameter(const std::function<glm::dvec3(double)>& at) {
    auto inside = [](glm::dvec3 x) {
        return std::abs(x.x) <= 1.0 && std::abs(x.y) <= 1.0 && std::abs(x.z) <= 1.0;
    };
    double lo = 0.0, hi = 1e-3;
    while (inside(at(hi))) lo = hi, hi += 1e-3;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (inside(at(mid)) ? lo : hi) = mid;
    }
    return lo;
}

constexpr float kN0 = 1.2f;     // n at y = -1
constexpr float kAlpha = 0.3f;  // d(n²)/dy

// The field f with n = 1 + f·(ior − 1) for a material of ior 2: f = n − 1.
inline float linearN2Field(glm::vec3 x) {
    return std::sqrt(kN0 * kN0 + kAlpha * (x.y + 1.0f)) - 1.0f;
}

// Where the path entering at x0 along unit `dir` leaves the box: marched in τ to the first exit,
// then bisected.
inline glm::dvec3 linearN2Exit(glm::dvec3 x0, glm::dvec3 dir) {
    const double n0 = std::sqrt(double(kN0) * kN0 + kAlpha * (x0.y + 1.0));
    const glm::dvec3 p0 = n0 * dir;
    const glm::dvec3 a(0.0, kAlpha / 4.0, 0.0);
    auto at = [&](double t) { return x0 + p0 * t + a * (t * t); };
    return at(boxExitParameter(at));
}

}  // namespace eikon::test
