#pragma once
// The smoke solver: a MAC grid over a box, stepped at the scene's frame rate in substeps chosen
// from a CFL number by the SimulationClock. Each substep advects (advection.h), injects the
// sources, applies the forces (smoke_forces.h) and projects (pressure_solver.h), so that the
// velocity it leaves is divergence-free. A blow-up (NaN or infinity in a field, a CFL far beyond
// the set maximum, a pressure solve that does not converge) throws eikon::Error naming the step,
// the field and the cell.
#include <functional>
#include <string>
#include <vector>

#include "core/mesh_voxelize.h"
#include "sim/advection.h"
#include "sim/clock.h"
#include "sim/mac_grid.h"
#include "sim/mass_correction.h"
#include "sim/pressure_solver.h"
#include "sim/smoke_forces.h"
#include "sim/smoke_shape.h"

namespace eikon::sim {

struct SmokeSource {
    SmokeShape shape;
    float densityRate = 1.0f;      // density added per second inside the shape
    float temperatureRate = 0.0f;  // degrees added per second
    // Inside the shape the face velocities are pulled toward this one at `velocityRate` per
    // second (a rate ≥ 1/dt sets them outright).
    glm::vec3 velocity{0.0f};
    float velocityRate = 0.0f;
};

struct SmokeSettings {
    Domain domain;
    double fps = 24.0;
    // The scene frame the first advanceFrame() produces: frame f's substeps run from the time of
    // frame f − 1 to the time of frame f on the clock (SimulationClock::timeOfSubstep).
    int firstFrame = 0;
    double maxCfl = 1.0;  // substeps per frame keep max speed·dt/h at or below this
    // More substeps than this in one frame means the velocity exploded, not that the scene is
    // fast: the frame throws rather than grinding through thousands of steps.
    int maxSubsteps = 64;
    AdvectionSettings advection;
    // Put back the density advection loses or gains (mass_correction.h), within the range the
    // density had before the step. Off by default: it changes where smoke is, a little,
    // everywhere.
    bool conserveMass = false;
    ForceSettings forces;
    PressureSettings pressure;
};

// Wall-clock time per stage and the pressure solve's effort, summed over substeps.
struct SmokeStepStats {
    int substeps = 0;
    double advectionMs = 0.0;
    double forcesMs = 0.0;  // sources and body forces
    double projectionMs = 0.0;
    int cgIterations = 0;     // summed over substeps
    int maxCgIterations = 0;  // of any one substep
    double cgResidual = 0.0;  // the largest relative residual of any substep
    double cfl = 0.0;         // max speed·dt/h of the substeps
    // With conserveMass: advection's relative density deficit, (target − advected)/target, and
    // what the bounds left uncorrected, remainder/target; of the substep where each is largest
    // in magnitude (signed). Zero when conserveMass is off.
    double massDeficit = 0.0;
    double massRemainder = 0.0;

    void add(const SmokeStepStats& o);
};

// Moves or changes the sources for a substep: called by advanceFrame() before each substep with
// the time in seconds at which that substep ends (the sources are injected as of that time). It
// must depend on nothing but the time, so that a frame is the same however the run was cut.
using SourceUpdate = std::function<void(double seconds, std::vector<SmokeSource>& sources)>;

class SmokeSolver {
public:
    explicit SmokeSolver(const SmokeSettings& settings);

    void addSource(const SmokeSource& source) { sources_.push_back(source); }
    // Keyframed sources (sim/smoke_from_scene.h builds one from a scene's tracks).
    void setSourceUpdate(SourceUpdate update) { sourceUpdate_ = std::move(update); }
    const std::vector<SmokeSource>& sources() const { return sources_; }
    // Marks the cells whose centres lie inside the shape solid (static obstacles).
    void addObstacle(const SmokeShape& shape);
    // Marks solid the cells whose centres a voxelized mesh holds (core/mesh_voxelize.h, on this
    // grid's cells); throws eikon::Error if the bits are of another resolution.
    void addObstacle(const InsideBits& inside);

    // One frame of 1/fps seconds in as many substeps as the CFL number asks, the sources updated
    // before each.
    SmokeStepStats advanceFrame();
    // One substep of dt seconds with the sources as they are.
    SmokeStepStats step(float dt);

    const SmokeSettings& settings() const { return settings_; }
    const MacGrid& grid() const { return grid_; }
    MacGrid& grid() { return grid_; }     // initial conditions, tests
    int frame() const { return frame_; }  // frames stepped so far
    int stepCount() const { return steps_; }

private:
    void injectSources(float dt);
    // Zero velocity on solid faces, no smoke inside solids.
    void enforceSolids();
    // Throws eikon::Error if any field holds a NaN or infinity after `stage`.
    void checkFinite(const char* stage) const;
    // The substeps a frame needs at the current velocity; throws eikon::Error, a blow-up, when
    // the velocity is not finite or needs more than maxSubsteps.
    int substepsForNextFrame(const char* stage) const;
    std::string where(const char* stage) const;

    SmokeSettings settings_;
    SimulationClock clock_;
    MacGrid grid_;
    std::vector<SmokeSource> sources_;
    SourceUpdate sourceUpdate_;
    int frame_ = 0;
    int steps_ = 0;
};

}  // namespace eikon::sim
