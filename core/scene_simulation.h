#pragma once
// Parser of the scene's "simulation" section (docs/scene-format.md#simulation). Internal to
// core: scene.cpp calls it; users read Scene::simulation.
#include <filesystem>

#include "core/json_reader.h"
#include "core/simulation_spec.h"

namespace eikon {

SmokeSimulationSpec readSimulation(const json::Value& value,
                                   const std::filesystem::path& sceneDirectory);

}  // namespace eikon
