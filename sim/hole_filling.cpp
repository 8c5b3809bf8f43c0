#include "sim/hole_filling.h"

#include <limits>

#include <glm/geometric.hpp>

#include "sim/mesh_edges.h"

namespace eikon {

namespace {

// The minimum-area triangulation of the polygon q[0..n-1] (n ≥ 3). Triangles (q[i], q[m], q[k])
// with i < m < k run the polygon's way round.
std::vector<glm::uvec3> minimumAreaTriangulation(const TriangleMesh& mesh,
                                                 const std::vector<std::uint32_t>& q,
                                                 double& area) {
    const std::size_t n = q.size();
    auto p = [&](std::size_t i) { return glm::dvec3(mesh.positions[q[i]]); };
    auto triangleArea = [&](std::size_t i, std::size_t m, std::size_t k) {
        return 0.5 * glm::length(glm::cross(p(m) - p(i), p(k) - p(i)));
    };
    // best[i][k]: least area triangulating q[i..k]; split[i][k]: the apex m that gives it.
    std::vector<double> best(n * n, 0.0);
    std::vector<std::uint32_t> split(n * n, 0);
    for (std::size_t span = 2; span < n; ++span) {
        for (std::size_t i = 0; i + span < n; ++i) {
            const std::size_t k = i + span;
            double least = std::numeric_limits<double>::infinity();
            for (std::size_t m = i + 1; m < k; ++m) {
                const double a = best[i * n + m] + best[m * n + k] + triangleArea(i, m, k);
                if (a < least) {
                    least = a;
                    split[i * n + k] = std::uint32_t(m);
                }
            }
            best[i * n + k] = least;
        }
    }
    area = best[n - 1];
    std::vector<glm::uvec3> triangles;
    std::vector<std::pair<std::size_t, std::size_t>> pending{{0, n - 1}};
    while (!pending.empty()) {
        const auto [i, k] = pending.back();
        pending.pop_back();
        if (k < i + 2) continue;
        const std::size_t m = split[i * n + k];
        triangles.emplace_back(q[i], q[m], q[k]);
        pending.push_back({i, m});
        pending.push_back({m, k});
    }
    return triangles;
}

}  // namespace

HoleFilling closeHoles(TriangleMesh& mesh, std::size_t maxEdges) {
    HoleFilling result;
    for (const BoundaryHole& hole : boundaryHoles(meshEdges(mesh))) {
        if (hole.edges > maxEdges || hole.edges > kMaxFillableHoleEdges) {
            result.tooLarge.push_back(hole.edges);
            continue;
        }
        if (!hole.simple()) {
            result.notSimple.push_back(hole.edges);
            continue;
        }
        // The patch runs each boundary edge backwards: the loop reversed.
        const std::vector<std::uint32_t> patch(hole.loop.rbegin(), hole.loop.rend());
        FilledHole filled;
        filled.edges = patch.size();
        const std::vector<glm::uvec3> triangles =
            minimumAreaTriangulation(mesh, patch, filled.area);
        filled.triangles = triangles.size();
        mesh.triangles.insert(mesh.triangles.end(), triangles.begin(), triangles.end());
        result.filled.push_back(filled);
    }
    return result;
}

}  // namespace eikon
