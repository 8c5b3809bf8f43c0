#pragma once
// Checks on a mesh file's raw bytes, for the damage OpenMesh's readers do not report. Each throws
// eikon::Error naming the file (and line, where there is one) and saying what is wrong.
//
// Measured on OpenMesh 9.0 (Debian 12):
// - a PLY whose header never reaches `end_header`, or one it cannot parse, sends the PLY reader
//   into an endless loop (sim/ply_header.h has the list); a count in a PLY header or body sizes its
//   buffers unchecked (sim/ply_body.h);
// - a binary STL cut short reads as a mesh with fewer (or no) triangles and no error;
// - a NaN corner in a binary STL goes into the ordered map that welds corners, whose ordering it
//   breaks;
// - an OBJ `v` line it cannot parse (`v nan 0 0`, `v 1e400 0 0`, `v x 0 0`) is skipped without a
//   word, which shifts every later vertex index onto the wrong vertex; in an ASCII STL such a
//   corner ends the reading early, leaving a mesh with no faces and no error;
// OFF files have their own checks: sim/off_header.h, sim/off_ascii.h, sim/off_binary.h.
#include <cstddef>
#include <string>

#include "sim/ply_header.h"

namespace eikon {

// Before reading a PLY: its header follows the grammar (sim/ply_header.h), asks for nothing that
// OpenMesh's reader would misread (a list other than the faces' vertex_indices, list counts of a
// type it does not take, integer coordinates or double colours in a binary file; a vertex element
// without x, y and z), and its body holds what the counts say (sim/ply_body.h). Returns the header,
// whose canonical form is what OpenMesh is given.
PlyHeader checkPlyFile(const std::string& path, const std::string& bytes);

// Whether an STL file is ASCII: it starts with `solid` and is not exactly the size of a binary STL
// (some exporters start the 80-byte header of a binary STL with `solid` too).
bool isAsciiStl(const std::string& bytes);

// Before reading a binary STL: the size is exactly the 84-byte header plus 50 bytes per triangle
// it declares, and every corner is finite (OpenMesh welds corners in an ordered map, which a NaN
// would corrupt).
void checkBinaryStl(const std::string& path, const std::string& bytes);

// Every line that starts with `keyword` (`v` in OBJ, `vertex` in ASCII STL) holds three finite
// numbers after it; returns how many such lines there are.
std::size_t checkVertexLines(const std::string& path, const std::string& bytes,
                             const std::string& keyword);

// After reading an OBJ: its `v` lines are sound and OpenMesh read as many vertices.
void checkObjVertices(const std::string& path, const std::string& bytes, std::size_t verticesRead);

}  // namespace eikon
