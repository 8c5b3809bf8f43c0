#include "sim/mesh_primitives.h"

#include <cmath>

#include "core/error.h"

namespace eikon {

TriangleMesh makeCylinder(float radius, float length, std::uint32_t around,
                          std::uint32_t segments) {
    if (around < 3 || segments < 1 || !(radius > 0.0f) || !(length > 0.0f))
        throw Error("cylinder",
                    "needs radius, length > 0, at least 3 vertices around and 1 segment");
    TriangleMesh mesh;
    const double pi = 3.14159265358979323846;
    for (std::uint32_t k = 0; k <= segments; ++k) {
        const float x = length * float(k) / float(segments);
        for (std::uint32_t a = 0; a < around; ++a) {
            const double theta = 2.0 * pi * a / around;
            mesh.positions.emplace_back(x, radius * float(std::cos(theta)),
                                        radius * float(std::sin(theta)));
        }
    }
    const std::uint32_t start = (segments + 1) * around, end = start + 1;
    mesh.positions.emplace_back(0.0f, 0.0f, 0.0f);
    mesh.positions.emplace_back(length, 0.0f, 0.0f);
    auto at = [&](std::uint32_t k, std::uint32_t a) { return k * around + a % around; };
    for (std::uint32_t k = 0; k < segments; ++k) {
        for (std::uint32_t a = 0; a < around; ++a) {
            mesh.triangles.emplace_back(at(k, a), at(k, a + 1), at(k + 1, a + 1));
            mesh.triangles.emplace_back(at(k, a), at(k + 1, a + 1), at(k + 1, a));
        }
    }
    for (std::uint32_t a = 0; a < around; ++a) {
        mesh.triangles.emplace_back(start, at(0, a + 1), at(0, a));
        mesh.triangles.emplace_back(end, at(segments, a), at(segments, a + 1));
    }
    return mesh;
}

std::vector<std::uint32_t> cylinderRings(std::uint32_t around, std::uint32_t segments,
                                         std::uint32_t first, std::uint32_t last) {
    std::vector<std::uint32_t> vertices;
    for (std::uint32_t k = first; k <= last && k <= segments; ++k)
        for (std::uint32_t a = 0; a < around; ++a) vertices.push_back(k * around + a);
    if (first == 0) vertices.push_back((segments + 1) * around);
    if (last >= segments) vertices.push_back((segments + 1) * around + 1);
    return vertices;
}

}  // namespace eikon
