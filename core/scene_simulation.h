#pragma once
// Parser of the scene's "simulation" section (docs/scene-format.md#simulation). Internal to
// core: scene.cpp calls it; users read Scene::simulation.
#include <filesystem>

#include "core/json_reader.h"
#include "core/scene.h"
#include "core/simulation_spec.h"

namespace eikon {

// Most smoke domains one scene may hold: each is a solver of its own, stepped every frame.
constexpr std::size_t kMaxSimulationDomains = 8;

// The section: one object (one domain, "label" optional) or an array of 1 to
// kMaxSimulationDomains objects, each with a "label" of its own. `meshes`: the scene's, read
// before, which obstacles may name. Cache names are left at "smoke" (+ "_<label>"): the scene
// sets them once its output name is known (setSimulationCacheNames).
std::vector<SmokeSimulationSpec> readSimulations(const json::Value& value,
                                                 const std::filesystem::path& sceneDirectory,
                                                 const std::vector<MeshObjectSpec>& meshes);

// Each domain's cache prefix: `base` (the scene's output name, or "smoke"), then "_<label>" for
// a labelled domain, so that the domains' files never overwrite each other.
void setSimulationCacheNames(std::vector<SmokeSimulationSpec>& simulations,
                             const std::string& base);

// The fields the domains publish (density, temperature, velocity; labelled per domain).
std::vector<std::string> simulationFieldNames(const std::vector<SmokeSimulationSpec>& simulations);

// Once the animation is read: a mesh obstacle whose placement a track animates would need a
// moving solid, which the solver does not model; throws eikon::Error at the obstacle's "mesh".
void checkObstaclesStandStill(const Scene& scene);

}  // namespace eikon
