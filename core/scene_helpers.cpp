#include "core/scene_helpers.h"

#include <sstream>

namespace eikon::scene_detail {

std::string formatVec3(const glm::vec3& v) {
    std::ostringstream out;
    out << "[" << v.x << ", " << v.y << ", " << v.z << "]";
    return out.str();
}

std::string resolveAgainst(const std::filesystem::path& sceneDirectory, const std::string& file) {
    const std::filesystem::path path(file);
    if (path.is_absolute() || sceneDirectory.empty()) return path.lexically_normal().string();
    return (sceneDirectory / path).lexically_normal().string();
}

bool isLabelCharacter(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

}  // namespace eikon::scene_detail
