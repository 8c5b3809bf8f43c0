// The "simulation" section of a scene, read as strictly as the rest (see scene.cpp): every
// error names "<file>:/simulation/...". Keep in step with docs/scene-format.md#simulation.
#include "core/scene_simulation.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/scene_helpers.h"
#include "core/scene_voxel_size.h"

namespace eikon {
namespace {

using json::Object;
using json::Range;
using json::Value;
using scene_detail::formatVec3;

// Cells along one axis. Beyond 512 a dense grid of this solver no longer fits in memory
// comfortably (512³ cells × 6 float arrays ≈ 3 GiB); 2 is the least that has an interior face.
constexpr int kMinCells = 2;
constexpr int kMaxCells = 512;
// Voxel sizes along the axes of an explicit [nx, ny, nz] may differ by this fraction: cells are
// cubes, so more means the resolution does not fit the box.
constexpr double kCubeTolerance = 1e-3;

const char* const kVec3Form = "an array of 3 numbers [x, y, z]";

Bounds3 readDomain(const Value& value) {
    Object object(value, "the simulation domain");
    Bounds3 box;
    box.min = object.required("min", kVec3Form).vec3();
    box.max = object.required("max", kVec3Form).vec3();
    object.finish();
    if (!box.valid()) {
        object.failAt("max", "expected max > min on every axis, got min " + formatVec3(box.min) +
                                 " and max " + formatVec3(box.max));
    }
    return box;
}

// One integer: cells along the longest axis, the others rounded to whole cubic cells (and the
// domain's max moved to match). Three: cells per axis, which must give cubic cells.
void readResolution(const Value& value, SmokeSimulationSpec& sim) {
    const glm::vec3 extent = sim.domain.max - sim.domain.min;
    if (value.isNumber()) {
        const int n = static_cast<int>(value.integer(kMinCells, kMaxCells));
        sim.voxelSize = std::max({extent.x, extent.y, extent.z}) / float(n);
        for (int a = 0; a < 3; ++a) {
            sim.resolution[a] = std::max(1, int(std::lround(extent[a] / sim.voxelSize)));
        }
        sim.domain.max = sim.domain.min + glm::vec3(sim.resolution) * sim.voxelSize;
        return;
    }
    if (!value.isArray()) {
        value.failExpected("an integer in [" + std::to_string(kMinCells) + ", " +
                           std::to_string(kMaxCells) + "] or an array of 3 such integers");
    }
    sim.resolution = value.ivec3(kMinCells, kMaxCells);
    const glm::vec3 h = extent / glm::vec3(sim.resolution);
    sim.voxelSize = h.x;
    if (std::abs(h.y - h.x) > kCubeTolerance * h.x || std::abs(h.z - h.x) > kCubeTolerance * h.x) {
        value.fail("expected cells that are cubes: the domain's extent " + formatVec3(extent) +
                   " over this resolution gives voxel sizes " + formatVec3(h) +
                   "; give one integer (cells along the longest axis) or fit the domain");
    }
}

std::array<SimWall, 6> readWalls(const Value& value) {
    Object object(value, "the walls");
    std::array<SimWall, 6> walls{};
    const char* const faces[6] = {"-x", "+x", "-y", "+y", "-z", "+z"};
    for (std::size_t f = 0; f < 6; ++f) {
        walls[f] = SimWall::Closed;
        if (auto wall = object.optional(faces[f])) {
            walls[f] = wall->choice({"closed", "open"}) == "open" ? SimWall::Open : SimWall::Closed;
        }
    }
    object.finish();
    return walls;
}

void readPressure(const Value& value, SmokeSimulationSpec& sim) {
    Object object(value, "the pressure settings");
    if (auto tolerance = object.optional("tolerance")) {
        sim.pressureTolerance = tolerance->number(Range::open(0.0, 1.0));
    }
    if (auto iterations = object.optional("max_iterations")) {
        sim.pressureMaxIterations = static_cast<int>(iterations->integer(1, 100000));
    }
    if (auto preconditioner = object.optional("preconditioner")) {
        sim.pressurePreconditioner = preconditioner->choice({"multigrid", "mic0"}) == "mic0"
                                         ? SimPreconditioner::Mic0
                                         : SimPreconditioner::Multigrid;
    }
    object.finish();
}

// The shape keys of a source or an obstacle; the caller has named the object's kind.
SimShapeSpec readShape(Object& object, const std::string& what) {
    SimShapeSpec shape;
    const std::string type =
        object.required("type", "\"sphere\" or \"box\"").choice({"sphere", "box"});
    object.setKind("a " + type + " " + what);
    if (type == "sphere") {
        shape.kind = SimShapeSpec::Kind::Sphere;
        if (auto center = object.optional("center")) shape.center = center->vec3();
        if (auto radius = object.optional("radius")) {
            shape.radius = radius->floatNumber(Range::greaterThan(0.0));
        }
        return shape;
    }
    shape.kind = SimShapeSpec::Kind::Box;
    if (auto min = object.optional("min")) shape.boxMin = min->vec3();
    if (auto max = object.optional("max")) shape.boxMax = max->vec3();
    if (!Bounds3{shape.boxMin, shape.boxMax}.valid()) {
        object.failAt("max", "expected max > min on every axis, got min " +
                                 formatVec3(shape.boxMin) + " and max " + formatVec3(shape.boxMax));
    }
    return shape;
}

SmokeSourceSpec readSource(const Value& value) {
    Object object(value, "a smoke source");
    SmokeSourceSpec source;
    source.shape = readShape(object, "smoke source");
    if (auto rate = object.optional("density_rate")) {
        source.densityRate = rate->floatNumber(Range::atLeast(0.0));
    }
    if (auto rate = object.optional("temperature_rate")) {
        source.temperatureRate = rate->floatNumber();
    }
    if (auto velocity = object.optional("velocity")) source.velocity = velocity->vec3();
    if (auto rate = object.optional("velocity_rate")) {
        source.velocityRate = rate->floatNumber(Range::atLeast(0.0));
    }
    object.finish();
    return source;
}

// A mesh obstacle names an entry of the scene's "meshes" that stands still: a jelly, a water
// surface or an ARAP-dragged mesh moves every frame, and the solver's solids do not.
SimShapeSpec readMeshObstacle(Object& object, const std::vector<MeshObjectSpec>& meshes) {
    SimShapeSpec shape;
    shape.kind = SimShapeSpec::Kind::Mesh;
    object.setKind("a mesh obstacle");
    const Value name = object.required("mesh", "the name of an entry of \"meshes\"");
    const std::string text = name.nonEmptyString();
    for (std::size_t m = 0; m < meshes.size(); ++m)
        if (meshes[m].name == text) shape.mesh = int(m);
    if (shape.mesh < 0) {
        std::string names;
        for (const MeshObjectSpec& mesh : meshes)
            names += (names.empty() ? "'" : ", '") + mesh.name + "'";
        name.fail("no mesh named '" + text + "' in \"meshes\" (" +
                  (names.empty() ? std::string("the scene has none") : "it has " + names) + ")");
    }
    const MeshObjectSpec& mesh = meshes[std::size_t(shape.mesh)];
    if (mesh.jelly || mesh.shape == MeshShapeType::Water)
        name.fail("mesh '" + text + "' moves by its own simulation (" +
                  (mesh.jelly ? "jelly" : "water") +
                  "); a smoke obstacle must stand still (moving solids are not simulated)");
    if (mesh.arap)
        name.fail("mesh '" + text +
                  "' is dragged by ARAP handles; a smoke obstacle must stand "
                  "still (moving solids are not simulated)");
    if (mesh.shape == MeshShapeType::Liquid)
        name.fail("mesh '" + text + "' is a liquid, not a solid the smoke flows around");
    return shape;
}

SimShapeSpec readObstacle(const Value& value, const std::vector<MeshObjectSpec>& meshes) {
    Object object(value, "an obstacle");
    SimShapeSpec shape =
        object.has("mesh") ? readMeshObstacle(object, meshes) : readShape(object, "obstacle");
    shape.jsonPath = value.pointer();
    object.finish();
    return shape;
}

void readAdvection(Object& object, SmokeSimulationSpec& sim) {
    if (auto scheme = object.optional("advection")) {
        const std::string s = scheme->choice({"semi_lagrangian", "maccormack", "bfecc"});
        sim.advection = s == "semi_lagrangian" ? SimAdvection::SemiLagrangian
                        : s == "maccormack"    ? SimAdvection::MacCormack
                                               : SimAdvection::Bfecc;
    }
    if (auto limiter = object.optional("limiter")) {
        const std::string l = limiter->choice({"clamp", "revert", "none"});
        sim.limiter = l == "clamp"    ? SimLimiter::Clamp
                      : l == "revert" ? SimLimiter::Revert
                                      : SimLimiter::None;
    }
    if (auto conserve = object.optional("conserve_mass")) sim.conserveMass = conserve->boolean();
}

void readForces(Object& object, SmokeSimulationSpec& sim) {
    if (auto alpha = object.optional("buoyancy_alpha")) sim.buoyancyAlpha = alpha->floatNumber();
    if (auto beta = object.optional("buoyancy_beta")) sim.buoyancyBeta = beta->floatNumber();
    if (auto ambient = object.optional("ambient_temperature")) {
        sim.ambientTemperature = ambient->floatNumber();
    }
    if (auto vorticity = object.optional("vorticity")) {
        sim.vorticity = vorticity->floatNumber(Range::atLeast(0.0));
    }
    if (auto wind = object.optional("wind")) sim.wind = wind->vec3();
}

// A domain's label: it becomes part of field names ("density.<label>") and of file names.
std::string readLabel(const Value& value) {
    const std::string label = value.nonEmptyString();
    for (const char c : label)
        if (!scene_detail::isLabelCharacter(c))
            value.fail(
                "expected a label of letters, digits and '_' (it names the domain's "
                "fields, density.<label>), got \"" +
                label + "\"");
    return label;
}

SmokeSimulationSpec readSimulation(const Value& value, const std::filesystem::path& sceneDirectory,
                                   const std::vector<MeshObjectSpec>& meshes, bool labelRequired) {
    Object object(value, "the simulation");
    SmokeSimulationSpec sim;
    sim.jsonPath = value.pointer();
    if (labelRequired)
        sim.label = readLabel(object.required(
            "label", "a name of letters, digits and '_'; each domain of several needs one"));
    else if (auto label = object.optional("label"))
        sim.label = readLabel(*label);
    sim.domain = readDomain(object.required("domain",
                                            "an object {\"min\": [x, y, z], \"max\": "
                                            "[x, y, z]}"));
    // The resolution depends on the domain, so it is read after it.
    readResolution(object.required("resolution", "an integer or [nx, ny, nz]"), sim);
    scene_detail::checkVoxelSize(object.value().child("domain"), glm::vec3(sim.voxelSize),
                                 sim.domain, "the domain's cells");
    if (auto walls = object.optional("walls")) sim.walls = readWalls(*walls);
    if (auto cfl = object.optional("cfl")) sim.cfl = cfl->number(Range::greaterThan(0.0));
    if (auto substeps = object.optional("max_substeps")) {
        sim.maxSubsteps = static_cast<int>(substeps->integer(1, 10000));
    }
    readAdvection(object, sim);
    readForces(object, sim);
    if (auto pressure = object.optional("pressure")) readPressure(*pressure, sim);
    if (auto sources = object.optional("sources")) {
        for (const Value& s : sources->elements("an array of smoke sources")) {
            sim.sources.push_back(readSource(s));
        }
    }
    if (auto obstacles = object.optional("obstacles")) {
        for (const Value& o : obstacles->elements("an array of obstacles")) {
            sim.obstacles.push_back(readObstacle(o, meshes));
        }
    }
    if (auto cache = object.optional("cache")) {
        sim.cacheDirectory = cache->nonEmptyString();
    }
    sim.cacheDirectory = scene_detail::resolveAgainst(sceneDirectory, sim.cacheDirectory);
    object.finish();
    return sim;
}

}  // namespace

std::vector<SmokeSimulationSpec> readSimulations(const Value& value,
                                                 const std::filesystem::path& sceneDirectory,
                                                 const std::vector<MeshObjectSpec>& meshes) {
    std::vector<SmokeSimulationSpec> simulations;
    if (!value.isArray()) {
        if (!value.isObject()) value.failExpected("an object, or an array of labelled objects");
        simulations.push_back(readSimulation(value, sceneDirectory, meshes, false));
        return simulations;
    }
    const std::vector<Value> domains =
        value.elements("an array of simulation domains", kMaxSimulationDomains);
    if (domains.empty()) value.fail("expected at least one simulation domain, got an empty array");
    for (const Value& domain : domains) {
        simulations.push_back(readSimulation(domain, sceneDirectory, meshes, true));
        for (std::size_t d = 0; d + 1 < simulations.size(); ++d)
            if (simulations[d].label == simulations.back().label)
                domain.child("label").fail("label \"" + simulations.back().label +
                                           "\" is taken by " + simulations[d].jsonPath +
                                           "; the domains' fields would overwrite each other");
    }
    return simulations;
}

void setSimulationCacheNames(std::vector<SmokeSimulationSpec>& simulations,
                             const std::string& base) {
    for (SmokeSimulationSpec& sim : simulations)
        sim.cacheName = sim.label.empty() ? base : base + "_" + sim.label;
}

std::vector<std::string> simulationFieldNames(const std::vector<SmokeSimulationSpec>& simulations) {
    std::vector<std::string> names;
    for (const SmokeSimulationSpec& sim : simulations)
        for (const char* kind : {"density", "temperature", "velocity"})
            names.push_back(simulationFieldName(sim, kind));
    return names;
}

void checkObstaclesStandStill(const Scene& scene) {
    for (const SmokeSimulationSpec& simulation : scene.simulations)
        for (const SimShapeSpec& obstacle : simulation.obstacles) {
            if (obstacle.kind != SimShapeSpec::Kind::Mesh) continue;
            const std::string prefix = "/meshes/" + std::to_string(obstacle.mesh) + "/";
            for (const AnimationTrack& track : scene.animation)
                for (const char* key : {"translate", "rotation", "scale"})
                    if (track.target == prefix + key)
                        throw Error(scene.path + ":" + obstacle.jsonPath + "/mesh",
                                    "mesh '" + scene.meshes[std::size_t(obstacle.mesh)].name +
                                        "' is moved by " + track.jsonPath + " (" + track.target +
                                        "); a smoke obstacle must stand still (moving solids are "
                                        "not simulated)");
        }
}

}  // namespace eikon
