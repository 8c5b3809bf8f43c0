#include "sim/off_binary.h"

#include <cstdint>

#include "core/error.h"

namespace eikon {

namespace {

std::uint32_t littleEndian32(const std::string& bytes, std::uint64_t at) {
    const auto b = [&](std::uint64_t k) { return std::uint32_t(std::uint8_t(bytes[at + k])); };
    return b(0) | b(1) << 8 | b(2) << 16 | b(3) << 24;
}

}  // namespace

void checkBinaryOff(const std::string& path, const std::string& bytes, const OffHeader& header) {
    if (!header.lineEnded)
        throw Error(path, "binary OFF: the header line has no end, so there are no counts");
    std::uint64_t at = header.bodyOffset;
    const auto left = [&] { return std::uint64_t(bytes.size()) - at; };
    if (left() < 12)
        throw Error(path, "binary OFF: the file ends before the vertex, face and edge counts (" +
                              std::to_string(left()) + " of 12 bytes)");
    const std::uint64_t vertices = littleEndian32(bytes, at);
    const std::uint64_t faces = littleEndian32(bytes, at + 4);
    at += 12;
    const std::uint64_t vertexBytes = vertices * header.vertexBytes;
    // Every face takes at least its 4-byte count: a face count the file cannot hold fails here,
    // before the walk.
    if (vertexBytes + faces * 4 > left())
        throw Error(path, "binary OFF declares " + std::to_string(vertices) + " vertices and " +
                              std::to_string(faces) + " faces, which need at least " +
                              std::to_string(vertexBytes + faces * 4) + " bytes, but " +
                              std::to_string(left()) + " follow the counts: truncated or corrupt");
    at += vertexBytes;
    for (std::uint64_t f = 0; f < faces; ++f) {
        if (left() < 4)
            throw Error(path, "binary OFF: the file ends before face " + std::to_string(f + 1) +
                                  " of " + std::to_string(faces) + ": truncated");
        const std::uint64_t corners = littleEndian32(bytes, at);
        at += 4;
        if (corners * 4 > left())
            throw Error(path, "binary OFF: face " + std::to_string(f + 1) + " declares " +
                                  std::to_string(corners) + " vertices, but " +
                                  std::to_string(left()) + " bytes are left: truncated or corrupt");
        at += corners * 4;
    }
}

}  // namespace eikon
