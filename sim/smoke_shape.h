#pragma once
// The analytic shapes smoke sources and obstacles take, in world space.
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace eikon::sim {

struct SmokeShape {
    enum class Kind { Sphere, Box };
    Kind kind = Kind::Sphere;
    glm::vec3 center{0.0f};  // sphere
    float radius = 0.0f;
    glm::vec3 boxMin{0.0f}, boxMax{0.0f};  // box

    static SmokeShape sphere(glm::vec3 c, float r) { return {Kind::Sphere, c, r, {}, {}}; }
    static SmokeShape box(glm::vec3 lo, glm::vec3 hi) { return {Kind::Box, {}, 0.0f, lo, hi}; }

    bool contains(glm::vec3 p) const {
        if (kind == Kind::Sphere) return glm::distance(p, center) <= radius;
        return glm::all(glm::greaterThanEqual(p, boxMin)) &&
               glm::all(glm::lessThanEqual(p, boxMax));
    }
};

}  // namespace eikon::sim
