#pragma once
// A converging GRIN lens with its paraxial ray computed apart: the reference of the intensity-law
// tests (the wavefront's and the plane sweep's). n − 1 = w(y)·(Δ − r²/(2f)) within the aperture
// a, with a window w of ∫w dy = 1 around the plane y = yLens. A ray at r leaves it with
// sin θ = ∫∂n/∂r dy = −r/f, so a collimated beam travelling −y converges on the axis and its
// cross-section shrinks as r(z)²: E(z) = E0 (r0 / r(z))². In the thin-lens limit r(z)/r0 = 1 − z/f;
// this lens is 6 voxels thick with n up to 1.8, where rays slow to 1/n and move sideways less,
// which moves its principal plane 0.026 below the window's centre (0.8 voxels, 14 % of E at
// z = 3f/4). The reference is therefore the paraxial ray of the lens's own n, integrated in
// double precision in 10⁴ slices: dr/dy = p/n(y), dp/dy = −w(y) r/f (no grid, no RK4).
#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/vec3.hpp>

namespace eikon::test {

struct GrinLens {
    static constexpr int kRes = 63;  // odd: x = z = 0 runs through a column of voxel centres
    static constexpr double kVoxel = 2.0 / kRes;
    static constexpr float kFocal = 1.0f, kAperture = 0.4f, kLensY = 0.6f;
    static constexpr float kHalfWidth = 3.0f * float(kVoxel);
    static constexpr float kDelta = kAperture * kAperture / (2.0f * kFocal);

    double slope = 0.0, offset = 0.0;  // r(z)/r0 = offset + slope · z past the window

    GrinLens() {
        const int slices = 10000;
        const double dy = 2.0 * kHalfWidth / slices;
        double r = 1.0, p = 0.0;
        for (int i = 0; i < slices; ++i) {  // midpoint rule from the window's top down
            const double y = kLensY + kHalfWidth - (i + 0.5) * dy;
            const double n = 1.0 + window(y) * kDelta;
            const double rMid = r + 0.5 * dy * p / n;
            p -= dy * window(y) * rMid / kFocal;
            r += dy * p / n;
        }
        slope = p;  // n = 1 below the window: dr/dz = p
        offset = r - p * kHalfWidth;
    }

    static double window(double y) {
        const double u = (y - kLensY) / kHalfWidth;
        if (std::abs(u) >= 1.0) return 0.0;
        const double c = std::cos(0.5 * glm::pi<double>() * u);
        return c * c / kHalfWidth;  // ∫w dy = 1
    }

    // n − 1 at x, read with a material of ior 2.
    static float field(glm::vec3 x) {
        const float r2 = std::min(x.x * x.x + x.z * x.z, kAperture * kAperture);
        return float(window(x.y)) * (kDelta - r2 / (2.0f * kFocal));
    }

    // E/E0 on the axis at z below yLens, z past the window.
    double paraxialE(double z) const { return 1.0 / std::pow(offset + slope * z, 2); }
    // The paraxial focus, below yLens.
    double focus() const { return -offset / slope; }
};

}  // namespace eikon::test
