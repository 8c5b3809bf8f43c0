#pragma once
// What is wrong with a triangle mesh, measured on its face list as given (mesh_edges.h), and
// whether it can be a closed refractive object: the voxelizer decides inside from outside, which
// needs a watertight, manifold, consistently and outward wound surface of sensible size.
#include <cstddef>
#include <string>
#include <vector>

#include "core/bounds.h"
#include "core/triangle_mesh.h"
#include "sim/mesh_io.h"

namespace eikon {

struct MeshReport {
    std::size_t vertices = 0;
    std::size_t faces = 0;  // polygons as the file lists them (= triangles for a built mesh)
    std::size_t triangles = 0;
    std::size_t unreferencedVertices = 0;
    std::size_t nonFiniteVertices = 0;  // among the referenced ones
    Bounds3 bounds;                     // of the referenced vertices

    std::size_t edges = 0;                // undirected
    std::size_t boundaryEdges = 0;        // used by one triangle
    std::vector<std::size_t> holeSizes;   // edges per hole (see BoundaryHole), largest first
    std::size_t complexHoles = 0;         // holes that are not one simple loop
    std::size_t largestSimpleHole = 0;    // edges; what close_holes must be to fill them all
    std::size_t nonManifoldEdges = 0;     // used by more than two triangles
    std::size_t nonManifoldVertices = 0;  // faces around it form more than one edge-connected fan
    std::size_t inconsistentEdges = 0;    // two triangles run along it the same way
    std::size_t degenerateTriangles = 0;  // a repeated index, or zero area (to float precision)
    std::size_t duplicateTriangles = 0;   // same vertex set as an earlier triangle
    std::size_t components = 0;           // vertex-connected pieces
    long eulerCharacteristic = 0;         // V − E + F over referenced vertices
    double signedVolume = 0.0;            // positive when wound outward (meaningful if closed)
    std::string scaleProblem;             // empty when the size is sensible

    // Every edge used by exactly two triangles (SOURCES.md's definition).
    bool watertight() const { return boundaryEdges == 0 && nonManifoldEdges == 0; }
};

// Bounding-box diagonal limits and the largest ratio of extents, in scene units, beyond which a
// mesh is taken to be in the wrong units or broken ("absurd scale").
constexpr double kMinMeshDiagonal = 1e-6;
constexpr double kMaxMeshDiagonal = 1e6;
constexpr double kMaxMeshExtentRatio = 1e6;

MeshReport checkMesh(const TriangleMesh& mesh);
MeshReport checkMesh(const LoadedMesh& loaded);  // counts the file's polygons as faces

// One line per problem found, in words ("not watertight: 223 boundary edges in 5 holes (largest
// 96 edges)"); empty for a clean closed mesh. Unreferenced vertices are no problem.
std::vector<std::string> meshProblems(const MeshReport& report);

// "set close_holes to N to fill holes of up to N edges" where some holes are simple loops that
// close_holes could fill; empty otherwise.
std::string closeHolesHint(const MeshReport& report);

// Throws eikon::Error(where, ...) listing every problem that stops the mesh from being a closed
// refractive object: no triangles, non-finite vertices, holes (with the close_holes setting that
// would fill them), non-manifold edges or vertices, inconsistent or inward winding, absurd scale.
// Degenerate and duplicate triangles alone do not stop it.
void requireClosedRefractiveMesh(const MeshReport& report, const std::string& where);

}  // namespace eikon
