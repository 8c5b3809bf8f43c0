#pragma once
// ASCII OFF files (sim/off_header.h says which files OpenMesh reads as ASCII), walked before
// OpenMesh reads them, value by value as its reader takes them.
//
// OpenMesh 9.0's read_ascii (OFFReader.cc) reads the three counts after the first line with `>>`,
// sizes its buffers from them, then per vertex three coordinates (six with an N prefix) and the
// rest of the line, per face a count and that many indices (and the rest of the line with a C
// prefix). It never checks the end of the file or a failed read: a value that does not parse
// leaves the stream failed and every later count at its last value, so each remaining face
// repeats the last count. Measured: "OFF\n4000000000 4000000000 0" ran past `timeout 20`; a face
// count of 4,000,000,000 in a 72-byte file (found by fuzz_off) ran out of memory; a file cut
// short read its last number again and again, giving garbage faces and no error.
#include <string>

#include "sim/off_header.h"

namespace eikon {

// Throws eikon::Error naming the file when a count is not a whole number, the counts need more
// bytes than the file has, or a coordinate, face count or index is missing (the file ends) or is
// not a number. Bytes after the last face are allowed, as OpenMesh ignores them.
void checkAsciiOff(const std::string& path, const std::string& bytes, const OffHeader& header);

}  // namespace eikon
