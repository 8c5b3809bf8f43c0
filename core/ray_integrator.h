#pragma once
// How a curved ray is stepped through the ray equation (shaders/shared/ray_equation.h): the
// integrators a scene names for view rays (render.integrator) and photons
// (render.light_transport.photons.integrator). The values are the shaders' EK_RAY_* (render checks
// that they agree).
#include <string>
#include <vector>

namespace eikon {

enum class RayIntegrator { Euler = 0, Midpoint = 1, Rk4 = 2, Verlet = 3 };

// "euler", "midpoint", "rk4", "verlet": the names scenes use, in the enum's order.
const std::vector<std::string>& rayIntegratorNames();
const std::string& rayIntegratorName(RayIntegrator integrator);
// The integrator called `name`, one of rayIntegratorNames().
RayIntegrator rayIntegratorNamed(const std::string& name);

}  // namespace eikon
