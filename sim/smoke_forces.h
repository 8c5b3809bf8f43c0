#pragma once
// Body forces on the smoke's face velocities, each integrated with forward Euler over dt.
#include <glm/vec3.hpp>

#include "sim/mac_grid.h"

namespace eikon::sim {

struct ForceSettings {
    // Buoyancy along +y: f = −alpha·density + beta·(T − ambientTemperature), per unit mass.
    float buoyancyAlpha = 0.1f;  // scene units/s² per unit density (smoke is heavier than air)
    float buoyancyBeta = 1.0f;   // scene units/s² per degree (hot air rises)
    float ambientTemperature = 0.0f;
    // Vorticity confinement strength ε (Fedkiw, Stam, Jensen 2001), dimensionless: the force is
    // ε·h·(N × ω) with N the unit gradient of |ω|. It restores swirls that advection smooths away.
    float vorticity = 0.0f;
    glm::vec3 wind{0.0f};  // a uniform acceleration, scene units/s²
};

void applyBuoyancy(MacGrid& grid, const ForceSettings& settings, float dt);
void applyVorticityConfinement(MacGrid& grid, float epsilon, float dt);
void applyWind(MacGrid& grid, glm::vec3 acceleration, float dt);

// All of the above that the settings switch on.
void applyForces(MacGrid& grid, const ForceSettings& settings, float dt);

}  // namespace eikon::sim
