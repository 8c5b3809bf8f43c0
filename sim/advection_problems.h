#pragma once
// Advection problems whose exact answer is the initial field: a shape carried by a velocity that
// brings it back where it started. The tests (tests/sim/test_advection.cpp) check their errors;
// `eikon bench advection` times them against those errors. Both call these functions, so the
// benchmark measures exactly what the tests check.
//
// Every problem starts from a sharp indicator (1 inside the shape, 0 outside, sampled at cell
// centres) in a closed unit box, advects it at CFL 1 (with advectField(), or with whatever
// DensityAdvector it is given: the benchmark's OpenVDB peer) and compares.
#include "sim/advection.h"

namespace eikon::sim {

// An advection method as the problems drive it. Only advect() is timed; moving data in and out
// of the method's own representation is not, as setting the velocity is not.
class DensityAdvector {
public:
    virtual ~DensityAdvector() = default;
    // The initial density is in g.density.
    virtual void load(const MacGrid& g) { (void)g; }
    // g's face velocities changed (before every step).
    virtual void setVelocity(const MacGrid& g) { (void)g; }
    // One step of dt seconds through g's velocity.
    virtual void advect(MacGrid& g, float dt) = 0;
    // Leaves the final density in g.density.
    virtual void store(MacGrid& g) { (void)g; }
};

struct AdvectionProblemResult {
    int resolution = 0;  // cells along x (and y; z too unless a slab)
    int steps = 0;
    double l1 = 0.0;          // Σ|φ − φ₀| / Σφ₀ at the end
    double volumeLoss = 0.0;  // 1 − (cells with φ ≥ ½ at the end) / (at the start)
    double massChange = 0.0;  // Σφ / Σφ₀ − 1
    // Wall time of the advect calls alone (setting up and updating the velocity is left
    // out), summed over the steps. Measured, never checked: tests do not time anything.
    double advectionMs = 0.0;
};

// Zalesak's slotted disk (Zalesak 1979, scaled to the grid: the classic 100×100 set-up is a disk
// of radius 15 at (50, 75) with a slot 5 wide reaching up to y = 85), turned once about the
// box's centre by a solid rotation about z. Rotation has u(y), v(x) only, so it is divergence-free
// on the faces exactly.
// - Disk: an n×n×2 slab (a cylinder through it), cheap; what the unit tests use.
// - Sphere: an n³ box holding Enright et al.'s (2002) 3D version, a sphere of radius 0.15 at
//   (0.5, 0.75, 0.5) with the same slot cut through it along z.
// Steps: CFL 1 at 0.4 from the centre (the disk's far edge), so ⌈0.4·n·2π⌉ of them.
enum class ZalesakShape { Disk, Sphere };
AdvectionProblemResult zalesakRotation(int n, ZalesakShape shape,
                                       const AdvectionSettings& settings);
AdvectionProblemResult zalesakRotation(int n, ZalesakShape shape, DensityAdvector& advector);

// Enright et al.'s (2002) deformation test on an n³ box: a sphere of radius 0.15 at
// (0.35, 0.35, 0.35) in the velocity field
//   u = 2 sin²(πx) sin(2πy) sin(2πz) c(t),  v = −sin(2πx) sin²(πy) sin(2πz) c(t),
//   w = −sin(2πx) sin(2πy) sin²(πz) c(t),   c(t) = cos(πt/T),
// which stretches it into a thin sheet until T/2 and undoes that by t = T (T = 3 in the paper).
// The faces take the field at the middle of each step; the field is divergence-free in the
// continuum and O(h²) divergent on the faces, as everyone samples it. Steps: CFL 1 at the peak
// speed 2, so ⌈2·n·T⌉ of them.
AdvectionProblemResult enrightDeformation(int n, const AdvectionSettings& settings,
                                          double period = 3.0);
AdvectionProblemResult enrightDeformation(int n, DensityAdvector& advector, double period = 3.0);

}  // namespace eikon::sim
