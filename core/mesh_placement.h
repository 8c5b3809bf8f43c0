#pragma once
// A scene mesh's triangles in object space (generated shapes) and in the world (placed by its
// scale, rotation and translation).
#include "core/scene.h"
#include "core/triangle_mesh.h"

namespace eikon {

// The object-space mesh of a generated shape (icosphere, box); empty for a mesh read from a file,
// for a level set (it has no triangles: core/level_set.h) and for a liquid (made from its
// container by sim/container_fill.h).
// Water: the box its waves stay in (the rest body with headroom for the droplets), which the
// render volume is framed on; the surface itself comes from sim/water_surface.h each frame.
TriangleMesh meshShape(const MeshObjectSpec& spec);

// The spec whose scale, rotation and translation place mesh `index`: its own, or for a liquid its
// container's, which it stands in and moves with (tracks animate the container).
const MeshObjectSpec& placementOf(const Scene& scene, size_t index);

// Every position p becomes translation + rotation · (scale ⊙ p). A mirroring scale (never from
// the parser, which wants scales > 0) would flip the winding.
TriangleMesh placeMesh(const TriangleMesh& local, const MeshObjectSpec& spec);

// The inverse: world positions back into the mesh's object space (for deformers that simulate in
// the world, such as the jelly, whose result the renderer places again).
TriangleMesh unplaceMesh(const TriangleMesh& world, const MeshObjectSpec& spec);

// One object-space point placed in the world, as placeMesh places each vertex.
glm::vec3 placePoint(glm::vec3 local, const MeshObjectSpec& spec);

// The object-space motion that the placement turns into the world motion `world` (a difference
// of points, so the translation drops out): what a drag in the world does to a handle.
glm::vec3 unplaceMotion(glm::vec3 world, const MeshObjectSpec& spec);

}  // namespace eikon
