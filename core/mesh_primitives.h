#pragma once
// Generated meshes for tests, benchmarks and demo scenes (the project ships no mesh files of its
// own; real ones are read from ../shared/data/meshes). All closed and wound outward.
#include "core/triangle_mesh.h"

namespace eikon {

// An icosahedron subdivided `subdivisions` times, its vertices pushed onto the sphere:
// 20·4^s triangles (s = 3: 1,280; s = 5: 20,480). Its volume is below 4/3·πr³ by the chords'
// cut, which tests must allow for (polyhedronVolume gives it exactly).
TriangleMesh icosphere(glm::vec3 center, float radius, int subdivisions);

// An axis-aligned box as 12 triangles.
TriangleMesh boxMesh(glm::vec3 min, glm::vec3 max);

// The mesh moved by `offset` (a rigid translation of every position).
TriangleMesh translated(TriangleMesh mesh, glm::vec3 offset);

}  // namespace eikon
