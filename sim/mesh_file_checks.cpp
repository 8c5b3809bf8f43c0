#include "sim/mesh_file_checks.h"

#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "core/error.h"

namespace eikon {

namespace {

std::string withoutLineEnd(std::string line) {
    while (!line.empty() && (line.back() == '\r' || line.back() == '\n')) line.pop_back();
    return line;
}

// Parses `count` numbers from `text`; false where one is missing or not finite as a float (the
// precision TriangleMesh keeps).
bool finiteFloats(const char* text, int count) {
    for (int i = 0; i < count; ++i) {
        char* end = nullptr;
        const double value = std::strtod(text, &end);
        if (end == text || !(std::fabs(value) <= double(FLT_MAX))) return false;
        text = end;
    }
    return true;
}

}  // namespace

void checkPlyHeader(const std::string& path, const std::string& bytes) {
    if (bytes.compare(0, 3, "ply") != 0)
        throw Error(path, "not a PLY file (it does not start with 'ply')");
    // A header is a few hundred bytes; the search stops at the first megabyte of data.
    const std::size_t end = bytes.find("end_header", 0);
    if (end == std::string::npos || end > (std::size_t(1) << 20))
        throw Error(path, "the PLY header never ends (no 'end_header'): truncated or corrupt");
}

namespace {

std::uint32_t declaredStlTriangles(const std::string& bytes) {
    std::uint32_t triangles = 0;
    if (bytes.size() >= 84) std::memcpy(&triangles, bytes.data() + 80, 4);  // little-endian host
    return triangles;
}

}  // namespace

bool isAsciiStl(const std::string& bytes) {
    const bool binarySize =
        bytes.size() >= 84 && 84 + 50 * std::uint64_t(declaredStlTriangles(bytes)) == bytes.size();
    return bytes.compare(0, 5, "solid") == 0 && !binarySize;
}

void checkBinaryStl(const std::string& path, const std::string& bytes) {
    if (bytes.size() < 84)
        throw Error(path, "too short for a binary STL (" + std::to_string(bytes.size()) +
                              " bytes; the header alone is 84)");
    const std::uint32_t triangles = declaredStlTriangles(bytes);
    const std::uint64_t expected = 84 + 50 * std::uint64_t(triangles);
    if (expected != bytes.size())
        throw Error(path, "binary STL declares " + std::to_string(triangles) + " triangles (" +
                              std::to_string(expected) + " bytes) but the file has " +
                              std::to_string(bytes.size()) + " bytes: truncated or corrupt");
    for (std::uint32_t t = 0; t < triangles; ++t) {
        for (int corner = 0; corner < 3; ++corner) {
            float xyz[3];  // after the 12-byte normal of each 50-byte record
            std::memcpy(xyz, bytes.data() + 84 + 50 * std::size_t(t) + 12 + 12 * corner, 12);
            for (float c : xyz) {
                if (!std::isfinite(c))
                    throw Error(path, "triangle " + std::to_string(t + 1) + " corner " +
                                          std::to_string(corner + 1) + " is not finite");
            }
        }
    }
}

std::size_t checkVertexLines(const std::string& path, const std::string& bytes,
                             const std::string& keyword) {
    std::size_t vertexLines = 0;
    std::size_t lineNumber = 0;
    for (std::size_t start = 0; start < bytes.size();) {
        std::size_t end = bytes.find('\n', start);
        if (end == std::string::npos) end = bytes.size();
        ++lineNumber;
        const std::size_t first = bytes.find_first_not_of(" \t", start);
        const std::size_t after = first + keyword.size();
        if (first < end && after < end && bytes.compare(first, keyword.size(), keyword) == 0 &&
            (bytes[after] == ' ' || bytes[after] == '\t')) {
            ++vertexLines;
            const std::string line = withoutLineEnd(bytes.substr(first, end - first));
            if (!finiteFloats(line.c_str() + keyword.size(), 3))
                throw Error(path + ":" + std::to_string(lineNumber),
                            "vertex " + std::to_string(vertexLines) + " ('" + line +
                                "') is not three finite numbers");
        }
        start = end + 1;
    }
    return vertexLines;
}

void checkObjVertices(const std::string& path, const std::string& bytes, std::size_t verticesRead) {
    const std::size_t vertexLines = checkVertexLines(path, bytes, "v");
    if (vertexLines != verticesRead)
        throw Error(path, "the file has " + std::to_string(vertexLines) +
                              " vertex lines but OpenMesh read " + std::to_string(verticesRead) +
                              " vertices: corrupt file");
}

void checkOffLength(const std::string& path, const std::string& bytes, std::size_t verticesRead,
                    const std::vector<std::vector<int>>& facesRead) {
    std::size_t tokens = 0;
    bool binary = false;
    for (std::size_t i = 0; i < bytes.size();) {
        if (bytes[i] == '#') {
            i = bytes.find('\n', i);
            if (i == std::string::npos) break;
            continue;
        }
        if (std::isspace((unsigned char)bytes[i])) {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < bytes.size() && !std::isspace((unsigned char)bytes[i]) && bytes[i] != '#') ++i;
        ++tokens;
        if (tokens == 2 && bytes.compare(start, i - start, "BINARY") == 0) binary = true;
        if (binary) return;  // binary OFF: OpenMesh reads counted records; nothing to count here
    }
    std::size_t needed = 1 + 3 + 3 * verticesRead;  // keyword, three counts, coordinates
    for (const std::vector<int>& face : facesRead) needed += 1 + face.size();
    if (tokens < needed)
        throw Error(path, "truncated: " + std::to_string(verticesRead) + " vertices and " +
                              std::to_string(facesRead.size()) + " faces need " +
                              std::to_string(needed) + " numbers, the file has " +
                              std::to_string(tokens));
}

}  // namespace eikon
