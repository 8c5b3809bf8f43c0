#pragma once
// The text `eikon info mesh.obj` prints: counts, bounds, topology and every problem found.
#include <string>

#include "sim/mesh_check.h"
#include "sim/mesh_io.h"

namespace eikon {

std::string formatMeshInfo(const std::string& path, const LoadedMesh& loaded,
                           const MeshReport& report);

}  // namespace eikon
