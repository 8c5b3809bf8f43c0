#include "sim/mesh_file_checks.h"

#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <initializer_list>

#include "core/error.h"
#include "core/printable.h"
#include "sim/ply_body.h"

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

namespace {

bool isOneOf(const std::string& name, std::initializer_list<const char*> names) {
    for (const char* n : names)
        if (name == n) return true;
    return false;
}

// What OpenMesh 9.0's PLY reader (PLYReader.cc) can read of a header the grammar accepts. Anything
// else it misreads silently, and a misread list count is up to 2^32 indices.
void checkPlyForOpenMesh(const std::string& path, const PlyHeader& header) {
    const bool binary = header.format != PlyFormat::Ascii;
    bool readOn = true;  // OpenMesh stops after the face element: later ones are never read
    for (const PlyElement& e : header.elements) {
        const std::string where = path + ":" + std::to_string(e.line);
        const std::string element = "element '" + printable(e.name) + "'";
        if (e.name == "vertex") {
            for (const char* axis : {"x", "y", "z"}) {
                bool found = false;
                for (const PlyProperty& p : e.properties) found = found || p.name == axis;
                if (!found) throw Error(where, element + " has no '" + axis + "' property");
            }
        }
        for (const PlyProperty& p : e.properties) {
            const std::string at = path + ":" + std::to_string(p.line);
            const std::string property = "property '" + printable(p.name) + "' of " + element;
            const bool indices =
                e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index");
            if (indices && !p.isList) throw Error(at, property + " is not a list");
            if (p.isList && readOn) {
                // OpenMesh skips a list it does not know as one value, misaligning what follows.
                if (!indices)
                    throw Error(at, property +
                                        " is a list, which OpenMesh's PLY reader cannot skip "
                                        "(only the face element's vertex_indices may be one)");
                if (!isOneOf(p.countTypeName, {"uchar", "uint8", "uint16", "int"}))
                    throw Error(at, property + " has count type '" + p.countTypeName +
                                        "'; OpenMesh's PLY reader takes uchar, uint8, uint16 "
                                        "or int");
                if (!plyTypeIsIntegral(p.type))
                    throw Error(at, property + " has items of type '" + p.typeName +
                                        "'; vertex indices are integers");
            }
            // In binary, OpenMesh reads these as floats and colours as integers or floats; a
            // type it cannot convert is not consumed at all, misaligning what follows.
            if (binary && readOn && e.name == "vertex" &&
                isOneOf(p.name, {"x", "y", "z", "nx", "ny", "nz", "u", "v", "s", "t"}) &&
                plyTypeIsIntegral(p.type))
                throw Error(at, property + " has type '" + p.typeName +
                                    "'; OpenMesh reads it from a binary file only as float or "
                                    "double");
            const bool colour = isOneOf(p.name, {"red", "green", "blue", "alpha"}) ||
                                (e.name == "vertex" &&
                                 isOneOf(p.name, {"diffuse_red", "diffuse_green", "diffuse_blue"}));
            if (binary && readOn && colour && (e.name == "vertex" || e.name == "face") &&
                p.type == PlyType::Float64)
                throw Error(at, property +
                                    " has type 'double'; OpenMesh reads a colour from a binary "
                                    "file only as an integer or a float");
        }
        if (e.name == "face") readOn = false;
    }
}

}  // namespace

PlyHeader checkPlyFile(const std::string& path, const std::string& bytes) {
    const PlyHeader header = parsePlyHeader(path, bytes);
    checkPlyForOpenMesh(path, header);
    checkPlyBody(path, bytes, header);
    return header;
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
                            "vertex " + std::to_string(vertexLines) + " ('" + printable(line) +
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

}  // namespace eikon
