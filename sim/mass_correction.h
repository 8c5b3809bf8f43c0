#pragma once
// Mass correction for advection that does not conserve mass (scene key
// `simulation.conserve_mass`, docs/scene-format.md#simulation).
//
// Trilinear semi-Lagrangian advection redistributes interpolation weights unevenly where the flow
// strains, and the limiters of the second-order schemes clip their undershoots: in a closed box
// the total density drifts by 1e-3…1e-1 over a few dozen steps (tests/sim/test_advection.cpp).
// After advection, this puts the deficit back (or takes the surplus away) globally, in proportion
// to each cell's excess over the pre-step minimum:
//
//     ρ' = lo + min(hi − lo, s · (ρ − lo))
//
// with one factor s for the whole field, chosen so that Σρ' equals the target. Why this form:
// - it keeps every cell inside [lo, hi], the range before the step (what the limiters keep), so
//   the correction never breaks a bound the scheme respects and never makes density negative
//   (lo is never below 0);
// - clean air (ρ = lo) stays clean: no smoke appears where there was none;
// - it is a one-parameter change, so the step statistics can report it as a single number.
// Where the cap hi leaves no room (or no cell holds any excess) the rest is not placed and is
// reported as the remainder rather than forced. The factor s is found by water-filling
// (cells that reach the cap are frozen, the rest rescaled), which approaches the exact s from
// below, so a pass limit can only under-correct, never overshoot a bound.
//
// Sums are taken in a fixed block order (sim_parallel.h), so the result is the same whatever the
// thread count.
#include "sim/mac_grid.h"

namespace eikon::sim {

// The smallest and largest value of `field` over the fluid (non-solid) cells.
struct FieldRange {
    float lo = 0.0f;
    float hi = 0.0f;
};
FieldRange fluidRange(const MacGrid& grid, const Array3& field);

// Σ field over the fluid cells, in a fixed order.
double fluidMass(const MacGrid& grid, const Array3& field);

// The net amount of a cell-centred field that leaves through the open walls in dt seconds at the
// grid's current velocity: Σ u_n·dt/h · ρ(boundary cell) over open boundary faces, first order
// upwind with the zero-gradient extrapolation that advection uses outside the box (what flows in
// carries the boundary cell's value). Zero for a closed box.
double openWallOutflow(const MacGrid& grid, const Array3& field, float dt);

struct MassCorrection {
    double target = 0.0;     // the total the step should have left
    double advected = 0.0;   // the total advection left, before the correction
    double placed = 0.0;     // what the correction added (> 0) or removed (< 0)
    double remainder = 0.0;  // target − total after: what the bounds did not allow
    double factor = 1.0;     // s above

    // (target − advected) / target: the advection's relative deficit this step (0 if no mass).
    double relativeDeficit() const;
    // remainder / target.
    double relativeRemainder() const;
};

// Moves the total of `field` over the fluid cells to `target` as described above, within
// [range.lo, range.hi] (lo is raised to 0 if below). Cells already outside that range (an
// unlimited scheme's overshoots) are left as they are.
MassCorrection correctMass(const MacGrid& grid, Array3& field, double target, FieldRange range);

}  // namespace eikon::sim
