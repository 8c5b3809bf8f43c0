#include "sim/mesh_edges.h"

#include <algorithm>
#include <numeric>

namespace eikon {

MeshEdges meshEdges(const TriangleMesh& mesh) {
    MeshEdges out;
    out.vertices = mesh.positions.size();
    out.uses.reserve(mesh.triangles.size() * 3);
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3& tri = mesh.triangles[t];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t from = tri[k], to = tri[(k + 1) % 3];
            if (from != to) out.uses.push_back({t, from, to});
        }
    }
    auto key = [](const EdgeUse& u) {
        return std::uint64_t(std::min(u.from, u.to)) << 32 | std::max(u.from, u.to);
    };
    // Sorting by (edge, triangle) keeps the order of uses independent of the sort's stability.
    std::sort(out.uses.begin(), out.uses.end(), [&](const EdgeUse& x, const EdgeUse& y) {
        const std::uint64_t kx = key(x), ky = key(y);
        return kx != ky ? kx < ky : x.triangle < y.triangle;
    });
    for (std::uint32_t i = 0; i < out.uses.size();) {
        std::uint32_t j = i + 1;
        while (j < out.uses.size() && key(out.uses[j]) == key(out.uses[i])) ++j;
        const EdgeUse& u = out.uses[i];
        out.edges.push_back({std::min(u.from, u.to), std::max(u.from, u.to), i, j - i});
        i = j;
    }
    return out;
}

std::vector<BoundaryHole> boundaryHoles(const MeshEdges& edges) {
    std::vector<EdgeUse> boundary;  // as their triangles run them
    for (const MeshEdge& e : edges.edges)
        if (e.uses == 1) boundary.push_back(edges.uses[e.firstUse]);
    std::vector<std::uint32_t> parent(edges.vertices), out(edges.vertices, 0),
        in(edges.vertices, 0), next(edges.vertices, 0);
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    for (const EdgeUse& h : boundary) {
        parent[find(h.from)] = find(h.to);
        ++out[h.from];
        ++in[h.to];
        next[h.from] = h.to;
    }
    // Boundary edges grouped by hole, each group in the order of its first edge.
    std::vector<std::uint32_t> order(boundary.size());
    std::iota(order.begin(), order.end(), 0u);
    std::vector<std::uint32_t> firstOfRoot(edges.vertices, std::uint32_t(-1));
    for (std::uint32_t i = 0; i < boundary.size(); ++i) {
        std::uint32_t& first = firstOfRoot[find(boundary[i].from)];
        if (first == std::uint32_t(-1)) first = i;
    }
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) {
        return firstOfRoot[find(boundary[x].from)] < firstOfRoot[find(boundary[y].from)];
    });

    std::vector<BoundaryHole> holes;
    for (std::size_t i = 0; i < order.size();) {
        const std::uint32_t root = find(boundary[order[i]].from);
        std::size_t j = i;
        bool simple = true;
        for (; j < order.size() && find(boundary[order[j]].from) == root; ++j) {
            const EdgeUse& h = boundary[order[j]];
            simple =
                simple && out[h.from] == 1 && in[h.from] == 1 && out[h.to] == 1 && in[h.to] == 1;
        }
        BoundaryHole hole;
        hole.edges = j - i;
        // A connected set where every vertex has one edge in and one out is a single cycle.
        if (simple) {
            const std::uint32_t start = boundary[order[i]].from;
            std::uint32_t v = start;
            do {
                hole.loop.push_back(v);
                v = next[v];
            } while (v != start);
        }
        holes.push_back(std::move(hole));
        i = j;
    }
    return holes;
}

}  // namespace eikon
