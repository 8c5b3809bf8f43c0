#pragma once
// Parser of the scene's "meshes" array (docs/scene-format.md#meshes). Internal to core:
// scene.cpp calls it; users read Scene::meshes and the materials it adds to Scene::materials.
#include <filesystem>
#include <vector>

#include "core/json_reader.h"
#include "core/scene.h"

namespace eikon {

// Each mesh takes one or two of the scene's material slots, so four meshes at most.
constexpr std::size_t kMaxMeshes = 4;

struct ParsedMeshes {
    std::vector<MeshObjectSpec> meshes;
    // Per mesh, in order: the coverage material (when it absorbs, scatters or emits) and the
    // index material (when ior ≠ 1).
    std::vector<MaterialSpec> materials;
};

ParsedMeshes readMeshes(const json::Value& value, const std::filesystem::path& sceneDirectory);

}  // namespace eikon
