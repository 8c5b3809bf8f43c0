#pragma once
// The "simulation" section of a scene (docs/scene-format.md#simulation): the plain settings of a
// smoke simulation. Core only holds them; sim/smoke_from_scene.h turns them into a solver, so
// that core never depends on sim.
#include <array>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/bounds.h"

namespace eikon {

enum class SimWall { Closed, Open };
enum class SimAdvection { SemiLagrangian, MacCormack, Bfecc };
enum class SimLimiter { None, Clamp, Revert };
enum class SimPreconditioner { Mic0, Multigrid };

// A sphere (center, radius) or a box (boxMin, boxMax), in scene units; an obstacle may also be
// one of the scene's meshes (Mesh: Scene::meshes[mesh], placed as that entry says), so that the
// glass the renderer shows is the solid the smoke flows around.
struct SimShapeSpec {
    enum class Kind { Sphere, Box, Mesh };
    Kind kind = Kind::Sphere;
    glm::vec3 center{0.0f};
    float radius = 0.5f;
    glm::vec3 boxMin{-0.5f};
    glm::vec3 boxMax{0.5f};
    int mesh = -1;         // Mesh: index into Scene::meshes
    std::string jsonPath;  // e.g. "/simulation/obstacles/0", for messages
};

struct SmokeSourceSpec {
    SimShapeSpec shape;
    float densityRate = 1.0f;      // per second inside the shape
    float temperatureRate = 0.0f;  // degrees per second
    glm::vec3 velocity{0.0f};      // target velocity inside the shape, scene units/s
    float velocityRate = 0.0f;     // per second; how fast the velocity is pulled to the target
};

struct SmokeSimulationSpec {
    // Tells the domains of a scene with several apart (letters, digits, '_'; empty for a lone
    // unlabelled one): its fields are published as "density.<label>", "temperature.<label>" and
    // "velocity.<label>" (labelled fields, docs/scene-format.md), so each can have a material.
    std::string label;
    // Where it is in the scene file: "/simulation" for a lone object, "/simulation/<d>" in an
    // array; its tracks are "<jsonPath>/sources/<i>/<key>".
    std::string jsonPath = "/simulation";
    // The box simulated. Cells are cubes of `voxelSize`; the box spans min + resolution·voxelSize
    // (the parser snaps "max" to whole cells when the resolution is one integer).
    Bounds3 domain{glm::vec3(-1.0f), glm::vec3(1.0f)};
    glm::ivec3 resolution{32};
    float voxelSize = 2.0f / 32.0f;
    // -x, +x, -y, +y, -z, +z.
    std::array<SimWall, 6> walls{SimWall::Closed, SimWall::Closed, SimWall::Closed,
                                 SimWall::Closed, SimWall::Closed, SimWall::Closed};
    double cfl = 1.0;
    int maxSubsteps = 64;
    SimAdvection advection = SimAdvection::MacCormack;
    SimLimiter limiter = SimLimiter::Revert;
    // Restore the density advection loses or gains each step (sim/mass_correction.h).
    bool conserveMass = false;
    float buoyancyAlpha = 0.1f;
    float buoyancyBeta = 1.0f;
    float ambientTemperature = 0.0f;
    float vorticity = 0.0f;
    glm::vec3 wind{0.0f};
    double pressureTolerance = 1e-5;
    int pressureMaxIterations = 500;
    SimPreconditioner pressurePreconditioner = SimPreconditioner::Multigrid;
    std::vector<SmokeSourceSpec> sources;
    std::vector<SimShapeSpec> obstacles;
    // Where `eikon simulate` writes when no -o is given (resolved against the scene's folder),
    // and the file prefix: <cacheDirectory>/<cacheName>_####.vdb.
    std::string cacheDirectory = "cache";
    std::string cacheName = "smoke";
};

// The name domain `spec` publishes field `kind` ("density", "temperature", "velocity") under:
// the kind itself for an unlabelled domain, "<kind>.<label>" otherwise.
inline std::string simulationFieldName(const SmokeSimulationSpec& spec, const std::string& kind) {
    return spec.label.empty() ? kind : kind + "." + spec.label;
}

}  // namespace eikon
