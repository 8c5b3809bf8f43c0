#include "core/exact_ray.h"

#include <algorithm>

namespace eikon {
namespace {

bool inside(const Bounds3& box, const glm::dvec3& x) {
    return x.x >= box.min.x && x.y >= box.min.y && x.z >= box.min.z && x.x <= box.max.x &&
           x.y <= box.max.y && x.z <= box.max.z;
}

// The fraction t in (0, 1] of the chord a → b (a inside) at which it leaves the box.
double exitFraction(const Bounds3& box, const glm::dvec3& a, const glm::dvec3& b) {
    double t = 1.0;
    for (int k = 0; k < 3; ++k) {
        const double d = b[k] - a[k];
        if (d > 0.0 && b[k] > double(box.max[k])) t = std::min(t, (double(box.max[k]) - a[k]) / d);
        if (d < 0.0 && b[k] < double(box.min[k])) t = std::min(t, (double(box.min[k]) - a[k]) / d);
    }
    return std::max(t, 0.0);
}

glm::dvec3 force(const IndexField& field, const glm::dvec3& x) {
    const glm::dvec4 g = field(x);
    return g.w * glm::dvec3(g);
}

}  // namespace

ExactRayEnd traceExactRay(const IndexField& field, const Bounds3& box, glm::dvec3 x, glm::dvec3 v,
                          double ds, int maxSteps) {
    ExactRayEnd end;
    for (int i = 0; i < maxSteps; ++i) {
        const glm::dvec4 g0 = field(x);
        if (!(g0.w > 0.0)) break;
        const double dtau = ds / g0.w;
        const glm::dvec3 f0 = g0.w * glm::dvec3(g0);
        const glm::dvec3 v2 = v + 0.5 * dtau * f0;
        const glm::dvec3 f2 = force(field, x + 0.5 * dtau * v);
        const glm::dvec3 v3 = v + 0.5 * dtau * f2;
        const glm::dvec3 f3 = force(field, x + 0.5 * dtau * v2);
        const glm::dvec3 v4 = v + dtau * f3;
        const glm::dvec3 f4 = force(field, x + dtau * v3);
        const glm::dvec3 next = x + dtau / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4);
        const glm::dvec3 vNext = v + dtau / 6.0 * (f0 + 2.0 * f2 + 2.0 * f3 + f4);
        if (!inside(box, next)) {
            const double t = exitFraction(box, x, next);
            end.position = x + t * (next - x);
            end.v = v + t * (vNext - v);
            end.left = true;
            return end;
        }
        x = next;
        v = vNext;
    }
    end.position = x;
    end.v = v;
    return end;
}

}  // namespace eikon
