#include "sim/smoke_from_scene.h"

#include <memory>
#include <optional>

#include "core/error.h"
#include "core/level_set.h"
#include "core/mesh_placement.h"
#include "core/mesh_voxelize.h"
#include "sim/animation.h"
#include "sim/refractive_mesh.h"

namespace eikon::sim {
namespace {

SmokeShape shapeFrom(const SimShapeSpec& s) {
    return s.kind == SimShapeSpec::Kind::Sphere ? SmokeShape::sphere(s.center, s.radius)
                                                : SmokeShape::box(s.boxMin, s.boxMax);
}

AdvectionScheme schemeFrom(SimAdvection a) {
    switch (a) {
        case SimAdvection::SemiLagrangian:
            return AdvectionScheme::SemiLagrangian;
        case SimAdvection::MacCormack:
            return AdvectionScheme::MacCormack;
        case SimAdvection::Bfecc:
            return AdvectionScheme::Bfecc;
    }
    return AdvectionScheme::MacCormack;
}

Limiter limiterFrom(SimLimiter l) {
    switch (l) {
        case SimLimiter::None:
            return Limiter::None;
        case SimLimiter::Clamp:
            return Limiter::Clamp;
        case SimLimiter::Revert:
            return Limiter::Revert;
    }
    return Limiter::Revert;
}

}  // namespace

SmokeSettings smokeSettingsFrom(const SmokeSimulationSpec& spec, double fps) {
    SmokeSettings s;
    s.domain.resolution = spec.resolution;
    s.domain.voxelSize = spec.voxelSize;
    s.domain.origin = spec.domain.min;
    for (std::size_t f = 0; f < 6; ++f) {
        s.domain.walls[f] = spec.walls[f] == SimWall::Open ? Wall::Open : Wall::Closed;
    }
    s.fps = fps;
    s.maxCfl = spec.cfl;
    s.maxSubsteps = spec.maxSubsteps;
    s.advection = {schemeFrom(spec.advection), limiterFrom(spec.limiter)};
    s.conserveMass = spec.conserveMass;
    s.forces.buoyancyAlpha = spec.buoyancyAlpha;
    s.forces.buoyancyBeta = spec.buoyancyBeta;
    s.forces.ambientTemperature = spec.ambientTemperature;
    s.forces.vorticity = spec.vorticity;
    s.forces.wind = spec.wind;
    s.pressure.tolerance = spec.pressureTolerance;
    s.pressure.maxIterations = spec.pressureMaxIterations;
    s.pressure.preconditioner = spec.pressurePreconditioner == SimPreconditioner::Mic0
                                    ? PressurePreconditioner::Mic0
                                    : PressurePreconditioner::Multigrid;
    return s;
}

std::vector<SmokeSource> smokeSourcesFrom(const SmokeSimulationSpec& spec) {
    std::vector<SmokeSource> sources;
    for (const SmokeSourceSpec& src : spec.sources) {
        SmokeSource source;
        source.shape = shapeFrom(src.shape);
        source.densityRate = src.densityRate;
        source.temperatureRate = src.temperatureRate;
        source.velocity = src.velocity;
        source.velocityRate = src.velocityRate;
        sources.push_back(source);
    }
    return sources;
}

namespace {

// The world-space triangles of a scene mesh, as the renderer places them (file meshes read,
// holes closed and checked closed as for rendering).
TriangleMesh worldMesh(const MeshObjectSpec& spec) {
    TriangleMesh local = meshShape(spec);
    if (spec.shape == MeshShapeType::File) {
        RefractiveMeshOptions options;
        options.closeHolesUpTo = std::size_t(spec.closeHolesUpTo);
        local = loadRefractiveMesh(spec.file, options).mesh;
    }
    const TriangleMesh world = placeMesh(local, spec);
    checkMeshForVoxelization(world, spec.shape == MeshShapeType::File ? spec.file : spec.name);
    return world;
}

// `meshes`: the scene's, for mesh obstacles; null when only the simulation spec is at hand.
// `scenePath` names the scene file in messages.
void addObstacles(SmokeSolver& solver, const SmokeSimulationSpec& spec,
                  const std::vector<MeshObjectSpec>* meshes, const std::string& scenePath = "") {
    const Domain& d = solver.settings().domain;
    for (const SimShapeSpec& obstacle : spec.obstacles) {
        if (obstacle.kind != SimShapeSpec::Kind::Mesh) {
            solver.addObstacle(shapeFrom(obstacle));
            continue;
        }
        if (!meshes || obstacle.mesh < 0 || std::size_t(obstacle.mesh) >= meshes->size())
            throw Error(obstacle.jsonPath,
                        "a mesh obstacle needs the scene's meshes: build the "
                        "solver from the scene (smokeSolverFrom(scene))");
        // Solid cells: those whose centres the closed mesh holds (parity at the cell centres).
        const MeshObjectSpec& mesh = (*meshes)[std::size_t(obstacle.mesh)];
        if (mesh.shape == MeshShapeType::LevelSet) {  // cells whose centres lie below zero
            std::optional<LevelSet> set;
            try {
                set = LevelSet::read(mesh.file, mesh.grid);
            } catch (const Error& e) {  // where the renderer says it (render/mesh_fields.cpp)
                throw Error(scenePath + ":" + mesh.jsonPath + "/file",
                            "mesh '" + mesh.name + "': " + e.what());
            }
            solver.addObstacle(set->inside(d.origin, glm::vec3(d.voxelSize), d.resolution, mesh));
            continue;
        }
        const TriangleMesh world = worldMesh(mesh);
        checkMeshFitsVoxelGrid(world,
                               scenePath + ":" + obstacle.jsonPath + " (mesh '" + mesh.name + "')",
                               d.origin, glm::vec3(d.voxelSize), d.resolution);
        solver.addObstacle(
            voxelizeInsideCpu(world, d.origin, glm::vec3(d.voxelSize), d.resolution));
    }
}

}  // namespace

SmokeSolver smokeSolverFrom(const SmokeSimulationSpec& spec, double fps) {
    SmokeSolver solver(smokeSettingsFrom(spec, fps));
    for (const SmokeSource& source : smokeSourcesFrom(spec)) solver.addSource(source);
    addObstacles(solver, spec, nullptr);
    return solver;
}

SmokeSolver smokeSolverFrom(const Scene& scene, std::size_t domain) {
    if (domain >= scene.simulations.size())
        throw Error(scene.path, scene.simulations.empty()
                                    ? "no \"simulation\" section"
                                    : "no simulation domain " + std::to_string(domain));
    const SmokeSimulationSpec& spec = scene.simulations[domain];
    SmokeSettings settings = smokeSettingsFrom(spec, scene.time.fps);
    settings.firstFrame = scene.time.frameStart;
    SmokeSolver solver(settings);
    for (const SmokeSource& source : smokeSourcesFrom(spec)) solver.addSource(source);
    addObstacles(solver, spec, &scene.meshes, scene.path);

    // The tracks that move sources, evaluated into a private copy of the scene (the others animate
    // what the simulation never reads); each substep rebuilds the sources from that copy, so
    // they depend on the time alone.
    Scene keyed = scene;
    keyed.animation.clear();
    for (const AnimationTrack& track : scene.animation)
        if (track.target.rfind(spec.jsonPath + "/", 0) == 0) keyed.animation.push_back(track);
    if (keyed.animation.empty()) return solver;
    auto state = std::make_shared<std::pair<Scene, SceneAnimation>>(keyed, SceneAnimation(keyed));
    solver.setSourceUpdate([state, domain](double seconds, std::vector<SmokeSource>& sources) {
        state->second.apply(seconds, state->first);
        sources = smokeSourcesFrom(state->first.simulations[domain]);
    });
    return solver;
}

}  // namespace eikon::sim
