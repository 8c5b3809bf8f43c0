#include "core/mesh_primitives.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>

#include <glm/geometric.hpp>

#include "core/error.h"

namespace eikon {

TriangleMesh icosphere(glm::vec3 center, float radius, int subdivisions) {
    // The unit icosahedron from three golden rectangles, wound outward.
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> unit = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                   {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                   {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (glm::vec3& p : unit) p = glm::normalize(p);
    std::vector<glm::uvec3> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                     {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                     {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                     {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int s = 0; s < subdivisions; ++s) {
        // Each edge's midpoint is made once, so neighbouring triangles share it (watertight).
        std::map<std::pair<unsigned, unsigned>, unsigned> midpoints;
        auto midpoint = [&](unsigned a, unsigned b) {
            const auto key = std::make_pair(std::min(a, b), std::max(a, b));
            const auto found = midpoints.find(key);
            if (found != midpoints.end()) return found->second;
            unit.push_back(glm::normalize(unit[a] + unit[b]));
            const auto index = unsigned(unit.size() - 1);
            midpoints.emplace(key, index);
            return index;
        };
        std::vector<glm::uvec3> finer;
        finer.reserve(faces.size() * 4);
        for (const glm::uvec3& f : faces) {
            const unsigned ab = midpoint(f.x, f.y), bc = midpoint(f.y, f.z),
                           ca = midpoint(f.z, f.x);
            finer.push_back({f.x, ab, ca});
            finer.push_back({f.y, bc, ab});
            finer.push_back({f.z, ca, bc});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }
    TriangleMesh mesh;
    mesh.positions.reserve(unit.size());
    for (const glm::vec3& p : unit) mesh.positions.push_back(center + radius * p);
    mesh.triangles = std::move(faces);
    return mesh;
}

TriangleMesh uvSphere(glm::vec3 center, float radius, int slices, int stacks) {
    TriangleMesh mesh;
    if (slices < 3 || stacks < 2) return mesh;
    const double pi = 3.14159265358979323846;
    mesh.positions.push_back(center + radius * glm::vec3(0.0f, 0.0f, 1.0f));  // north pole
    for (int i = 1; i < stacks; ++i) {
        const double theta = pi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2.0 * pi * j / slices;
            mesh.positions.push_back(center +
                                     radius * glm::vec3(float(std::sin(theta) * std::cos(phi)),
                                                        float(std::sin(theta) * std::sin(phi)),
                                                        float(std::cos(theta))));
        }
    }
    mesh.positions.push_back(center + radius * glm::vec3(0.0f, 0.0f, -1.0f));  // south pole
    const auto south = unsigned(mesh.positions.size() - 1);
    auto ring = [&](int i, int j) { return unsigned(1 + (i - 1) * slices + (j % slices)); };
    for (int j = 0; j < slices; ++j) mesh.triangles.push_back({0u, ring(1, j), ring(1, j + 1)});
    for (int i = 1; i < stacks - 1; ++i)
        for (int j = 0; j < slices; ++j) {
            mesh.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            mesh.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
    for (int j = 0; j < slices; ++j)
        mesh.triangles.push_back({south, ring(stacks - 1, j + 1), ring(stacks - 1, j)});
    return mesh;
}

TriangleMesh boxMesh(glm::vec3 min, glm::vec3 max) {
    TriangleMesh mesh;
    for (int i = 0; i < 8; ++i)  // bit 0: x, bit 1: y, bit 2: z at max
        mesh.positions.push_back(
            {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z});
    mesh.triangles = {{0, 2, 3}, {0, 3, 1},   // z = min, normal −z
                      {4, 5, 7}, {4, 7, 6},   // z = max, +z
                      {0, 1, 5}, {0, 5, 4},   // y = min, −y
                      {2, 6, 7}, {2, 7, 3},   // y = max, +y
                      {0, 4, 6}, {0, 6, 2},   // x = min, −x
                      {1, 3, 7}, {1, 7, 5}};  // x = max, +x
    return mesh;
}

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

TriangleMesh revolvedProfile(const std::vector<glm::vec2>& profile, std::uint32_t sectors) {
    const size_t n = profile.size();
    if (n < 3 || sectors < 3)
        throw Error("revolved profile", "needs at least 3 profile points and 3 sectors");
    if (profile.front().x != 0.0f || profile.back().x != 0.0f)
        throw Error("revolved profile", "the profile must start and end on the axis (r = 0)");
    for (size_t i = 1; i + 1 < n; ++i)
        if (!(profile[i].x > 0.0f))
            throw Error("revolved profile", "point " + std::to_string(i) +
                                                " lies on or across the axis (r must be > 0)");
    TriangleMesh mesh;
    const double pi = 3.14159265358979323846;
    const std::uint32_t rings = std::uint32_t(n - 2);
    for (std::uint32_t k = 0; k < rings; ++k) {
        const glm::vec2 p = profile[k + 1];
        for (std::uint32_t a = 0; a < sectors; ++a) {
            const double theta = 2.0 * pi * a / sectors;
            mesh.positions.emplace_back(p.x * float(std::cos(theta)), p.y,
                                        p.x * float(std::sin(theta)));
        }
    }
    const std::uint32_t first = rings * sectors, last = first + 1;
    mesh.positions.emplace_back(0.0f, profile.front().y, 0.0f);
    mesh.positions.emplace_back(0.0f, profile.back().y, 0.0f);
    auto at = [&](std::uint32_t k, std::uint32_t a) { return k * sectors + a % sectors; };
    for (std::uint32_t a = 0; a < sectors; ++a)
        mesh.triangles.emplace_back(first, at(0, a), at(0, a + 1));
    for (std::uint32_t k = 0; k + 1 < rings; ++k) {
        for (std::uint32_t a = 0; a < sectors; ++a) {
            mesh.triangles.emplace_back(at(k, a), at(k + 1, a), at(k + 1, a + 1));
            mesh.triangles.emplace_back(at(k, a), at(k + 1, a + 1), at(k, a + 1));
        }
    }
    for (std::uint32_t a = 0; a < sectors; ++a)
        mesh.triangles.emplace_back(last, at(rings - 1, a + 1), at(rings - 1, a));
    // The winding above is outward for one direction of travel; flip it for the other.
    if (signedVolume(mesh) < 0.0)
        for (glm::uvec3& t : mesh.triangles) std::swap(t.y, t.z);
    return mesh;
}

TriangleMesh translated(TriangleMesh mesh, glm::vec3 offset) {
    for (glm::vec3& p : mesh.positions) p += offset;
    return mesh;
}

}  // namespace eikon
