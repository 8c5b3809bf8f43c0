// Snell's law through a sharp sphere (core/sphere_refraction.h), the exact reference of the
// sampled sphere's photons: against the closed forms it must meet.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "core/sphere_refraction.h"

using namespace eikon;

TEST_CASE("Snell's law through a sphere: the axis goes straight, paraxial rays meet at the focus",
          "[optics]") {
    const glm::dvec3 centre(0.1, 0.5, -0.2);
    const double radius = 0.7;
    glm::dvec3 exitPoint, exitDir;
    // Straight through along the axis, out at the bottom.
    REQUIRE(refractDownThroughSphere(centre, radius, 1.5, 0.0, 0.0, exitPoint, exitDir));
    CHECK(glm::length(exitPoint - (centre - glm::dvec3(0.0, radius, 0.0))) < 1e-12);
    CHECK(glm::length(exitDir - glm::dvec3(0.0, -1.0, 0.0)) < 1e-12);
    // A paraxial ray crosses the axis at f = nR / (2(n − 1)) below the centre (to O(h²)).
    for (double ior : {1.5, 2.0}) {
        const double h = 1e-4 * radius;
        REQUIRE(refractDownThroughSphere(centre, radius, ior, h, 0.0, exitPoint, exitDir));
        const double t = -(exitPoint.x - centre.x) / exitDir.x;
        const double crossing = centre.y - (exitPoint.y + t * exitDir.y);
        CHECK(crossing == Approx(ior * radius / (2.0 * (ior - 1.0))).epsilon(1e-6));
    }
    // A marginal ray leaves on the sphere, unit length, and is bent toward the axis.
    REQUIRE(refractDownThroughSphere(centre, radius, 1.5, 0.6, 0.0, exitPoint, exitDir));
    CHECK(glm::length(exitPoint - centre) == Approx(radius).epsilon(1e-12));
    CHECK(glm::length(exitDir) == Approx(1.0).epsilon(1e-12));
    CHECK(exitDir.x < 0.0);
    // Outside the disk the ray misses: no answer.
    CHECK_FALSE(refractDownThroughSphere(centre, radius, 1.5, 0.5, 0.5, exitPoint, exitDir));
    // Total internal reflection at a surface seen from the dense side.
    glm::dvec3 out;
    CHECK_FALSE(refractSnell(glm::normalize(glm::dvec3(1.0, -0.3, 0.0)), glm::dvec3(0.0, 1.0, 0.0),
                             1.5, out));
    CHECK(refractSnell(glm::dvec3(0.0, -1.0, 0.0), glm::dvec3(0.0, 1.0, 0.0), 1.5, out));
}
