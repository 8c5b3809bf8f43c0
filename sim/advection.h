#pragma once
// Advection of the smoke state through its velocity over one time step.
//
// Every scheme back-traces with second-order Runge–Kutta (midpoint) and samples trilinearly:
// - SemiLagrangian: one back-trace; first order, diffusive, unconditionally stable.
// - MacCormack (Selle et al. 2008): forward then backward semi-Lagrangian passes estimate the
//   error of the forward one and subtract half of it; second order in smooth regions.
// - Bfecc (Kim et al. 2005): the error estimate corrects the *input*, which is then advected again.
// The second-order schemes overshoot near steep gradients; a limiter keeps them in bounds:
// - Clamp: clamp the result to the range of the eight samples around the back-traced point.
// - Revert: where the result leaves that range, use the semi-Lagrangian value instead.
#include "sim/mac_grid.h"

namespace eikon::sim {

enum class AdvectionScheme { SemiLagrangian, MacCormack, Bfecc };
enum class Limiter { None, Clamp, Revert };

const char* schemeName(AdvectionScheme scheme);

struct AdvectionSettings {
    AdvectionScheme scheme = AdvectionScheme::MacCormack;
    Limiter limiter = Limiter::Revert;
};

// Advects `src` (any lattice: centres or faces) through the velocity of `flow` over dt seconds,
// writing `dst` (same lattice as src; it must not alias src).
void advectField(const MacGrid& flow, const Array3& src, Array3& dst, float dt,
                 const AdvectionSettings& settings);

// Advects density, temperature and the velocity itself through the velocity at the start of the
// step.
void advectState(MacGrid& grid, float dt, const AdvectionSettings& settings);

}  // namespace eikon::sim
