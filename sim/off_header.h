#pragma once
// What OpenMesh 9.0's OFF reader (OFFReader.cc) makes of an OFF file's first line, so that the
// checks before it (sim/mesh_file_checks.h for ASCII, sim/off_binary.h for binary) look at the
// same bytes it will read. Measured against it:
// - the line must start with "OFF" after an optional prefix [ST][C][N][4][n] in that order;
//   anything may follow on the line ("OFF\x01..." reads as ASCII OFF); with a '4' or 'n' prefix
//   it refuses the file;
// - it is binary when "BINARY" follows "OFF" after exactly one character, whatever that is;
// - the counts are read from after the first line, never from the line itself: "OFF 3 1 0\n"
//   followed by "4000000000 4000000000 0" sized its buffers from the second line.
#include <cstddef>
#include <cstdint>
#include <string>

namespace eikon {

struct OffHeader {
    bool readable = false;  // OpenMesh reads it; otherwise it fails, saying so
    bool binary = false;
    std::size_t bodyOffset = 0;  // just past the first line's '\n' (the file's size without one)
    bool lineEnded = false;      // the first line has a '\n'
    bool normals = false;        // N: each vertex has a normal after its position
    bool colours = false;  // C: vertices and faces have colours, each face's on its line's rest
    // Binary: the bytes of one vertex record (x, y, z as float; 8 more for ST, 12 for C, 12
    // for N).
    std::uint64_t vertexBytes = 12;
};

OffHeader readOffHeader(const std::string& bytes);

}  // namespace eikon
