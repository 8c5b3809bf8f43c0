#pragma once
// Pressure projection: makes the face velocities discretely divergence-free in every fluid cell,
// with no flow through solid faces (obstacles and closed walls) and p = 0 beyond open walls.
//
// The unknown is the scaled pressure p' = p·dt/(ρ·h), so that the update is u -= p'_b − p'_a
// across each face and the system is the 7-point Laplacian A p' = −h·(∇·u). It is solved by
// conjugate gradients preconditioned with MIC(0) (Bridson, "Fluid Simulation for Computer
// Graphics", ch. 5) or by a multigrid V-cycle (the default), in double precision. MIC(0)'s two
// triangular solves run serially in cell order; every other loop is slab-parallel, the
// multigrid's sweeps update one colour of cells from the other, and every dot product sums fixed
// blocks in a fixed order, so the result does not depend on the thread count.
#include <glm/vec3.hpp>

#include "sim/mac_grid.h"

namespace eikon::sim {

// What approximates A⁻¹ inside conjugate gradients: Bridson's MIC(0) (mic_preconditioner.h,
// serial triangular solves) or a geometric multigrid V-cycle (multigrid_preconditioner.h,
// parallel, fewer iterations on large grids).
enum class PressurePreconditioner { Mic0, Multigrid };

struct PressureSettings {
    // Stop when max |residual| ≤ tolerance · max |h·∇·u| before projecting: the residual is
    // exactly −h·∇·u after the update, so this bounds the divergence left, relative to what was.
    double tolerance = 1e-5;
    int maxIterations = 500;
    PressurePreconditioner preconditioner = PressurePreconditioner::Multigrid;
};

struct PressureResult {
    int iterations = 0;
    double initialDivergence = 0.0;  // max |h·∇·u| over fluid cells before, scene units/s
    double residual = 0.0;           // max |residual| / initialDivergence (0 when nothing to do)
    bool converged = true;
    glm::ivec3 worstCell{0};  // where the residual is largest
};

PressureResult project(MacGrid& grid, const PressureSettings& settings);

// max |h·∇·u| over the fluid cells (scene units/s), and where.
double maxDivergence(const MacGrid& grid, glm::ivec3* where = nullptr);

}  // namespace eikon::sim
