#pragma once
// Binary OFF files (sim/off_header.h says which files OpenMesh reads as binary), checked before
// OpenMesh reads them.
//
// OpenMesh 9.0's reader takes three 32-bit little-endian counts after the first line, sizes its
// buffers from them, and loops over the faces (and each face's indices) without looking for the
// end of the file. Measured: a face count of 2^32 − 1 in a 60-byte file ran out of memory after
// 19 s, a vertex count of 2^31 or a face of 2^32 − 16 indices ran past `timeout 20` at 2 GB, and
// a file with no line end read its counts from uninitialised memory. Walking the records here
// first proves every count is backed by bytes.
#include <string>

#include "sim/off_header.h"

namespace eikon {

// Throws eikon::Error naming the file when the bytes after the first line do not hold the three
// counts, the vertex records the counts and the header call for, and every face record (a count,
// then that many 4-byte indices). Bytes after the last face are allowed, as OpenMesh ignores
// them.
void checkBinaryOff(const std::string& path, const std::string& bytes, const OffHeader& header);

}  // namespace eikon
