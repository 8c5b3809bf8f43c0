#pragma once
// A reference trace of the ray equation d/ds(n dx/ds) = ∇n through a continuous index field, in
// double precision with classical RK4 at a small step: the "exact trace" the integrators of
// shaders/shared/ray_equation.h are measured against (`eikon bench integrators`). Same τ form:
// dx/dτ = v, dv/dτ = n∇n, v = n dx/ds.
#include <functional>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/bounds.h"

namespace eikon {

// xyz: ∇n; w: n, at a world point.
using IndexField = std::function<glm::dvec4(const glm::dvec3&)>;

struct ExactRayEnd {
    glm::dvec3 position{0.0};  // where the ray left the box (or stopped)
    glm::dvec3 v{0.0};         // n dx/ds there
    bool left = false;         // false: still inside after maxSteps, or n ≤ 0 on the way
};

// Traces from x (inside `box` or on its face) with v = n dx/ds, RK4 steps of arc length ds
// (Δτ = ds / n at each step's start), until the ray leaves the box: the exit point is where the
// last step's chord crosses the face (the chord is within ds² × curvature of the path).
ExactRayEnd traceExactRay(const IndexField& field, const Bounds3& box, glm::dvec3 x, glm::dvec3 v,
                          double ds, int maxSteps);

}  // namespace eikon
