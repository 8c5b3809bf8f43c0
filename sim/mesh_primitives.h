#pragma once
// Generated closed meshes for deformer tests, benchmarks and demo scenes.
#include <cstdint>
#include <vector>

#include "core/triangle_mesh.h"

namespace eikon {

// A closed cylinder along +x from x = 0 to `length`, of `radius`, with `around` vertices per ring
// and `segments` + 1 rings, each end closed by a fan around a centre vertex. Vertex k·around + a
// is ring k, angle 2πa/around; the two centres come last (x = 0, then x = length). Wound outward.
TriangleMesh makeCylinder(float radius, float length, std::uint32_t around, std::uint32_t segments);

// The vertices of rings [first, last] of a makeCylinder mesh, and that end's centre vertex if
// the range includes ring 0 or the last ring: the handles that hold or move one end.
std::vector<std::uint32_t> cylinderRings(std::uint32_t around, std::uint32_t segments,
                                         std::uint32_t first, std::uint32_t last);

}  // namespace eikon
