#pragma once
// Snell's law through a sharp glass sphere, in double: the exact reference that tests and benches
// hold a sampled sphere's photons against (issue 15). Refraction only, no reflection, as the
// POV-Ray peer's scene.
#include <glm/vec3.hpp>

namespace eikon {

// Refracts unit d at unit normal nrm (facing against d), eta = n1 / n2; false: total internal
// reflection.
bool refractSnell(const glm::dvec3& d, const glm::dvec3& nrm, double eta, glm::dvec3& out);

// A ray of unit direction d straight down (0, −1, 0) that enters the sphere (centre, radius, index
// ior in vacuum) at offset (x, z) from its axis, (x² + z²) < radius²: where it leaves and in
// which direction, refracted in and out. False where it does not get out (total internal
// reflection, which a sphere never causes for rays from outside, or a grazing ray).
bool refractDownThroughSphere(const glm::dvec3& centre, double radius, double ior, double x,
                              double z, glm::dvec3& exitPoint, glm::dvec3& exitDir);

}  // namespace eikon
