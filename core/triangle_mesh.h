#pragma once
// A triangle mesh as the rest of Eikon sees it: positions and index triples, nothing else.
// `sim` loads and deforms meshes (on OpenMesh) and hands them over in this form; `render`
// voxelizes it. Neither includes the other: they meet here (docs/architecture.md).
// Winding: counter-clockwise seen from outside, so a closed mesh has a positive signed volume.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/bounds.h"

namespace eikon {

struct TriangleMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::uvec3> triangles;  // indices into positions
};

// Axis-aligned bounds of the positions the triangles use (unreferenced positions are ignored);
// an invalid Bounds3 for a mesh without triangles.
Bounds3 boundsOf(const TriangleMesh& mesh);

// Σ over triangles of det(a, b, c)/6, in double: the enclosed volume of a closed, consistently
// wound mesh (positive when wound outward), meaningless for an open one.
double signedVolume(const TriangleMesh& mesh);

}  // namespace eikon
