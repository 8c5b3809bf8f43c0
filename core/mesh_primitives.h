#pragma once
// Generated meshes for tests, benchmarks and demo scenes (the project ships no mesh files of its
// own; real ones are read from ../shared/data/meshes). All closed and wound outward.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "core/triangle_mesh.h"

namespace eikon {

// An icosahedron subdivided `subdivisions` times, its vertices pushed onto the sphere:
// 20·4^s triangles (s = 3: 1,280; s = 5: 20,480). Its volume is below 4/3·πr³ by the chords'
// cut, which tests must allow for (polyhedronVolume gives it exactly).
TriangleMesh icosphere(glm::vec3 center, float radius, int subdivisions);

// A latitude/longitude sphere with poles on ±z: `slices` around, `stacks` from pole to pole,
// 2·slices·(stacks − 1) triangles (100×51: 10,000; 200×201: 80,000), the layout of the mesh-to-
// volume peer (../shared/peers/cpp/meshtovolume_peer.cpp) so that both voxelize the same mesh.
TriangleMesh uvSphere(glm::vec3 center, float radius, int slices, int stacks);

// An axis-aligned box as 12 triangles.
TriangleMesh boxMesh(glm::vec3 min, glm::vec3 max);

// A closed cylinder along +x from x = 0 to `length`, of `radius`, with `around` vertices per ring
// and `segments` + 1 rings, each end closed by a fan around a centre vertex. Vertex k·around + a
// is ring k, angle 2πa/around; the two centres come last (x = 0, then x = length). Wound outward.
TriangleMesh makeCylinder(float radius, float length, std::uint32_t around, std::uint32_t segments);

// The vertices of rings [first, last] of a makeCylinder mesh, and that end's centre vertex if
// the range includes ring 0 or the last ring: the handles that hold or move one end.
std::vector<std::uint32_t> cylinderRings(std::uint32_t around, std::uint32_t segments,
                                         std::uint32_t first, std::uint32_t last);

// A closed surface of revolution about the y axis: `profile` is a polyline of (r, y) points that
// starts and ends on the axis (r = 0) with r > 0 in between, swept through `sectors` angles
// (vertex angle 2πa/sectors from +x towards +z). The two axis points become single vertices closed
// by fans. Wound outward whichever way the profile runs. Throws eikon::Error for fewer than 3
// points, ends off the axis, an inner point with r <= 0 or fewer than 3 sectors. Tests build cups
// and glasses with it whose volumes are known exactly.
TriangleMesh revolvedProfile(const std::vector<glm::vec2>& profile, std::uint32_t sectors);

// The mesh moved by `offset` (a rigid translation of every position).
TriangleMesh translated(TriangleMesh mesh, glm::vec3 offset);

}  // namespace eikon
