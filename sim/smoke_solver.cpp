#include "sim/smoke_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "sim/sim_parallel.h"

namespace eikon::sim {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::string cellText(glm::ivec3 c) {
    return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ", " + std::to_string(c.z) +
           ")";
}

}  // namespace

void SmokeStepStats::add(const SmokeStepStats& o) {
    substeps += o.substeps;
    advectionMs += o.advectionMs;
    forcesMs += o.forcesMs;
    projectionMs += o.projectionMs;
    cgIterations += o.cgIterations;
    maxCgIterations = std::max(maxCgIterations, o.maxCgIterations);
    cgResidual = std::max(cgResidual, o.cgResidual);
    cfl = std::max(cfl, o.cfl);
    if (std::fabs(o.massDeficit) > std::fabs(massDeficit)) massDeficit = o.massDeficit;
    if (std::fabs(o.massRemainder) > std::fabs(massRemainder)) massRemainder = o.massRemainder;
}

SmokeSolver::SmokeSolver(const SmokeSettings& settings)
    : settings_(settings), clock_(settings.fps, settings.maxCfl), grid_(settings.domain) {
    if (settings.maxSubsteps < 1) throw Error("smoke settings", "maxSubsteps must be at least 1");
    if (!(settings.pressure.tolerance > 0.0) || settings.pressure.maxIterations < 1)
        throw Error("smoke settings", "the pressure tolerance and iteration cap must be positive");
}

void SmokeSolver::addObstacle(const SmokeShape& shape) {
    const glm::ivec3 n = grid_.resolution();
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i)
                if (shape.contains(grid_.domain.cellCenter(i, j, k)))
                    grid_.solid[grid_.cellIndex(i, j, k)] = 1;
    enforceSolids();
}

void SmokeSolver::addObstacle(const InsideBits& inside) {
    const glm::ivec3 n = grid_.resolution();
    if (inside.resolution != n) throw Error("smoke obstacle", "voxelized at another resolution");
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i)
                if (inside.inside(i, j, k)) grid_.solid[grid_.cellIndex(i, j, k)] = 1;
    enforceSolids();
}

std::string SmokeSolver::where(const char* stage) const {
    return "smoke step " + std::to_string(steps_) + " (frame " + std::to_string(frame_) + ", " +
           stage + ")";
}

void SmokeSolver::checkFinite(const char* stage) const {
    auto check = [&](const Array3& a, const std::string& name) {
        if (auto bad = a.firstNonFinite())
            throw Error(where(stage), "field '" + name + "' is " +
                                          std::to_string(a(bad->x, bad->y, bad->z)) + " at cell " +
                                          cellText(*bad) + ": the simulation blew up");
    };
    for (int a = 0; a < 3; ++a) check(grid_.velocity[std::size_t(a)], velocityComponentName(a));
    check(grid_.density, "density");
    check(grid_.temperature, "temperature");
}

void SmokeSolver::enforceSolids() {
    MacGrid& g = grid_;
    for (int axis = 0; axis < 3; ++axis) {
        Array3& face = g.velocity[std::size_t(axis)];
        const glm::ivec3 s = face.size();
        forEachSlab(s.z, [&](int k) {
            for (int j = 0; j < s.y; ++j)
                for (int i = 0; i < s.x; ++i)
                    if (g.faceIsSolid(axis, i, j, k)) face(i, j, k) = 0.0f;
        });
    }
    forEachSlab(g.resolution().z, [&](int k) {
        for (int j = 0; j < g.resolution().y; ++j)
            for (int i = 0; i < g.resolution().x; ++i)
                if (g.isSolid(i, j, k)) {
                    g.density(i, j, k) = 0.0f;
                    g.temperature(i, j, k) = settings_.forces.ambientTemperature;
                }
    });
}

void SmokeSolver::injectSources(float dt) {
    MacGrid& g = grid_;
    for (const SmokeSource& src : sources_) {
        forEachSlab(g.resolution().z, [&](int k) {
            for (int j = 0; j < g.resolution().y; ++j)
                for (int i = 0; i < g.resolution().x; ++i)
                    if (!g.isSolid(i, j, k) && src.shape.contains(g.domain.cellCenter(i, j, k))) {
                        g.density(i, j, k) += src.densityRate * dt;
                        g.temperature(i, j, k) += src.temperatureRate * dt;
                    }
        });
        if (src.velocityRate <= 0.0f) continue;
        const float blend = std::min(1.0f, src.velocityRate * dt);
        for (int axis = 0; axis < 3; ++axis) {
            Array3& face = g.velocity[std::size_t(axis)];
            const glm::ivec3 s = face.size();
            forEachSlab(s.z, [&](int k) {
                for (int j = 0; j < s.y; ++j)
                    for (int i = 0; i < s.x; ++i) {
                        const glm::vec3 p = g.domain.worldFromIndex(face.position(i, j, k));
                        if (src.shape.contains(p))
                            face(i, j, k) += blend * (src.velocity[axis] - face(i, j, k));
                    }
            });
        }
    }
}

SmokeStepStats SmokeSolver::step(float dt) {
    SmokeStepStats stats;
    stats.substeps = 1;
    checkFinite("start");
    stats.cfl = double(grid_.maxSpeed()) * dt / grid_.domain.voxelSize;

    Clock::time_point t0 = Clock::now();
    // The mass the step should keep: what there is, less what the velocity at the start of the
    // step carries out through open walls (advection uses that velocity too).
    FieldRange range;
    double targetMass = 0.0;
    if (settings_.conserveMass) {
        range = fluidRange(grid_, grid_.density);
        targetMass = std::max(
            0.0, fluidMass(grid_, grid_.density) - openWallOutflow(grid_, grid_.density, dt));
    }
    advectState(grid_, dt, settings_.advection);
    enforceSolids();
    if (settings_.conserveMass) {
        const MassCorrection m = correctMass(grid_, grid_.density, targetMass, range);
        stats.massDeficit = m.relativeDeficit();
        stats.massRemainder = m.relativeRemainder();
    }
    stats.advectionMs = msSince(t0);
    checkFinite("advection");

    t0 = Clock::now();
    injectSources(dt);
    applyForces(grid_, settings_.forces, dt);
    enforceSolids();
    stats.forcesMs = msSince(t0);
    checkFinite("forces");

    t0 = Clock::now();
    const PressureResult p = project(grid_, settings_.pressure);
    stats.projectionMs = msSince(t0);
    stats.cgIterations = stats.maxCgIterations = p.iterations;
    stats.cgResidual = p.residual;
    if (!p.converged)
        throw Error(where("projection"),
                    "field 'pressure' did not converge in " + std::to_string(p.iterations) +
                        " iterations: relative residual " + std::to_string(p.residual) +
                        " (tolerance " + std::to_string(settings_.pressure.tolerance) +
                        "), largest at cell " + cellText(p.worstCell));
    checkFinite("projection");
    ++steps_;
    return stats;
}

int SmokeSolver::substepsForNextFrame(const char* stage) const {
    glm::ivec3 fastest(0);
    const double speed = grid_.maxSpeed(&fastest);
    if (!std::isfinite(speed)) checkFinite(stage);  // names the bad cell
    const int substeps = clock_.substepsFor(speed, grid_.domain.voxelSize);
    if (substeps > settings_.maxSubsteps)
        throw Error(where(stage),
                    "field 'velocity' reaches " + std::to_string(speed) +
                        " scene units/s near cell " + cellText(fastest) + ": CFL " +
                        std::to_string(speed / settings_.fps / grid_.domain.voxelSize) +
                        " per frame needs " + std::to_string(substeps) +
                        " substeps, more than the limit " + std::to_string(settings_.maxSubsteps) +
                        "; the simulation blew up");
    return substeps;
}

SmokeStepStats SmokeSolver::advanceFrame() {
    const int substeps = substepsForNextFrame("substep count");
    const float dt = float(clock_.frameDuration() / substeps);
    const int sceneFrame = settings_.firstFrame + frame_;
    SmokeStepStats total;
    for (int s = 0; s < substeps; ++s) {
        if (sourceUpdate_) sourceUpdate_(clock_.timeOfSubstep(sceneFrame, s, substeps), sources_);
        total.add(step(dt));
    }
    // A frame whose velocity the next frame could not step is a blow-up now, before anyone
    // publishes or writes it (a cache's last frame held velocities of 1e14 when this was
    // checked only at the next frame's start).
    substepsForNextFrame("end of frame");
    ++frame_;
    return total;
}

}  // namespace eikon::sim
