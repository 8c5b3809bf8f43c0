#pragma once
// Reading triangle meshes from OBJ, OFF, PLY (ASCII and binary) and STL files through OpenMesh's
// readers, into the TriangleMesh that sim and render share.
//
// The face list is kept as the file gives it (see openmesh_face_recorder.h): nothing is welded,
// dropped or repaired here, so that mesh_check.h judges the file's own topology. STL is the
// exception that cannot be helped: it stores every triangle's corners separately, and OpenMesh's
// STL reader welds equal positions into shared vertices.
#include <cstddef>
#include <string>
#include <vector>

#include "core/triangle_mesh.h"

namespace eikon {

struct LoadedMesh {
    TriangleMesh mesh;      // polygons fan-triangulated: (v0, vk, vk+1)
    std::size_t faces = 0;  // polygons as the file lists them
    // What OpenMesh's reader said and tolerated (a missing material file, for example).
    std::vector<std::string> notes;
};

// Loads `path`, choosing the reader by extension (.obj, .off, .ply, .stl, any case). Throws
// eikon::Error naming the file for an unknown extension, a file that cannot be opened, read or
// parsed (truncated, corrupt), a face that names a vertex the file does not have, a vertex that
// is not finite in single precision, and a file with no faces.
// OpenMesh reports through global streams; call from one thread at a time.
LoadedMesh loadMesh(const std::string& path);

// Whether `path` has one of the extensions loadMesh reads.
bool isMeshFile(const std::string& path);

}  // namespace eikon
