#pragma once
// A mesh file made ready to be a closed refractive object: loaded, its small holes closed where
// the scene asks (close_holes), then checked. The one call the scene loader and `eikon info`
// need for a glass, water or jelly object.
#include <cstddef>
#include <string>
#include <vector>

#include "core/triangle_mesh.h"
#include "sim/hole_filling.h"
#include "sim/mesh_check.h"

namespace eikon {

struct RefractiveMeshOptions {
    // Fill holes of up to this many boundary edges (scene key close_holes); 0 fills none.
    std::size_t closeHolesUpTo = 0;
};

struct RefractiveMesh {
    TriangleMesh mesh;
    MeshReport report;               // after hole filling
    HoleFilling holes;               // what was filled and what was left open
    std::vector<std::string> notes;  // from the reader
};

// Throws eikon::Error naming `path` when the file cannot be loaded or the mesh, after filling,
// cannot be a closed refractive object (requireClosedRefractiveMesh).
RefractiveMesh loadRefractiveMesh(const std::string& path, const RefractiveMeshOptions& options);

}  // namespace eikon
