#pragma once
// Axis-aligned box in world (scene) units.
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace eikon {

struct Bounds3 {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};

    bool valid() const { return min.x < max.x && min.y < max.y && min.z < max.z; }
    glm::vec3 size() const { return max - min; }
    glm::vec3 center() const { return 0.5f * (min + max); }
    Bounds3 unite(const Bounds3& o) const {
        if (!valid()) return o;
        if (!o.valid()) return *this;
        return {glm::min(min, o.min), glm::max(max, o.max)};
    }
};

}  // namespace eikon
