#pragma once
// Parser of the scene's "simulation" section (docs/scene-format.md#simulation). Internal to
// core: scene.cpp calls it; users read Scene::simulation.
#include <filesystem>

#include "core/json_reader.h"
#include "core/scene.h"
#include "core/simulation_spec.h"

namespace eikon {

// `meshes`: the scene's, read before, which obstacles may name.
SmokeSimulationSpec readSimulation(const json::Value& value,
                                   const std::filesystem::path& sceneDirectory,
                                   const std::vector<MeshObjectSpec>& meshes);

// Once the animation is read: a mesh obstacle whose placement a track animates would need a
// moving solid, which the solver does not model; throws eikon::Error at the obstacle's "mesh".
void checkObstaclesStandStill(const Scene& scene);

}  // namespace eikon
