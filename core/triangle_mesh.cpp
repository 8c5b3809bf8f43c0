#include "core/triangle_mesh.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace eikon {

Bounds3 boundsOf(const TriangleMesh& mesh) {
    if (mesh.triangles.empty()) return {};
    Bounds3 b{mesh.positions[mesh.triangles[0].x], mesh.positions[mesh.triangles[0].x]};
    for (const glm::uvec3& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            b.min = glm::min(b.min, mesh.positions[t[k]]);
            b.max = glm::max(b.max, mesh.positions[t[k]]);
        }
    }
    return b;
}

double signedVolume(const TriangleMesh& mesh) {
    double volume = 0.0;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
        volume += glm::dot(a, glm::cross(b, c));
    }
    return volume / 6.0;
}

}  // namespace eikon
