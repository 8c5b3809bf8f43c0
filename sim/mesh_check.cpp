#include "sim/mesh_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numeric>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "sim/mesh_edges.h"

namespace eikon {

namespace {

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : parent_(n) {
        std::iota(parent_.begin(), parent_.end(), std::uint32_t(0));
    }
    std::uint32_t find(std::uint32_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void unite(std::uint32_t x, std::uint32_t y) { parent_[find(x)] = find(y); }

private:
    std::vector<std::uint32_t> parent_;
};

std::string plural(std::size_t n, const std::string& one, const std::string& many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", x);
    return text;
}

bool isDegenerate(const TriangleMesh& mesh, const glm::uvec3& t) {
    if (t.x == t.y || t.y == t.z || t.z == t.x) return true;
    const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    const double longest2 =
        std::max({glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)});
    // Twice the area against the longest edge squared: the height over that edge relative to
    // its length. Below 1e-7 it is zero to float precision.
    return glm::length(glm::cross(b - a, c - a)) <= 1e-7 * longest2;
}

std::size_t countDuplicates(const TriangleMesh& mesh) {
    std::vector<std::array<std::uint32_t, 3>> sorted;
    sorted.reserve(mesh.triangles.size());
    for (const glm::uvec3& t : mesh.triangles) {
        std::array<std::uint32_t, 3> k{t.x, t.y, t.z};
        std::sort(k.begin(), k.end());
        sorted.push_back(k);
    }
    std::sort(sorted.begin(), sorted.end());
    std::size_t duplicates = 0;
    for (std::size_t i = 1; i < sorted.size(); ++i) duplicates += sorted[i] == sorted[i - 1];
    return duplicates;
}

// A vertex is non-manifold when the triangle corners at it fall into more than one fan, two
// corners being in one fan when their triangles share an edge that ends at the vertex.
std::size_t countNonManifoldVertices(const TriangleMesh& mesh, const MeshEdges& edges) {
    auto cornerOf = [&](std::uint32_t triangle, std::uint32_t vertex) {
        const glm::uvec3& t = mesh.triangles[triangle];
        const int k = t.x == vertex ? 0 : t.y == vertex ? 1 : 2;
        return 3 * triangle + std::uint32_t(k);
    };
    UnionFind fans(mesh.triangles.size() * 3);
    for (const MeshEdge& e : edges.edges) {
        const std::uint32_t first = edges.uses[e.firstUse].triangle;
        for (std::uint32_t u = 1; u < e.uses; ++u) {
            const std::uint32_t other = edges.uses[e.firstUse + u].triangle;
            fans.unite(cornerOf(first, e.a), cornerOf(other, e.a));
            fans.unite(cornerOf(first, e.b), cornerOf(other, e.b));
        }
    }
    std::vector<std::int64_t> fanOfVertex(mesh.positions.size(), -1);
    std::vector<bool> nonManifold(mesh.positions.size(), false);
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.triangles[t][k];
            const std::int64_t fan = fans.find(3 * t + std::uint32_t(k));
            if (fanOfVertex[v] < 0) fanOfVertex[v] = fan;
            // A triangle that repeats v has two corners there and is its own fan twice; only
            // a second fan from another triangle makes v non-manifold.
            else if (fanOfVertex[v] != fan && mesh.triangles[t][(k + 1) % 3] != v &&
                     mesh.triangles[t][(k + 2) % 3] != v)
                nonManifold[v] = true;
        }
    }
    return std::size_t(std::count(nonManifold.begin(), nonManifold.end(), true));
}

void checkEdges(const TriangleMesh& mesh, MeshReport& r) {
    const MeshEdges edges = meshEdges(mesh);
    r.edges = edges.edges.size();
    for (const MeshEdge& e : edges.edges) {
        if (e.uses == 1) ++r.boundaryEdges;
        if (e.uses > 2) ++r.nonManifoldEdges;
        if (e.uses == 2 && edges.uses[e.firstUse].from == edges.uses[e.firstUse + 1].from)
            ++r.inconsistentEdges;
    }
    for (const BoundaryHole& hole : boundaryHoles(edges)) {
        r.holeSizes.push_back(hole.edges);
        if (hole.simple())
            r.largestSimpleHole = std::max(r.largestSimpleHole, hole.edges);
        else
            ++r.complexHoles;
    }
    std::sort(r.holeSizes.begin(), r.holeSizes.end(), std::greater<>());
    r.nonManifoldVertices = countNonManifoldVertices(mesh, edges);
}

void checkVertices(const TriangleMesh& mesh, MeshReport& r) {
    std::vector<bool> referenced(mesh.positions.size(), false);
    UnionFind pieces(mesh.positions.size());
    for (const glm::uvec3& t : mesh.triangles) {
        referenced[t.x] = referenced[t.y] = referenced[t.z] = true;
        pieces.unite(t.x, t.y);
        pieces.unite(t.y, t.z);
    }
    bool first = true;
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        if (!referenced[v]) {
            ++r.unreferencedVertices;
            continue;
        }
        r.components += pieces.find(v) == v;
        const glm::vec3& p = mesh.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            ++r.nonFiniteVertices;
            continue;
        }
        r.bounds =
            first ? Bounds3{p, p} : Bounds3{glm::min(r.bounds.min, p), glm::max(r.bounds.max, p)};
        first = false;
    }
}

std::string scaleProblem(const Bounds3& b) {
    const glm::dvec3 size(b.size());
    const double diagonal = glm::length(size);
    if (diagonal < kMinMeshDiagonal)
        return "absurd scale: bounding-box diagonal " + number(diagonal) + " (below " +
               number(kMinMeshDiagonal) + " scene units)";
    if (diagonal > kMaxMeshDiagonal)
        return "absurd scale: bounding-box diagonal " + number(diagonal) + " (above " +
               number(kMaxMeshDiagonal) + " scene units)";
    const double largest = std::max({size.x, size.y, size.z});
    const double smallest = std::min({size.x, size.y, size.z});
    if (smallest * kMaxMeshExtentRatio < largest)
        return "absurd scale: extents " + number(size.x) + " x " + number(size.y) + " x " +
               number(size.z) + " (largest over smallest above " + number(kMaxMeshExtentRatio) +
               ")";
    return {};
}

std::string holesText(const MeshReport& r) {
    std::string text =
        "not watertight: " + plural(r.boundaryEdges, "boundary edge", "boundary edges") + " in " +
        plural(r.holeSizes.size(), "hole", "holes");
    if (!r.holeSizes.empty()) text += " (largest " + plural(r.holeSizes[0], "edge", "edges") + ")";
    return text;
}

}  // namespace

MeshReport checkMesh(const TriangleMesh& mesh) {
    MeshReport r;
    r.vertices = mesh.positions.size();
    r.faces = r.triangles = mesh.triangles.size();
    checkVertices(mesh, r);
    checkEdges(mesh, r);
    for (const glm::uvec3& t : mesh.triangles) r.degenerateTriangles += isDegenerate(mesh, t);
    r.duplicateTriangles = countDuplicates(mesh);
    r.eulerCharacteristic =
        long(r.vertices - r.unreferencedVertices) - long(r.edges) + long(r.triangles);
    r.signedVolume = signedVolume(mesh);
    if (r.triangles > 0 && r.nonFiniteVertices == 0) r.scaleProblem = scaleProblem(r.bounds);
    return r;
}

MeshReport checkMesh(const LoadedMesh& loaded) {
    MeshReport r = checkMesh(loaded.mesh);
    r.faces = loaded.faces;
    return r;
}

namespace {

struct Problem {
    Problem(std::string text, bool blocks = true)
        : text(std::move(text)), blocksRefraction(blocks) {}
    std::string text;
    bool blocksRefraction;  // false: harmless to the voxelizer's inside/outside test
    std::string hint;       // what the user can set to get past it
};

std::vector<Problem> findProblems(const MeshReport& r) {
    std::vector<Problem> p;
    if (r.triangles == 0) p.push_back({"no triangles"});
    if (r.nonFiniteVertices > 0)
        p.push_back({plural(r.nonFiniteVertices, "vertex is", "vertices are") +
                     " not finite (NaN or infinite)"});
    if (r.boundaryEdges > 0) {
        Problem holes{holesText(r)};
        holes.hint = closeHolesHint(r);
        p.push_back(holes);
    }
    if (r.complexHoles > 0)
        p.push_back(
            {plural(r.complexHoles, "hole is not a simple loop", "holes are not simple loops") +
             " (the boundary touches itself or meets non-manifold edges); close_holes "
             "does not fill those"});
    if (r.nonManifoldEdges > 0)
        p.push_back({plural(r.nonManifoldEdges, "non-manifold edge", "non-manifold edges") +
                     " (used by more than two faces)"});
    if (r.nonManifoldVertices > 0)
        p.push_back({plural(r.nonManifoldVertices, "non-manifold vertex", "non-manifold vertices") +
                     " (the faces around each form more than one fan)"});
    if (r.inconsistentEdges > 0)
        p.push_back(
            {"inconsistent winding: " + plural(r.inconsistentEdges, "edge is", "edges are") +
             " run the same way by both faces"});
    if (r.watertight() && r.inconsistentEdges == 0 && r.triangles > 0 && r.signedVolume <= 0.0)
        p.push_back({"wound inward: signed volume " + number(r.signedVolume) +
                     " (faces must run counter-clockwise seen from outside)"});
    if (r.degenerateTriangles > 0)
        p.push_back({plural(r.degenerateTriangles, "degenerate triangle", "degenerate triangles") +
                         " (zero area or a repeated vertex)",
                     false});
    if (r.duplicateTriangles > 0)
        p.push_back({plural(r.duplicateTriangles, "duplicate face", "duplicate faces") +
                         " (same vertices as an earlier face)",
                     false});
    if (!r.scaleProblem.empty()) p.push_back({r.scaleProblem});
    return p;
}

}  // namespace

std::string closeHolesHint(const MeshReport& r) {
    if (r.largestSimpleHole == 0) return {};
    const std::string n = std::to_string(r.largestSimpleHole);
    return "set close_holes to " + n + " to fill holes of up to " + n + " edges";
}

std::vector<std::string> meshProblems(const MeshReport& report) {
    std::vector<std::string> texts;
    for (const Problem& problem : findProblems(report)) texts.push_back(problem.text);
    return texts;
}

void requireClosedRefractiveMesh(const MeshReport& report, const std::string& where) {
    std::string reason;
    for (const Problem& problem : findProblems(report)) {
        if (!problem.blocksRefraction) continue;
        if (!reason.empty()) reason += "; ";
        reason += problem.text;
        if (!problem.hint.empty()) reason += "; " + problem.hint;
    }
    if (!reason.empty()) throw Error(where, reason);
}

}  // namespace eikon
