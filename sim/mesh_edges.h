#pragma once
// The edges of a triangle list and the faces that use each, found by sorting (no half-edge
// structure, so non-manifold and duplicate faces are counted as they are, not refused), and the
// holes their boundary edges form. Shared by mesh_check (reporting) and hole_filling (repair).
#include <cstdint>
#include <vector>

#include "core/triangle_mesh.h"

namespace eikon {

// One use of an edge by a triangle, in the direction that triangle runs along it.
struct EdgeUse {
    std::uint32_t triangle;
    std::uint32_t from, to;
};

struct MeshEdge {
    std::uint32_t a, b;            // a < b
    std::uint32_t firstUse, uses;  // range in MeshEdges::uses
};

struct MeshEdges {
    std::size_t vertices = 0;     // of the mesh, referenced or not
    std::vector<MeshEdge> edges;  // sorted by (a, b)
    std::vector<EdgeUse> uses;
};

// Every undirected edge of the triangles. An "edge" from a vertex to itself (a triangle that
// repeats an index) is not an edge and is left out.
MeshEdges meshEdges(const TriangleMesh& mesh);

// A hole: a connected set of boundary edges (edges used by one triangle). Two loops that touch at
// a vertex are one hole, as are chains that end at non-manifold edges.
struct BoundaryHole {
    std::size_t edges = 0;
    // Where the hole is one simple loop (every vertex on it has one boundary edge in and one
    // out): its vertices in order, loop[i] → loop[i+1] running the way its triangle runs, so a
    // patch that closes the hole must run the other way. Empty otherwise: such a hole cannot be
    // filled without choosing how its pieces pair up.
    std::vector<std::uint32_t> loop;
    bool simple() const { return !loop.empty(); }
};

// The holes, in the order of their first boundary edge in MeshEdges::edges.
std::vector<BoundaryHole> boundaryHoles(const MeshEdges& edges);

}  // namespace eikon
