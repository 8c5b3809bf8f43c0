#include "sim/refractive_mesh.h"

#include "sim/mesh_io.h"

namespace eikon {

RefractiveMesh loadRefractiveMesh(const std::string& path, const RefractiveMeshOptions& options) {
    LoadedMesh loaded = loadMesh(path);
    RefractiveMesh out;
    out.mesh = std::move(loaded.mesh);
    out.notes = std::move(loaded.notes);
    out.holes = closeHoles(out.mesh, options.closeHolesUpTo);
    out.report = checkMesh(out.mesh);
    out.report.faces = loaded.faces;  // the file's polygons and the triangles filling added
    for (const FilledHole& hole : out.holes.filled) out.report.faces += hole.triangles;
    requireClosedRefractiveMesh(out.report, path);
    return out;
}

}  // namespace eikon
