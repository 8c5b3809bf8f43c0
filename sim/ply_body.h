#pragma once
// The body of a PLY file walked against its header (sim/ply_header.h), before OpenMesh reads it.
//
// OpenMesh's PLY reader sizes its buffers from the header's counts and each face from its list
// count, and reads on past the end of the file without stopping (a face count of 99,999,999 in a
// 20 kB file gave 3.5 GB in the edge sort; a list count read from misaligned bytes is up to 2^32
// indices). Walking every element, item and property here proves that each count is backed by
// bytes the file holds, so no count can make anything allocate beyond a small multiple of the
// file's size, and a file cut short or with a garbled value is one error naming where.
// ASCII values are checked to be numbers of their type (integers for integer types and list
// counts; finite numbers a float can hold for float types): OpenMesh reads them with `>>`, and one
// that fails leaves every later value unread and the mesh silently garbage.
#include <string>

#include "sim/ply_header.h"

namespace eikon {

// Throws eikon::Error naming the file (and the line, in ASCII) when the body is shorter than the
// header's counts need, a list count is negative or runs past the end, or an ASCII value is not a
// number of its type. Bytes after the last element are allowed.
void checkPlyBody(const std::string& path, const std::string& bytes, const PlyHeader& header);

}  // namespace eikon
