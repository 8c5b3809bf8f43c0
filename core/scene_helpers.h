#pragma once
// Small pieces the scene parsers (scene.cpp, scene_simulation.cpp) share. Internal to core.
#include <filesystem>
#include <string>

#include <glm/vec3.hpp>

namespace eikon::scene_detail {

// "[x, y, z]" for messages.
std::string formatVec3(const glm::vec3& v);

// Relative paths in a scene are relative to the scene file, so that a scene and its caches can
// move together.
std::string resolveAgainst(const std::filesystem::path& sceneDirectory, const std::string& file);

// The characters of a field label ("n.crown") or a simulation domain's label: letters, digits, _.
bool isLabelCharacter(char c);

}  // namespace eikon::scene_detail
