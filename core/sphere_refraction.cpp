#include "core/sphere_refraction.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace eikon {

bool refractSnell(const glm::dvec3& d, const glm::dvec3& nrm, double eta, glm::dvec3& out) {
    const double cosI = -glm::dot(d, nrm);
    const double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
    if (k < 0.0) return false;
    out = glm::normalize(eta * d + (eta * cosI - std::sqrt(k)) * nrm);
    return true;
}

bool refractDownThroughSphere(const glm::dvec3& centre, double radius, double ior, double x,
                              double z, glm::dvec3& exitPoint, glm::dvec3& exitDir) {
    const double r2 = (x * x + z * z) / (radius * radius);
    if (!(r2 < 1.0)) return false;
    const glm::dvec3 p1 = centre + glm::dvec3(x, radius * std::sqrt(1.0 - r2), z);
    const glm::dvec3 n1 = (p1 - centre) / radius;
    glm::dvec3 inside;
    if (!refractSnell(glm::dvec3(0.0, -1.0, 0.0), n1, 1.0 / ior, inside)) return false;
    // The second intersection from inside: p1 + s t with |p − centre| = radius, s = −2 n1·t R.
    exitPoint = p1 - 2.0 * radius * glm::dot(n1, inside) * inside;
    return refractSnell(inside, -(exitPoint - centre) / radius, ior, exitDir);
}

}  // namespace eikon
