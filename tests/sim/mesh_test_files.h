#pragma once
// Small generated meshes and writers for every format the loader reads, so that mesh tests can
// make good and broken files without OpenMesh (the writers are independent of the readers).
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "support/contains.h"

namespace eikon::test {

struct PolygonMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::vector<int>> faces;  // 0-based, counter-clockwise seen from outside
};

// The unit cube [0,1]³ as six outward quads.
inline PolygonMesh unitCubeQuads() {
    PolygonMesh m;
    for (int i = 0; i < 8; ++i)
        m.positions.emplace_back(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
    m.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    return m;
}

// The same cube as twelve triangles (each quad split along its first diagonal).
inline PolygonMesh unitCubeTriangles() {
    PolygonMesh quads = unitCubeQuads(), m;
    m.positions = quads.positions;
    for (const std::vector<int>& q : quads.faces) {
        m.faces.push_back({q[0], q[1], q[2]});
        m.faces.push_back({q[0], q[2], q[3]});
    }
    return m;
}

inline std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

inline void writeObj(const std::string& path, const PolygonMesh& m) {
    std::ostringstream out;
    for (const glm::vec3& p : m.positions) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const std::vector<int>& f : m.faces) {
        out << 'f';
        for (int v : f) out << ' ' << v + 1;
        out << '\n';
    }
    writeText(path, out.str());
}

// Vertex lines "x y z", then face lines "n i j k …": the body of ASCII OFF and PLY alike.
inline std::string countedPolygons(const PolygonMesh& m) {
    std::ostringstream out;
    for (const glm::vec3& p : m.positions) out << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const std::vector<int>& f : m.faces) {
        out << f.size();
        for (int v : f) out << ' ' << v;
        out << '\n';
    }
    return out.str();
}

inline void writeOff(const std::string& path, const PolygonMesh& m) {
    std::ostringstream out;
    out << "OFF\n" << m.positions.size() << ' ' << m.faces.size() << " 0\n";
    writeText(path, out.str() + countedPolygons(m));
}

inline std::string plyHeader(const PolygonMesh& m, const std::string& format) {
    std::ostringstream out;
    out << "ply\nformat " << format << " 1.0\nelement vertex " << m.positions.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << m.faces.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    return out.str();
}

inline void writePlyAscii(const std::string& path, const PolygonMesh& m) {
    writeText(path, plyHeader(m, "ascii") + countedPolygons(m));
}

template <typename T>
void appendBytes(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));  // little-endian hosts only, as the formats say
    out.append(bytes, sizeof(T));
}

inline std::string plyBinaryBytes(const PolygonMesh& m) {
    std::string out = plyHeader(m, "binary_little_endian");
    for (const glm::vec3& p : m.positions) {
        appendBytes(out, p.x);
        appendBytes(out, p.y);
        appendBytes(out, p.z);
    }
    for (const std::vector<int>& f : m.faces) {
        appendBytes(out, std::uint8_t(f.size()));
        for (int v : f) appendBytes(out, std::int32_t(v));
    }
    return out;
}

// Binary OFF as OpenMesh reads it: the first line, three little-endian 32-bit counts, per vertex
// x, y, z as float then `extraVertexBytes` zero bytes (what a C, N or ST prefix adds), per face
// its count and 32-bit indices.
inline std::string offBinaryBytes(const PolygonMesh& m, const std::string& firstLine = "OFF BINARY",
                                  std::size_t extraVertexBytes = 0) {
    std::string out = firstLine + "\n";
    appendBytes(out, std::uint32_t(m.positions.size()));
    appendBytes(out, std::uint32_t(m.faces.size()));
    appendBytes(out, std::uint32_t(0));
    for (const glm::vec3& p : m.positions) {
        appendBytes(out, p.x);
        appendBytes(out, p.y);
        appendBytes(out, p.z);
        out.append(extraVertexBytes, '\0');
    }
    for (const std::vector<int>& f : m.faces) {
        appendBytes(out, std::uint32_t(f.size()));
        for (int v : f) appendBytes(out, std::uint32_t(v));
    }
    return out;
}

// STL keeps no indices: each triangle of the fan-triangulated polygons is written with its
// corners' positions.
inline std::vector<std::vector<glm::vec3>> stlTriangles(const PolygonMesh& m) {
    std::vector<std::vector<glm::vec3>> triangles;
    for (const std::vector<int>& f : m.faces)
        for (std::size_t k = 1; k + 1 < f.size(); ++k)
            triangles.push_back({m.positions[f[0]], m.positions[f[k]], m.positions[f[k + 1]]});
    return triangles;
}

inline void writeStlAscii(const std::string& path, const PolygonMesh& m) {
    std::ostringstream out;
    out << "solid test\n";
    for (const std::vector<glm::vec3>& t : stlTriangles(m)) {
        out << "facet normal 0 0 0\nouter loop\n";
        for (const glm::vec3& p : t) out << "vertex " << p.x << ' ' << p.y << ' ' << p.z << '\n';
        out << "endloop\nendfacet\n";
    }
    out << "endsolid test\n";
    writeText(path, out.str());
}

inline std::string stlBinaryBytes(const PolygonMesh& m) {
    const std::vector<std::vector<glm::vec3>> triangles = stlTriangles(m);
    std::string out(80, ' ');
    appendBytes(out, std::uint32_t(triangles.size()));
    for (const std::vector<glm::vec3>& t : triangles) {
        for (int k = 0; k < 3; ++k) appendBytes(out, 0.0f);  // normal: readers recompute it
        for (const glm::vec3& p : t) {
            appendBytes(out, p.x);
            appendBytes(out, p.y);
            appendBytes(out, p.z);
        }
        appendBytes(out, std::uint16_t(0));
    }
    return out;
}

}  // namespace eikon::test
