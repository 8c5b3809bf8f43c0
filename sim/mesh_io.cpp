#include "sim/mesh_io.h"

#include <OpenMesh/Core/IO/MeshIO.hh>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "core/error.h"
#include "core/printable.h"
#include "sim/mesh_file_checks.h"
#include "sim/obj_face_lines.h"
#include "sim/off_ascii.h"
#include "sim/off_binary.h"
#include "sim/off_header.h"
#include "sim/openmesh_face_recorder.h"
#include "sim/openmesh_messages.h"

namespace eikon {

namespace {

std::string lowercaseExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::string readBytes(const std::string& path) {
    if (std::filesystem::is_directory(path)) throw Error(path, "is a directory, not a mesh file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path, std::string("cannot open: ") + std::strerror(errno));
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string formatName(const std::string& ext) {
    std::string name = ext.substr(1);
    for (char& c : name) c = char(std::toupper((unsigned char)c));
    return name;
}

// Every index names a vertex the file has, and every polygon has at least three corners.
void checkFaces(const std::string& path, const OpenMeshFaceRecorder& read) {
    for (std::size_t f = 0; f < read.faces.size(); ++f) {
        const std::vector<int>& face = read.faces[f];
        if (face.size() < 3)
            throw Error(path, "face " + std::to_string(f + 1) + " has " +
                                  std::to_string(face.size()) + " vertices (at least 3 needed)");
        for (int v : face) {
            if (v < 0 || std::size_t(v) >= read.points.size())
                throw Error(path, "face " + std::to_string(f + 1) +
                                      " refers to a vertex the file does not have (" +
                                      std::to_string(read.points.size()) + " vertices)");
        }
    }
}

glm::vec3 finitePosition(const std::string& path, std::size_t index, const OpenMesh::Vec3d& p) {
    for (int k = 0; k < 3; ++k) {
        if (!(std::fabs(p[k]) <= double(FLT_MAX)))
            throw Error(path, "vertex " + std::to_string(index + 1) + " is not finite (" +
                                  std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " +
                                  std::to_string(p[2]) + ")");
    }
    return glm::vec3(float(p[0]), float(p[1]), float(p[2]));
}

TriangleMesh fanTriangulated(const std::string& path, const OpenMeshFaceRecorder& read) {
    TriangleMesh mesh;
    mesh.positions.reserve(read.points.size());
    for (std::size_t i = 0; i < read.points.size(); ++i)
        mesh.positions.push_back(finitePosition(path, i, read.points[i]));
    for (const std::vector<int>& face : read.faces) {
        for (std::size_t k = 1; k + 1 < face.size(); ++k)
            mesh.triangles.emplace_back(unsigned(face[0]), unsigned(face[k]),
                                        unsigned(face[k + 1]));
    }
    return mesh;
}

}  // namespace

bool isMeshFile(const std::string& path) {
    const std::string ext = lowercaseExtension(path);
    return ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl";
}

LoadedMesh loadMesh(const std::string& path) {
    const std::string ext = lowercaseExtension(path);
    if (!isMeshFile(path))
        throw Error(path, "unknown mesh format '" + ext +
                              "' (eikon reads .obj, .off, .ply and .stl meshes)");
    const std::string bytes = readBytes(path);
    if (bytes.empty()) throw Error(path, "empty file");
    PlyHeader ply;
    if (ext == ".ply") ply = checkPlyFile(path, bytes);
    OffHeader off;
    if (ext == ".off") {
        off = readOffHeader(bytes);
        if (off.binary)
            checkBinaryOff(path, bytes, off);
        else if (off.readable)  // otherwise OpenMesh refuses it, and says so
            checkAsciiOff(path, bytes, off);
    }
    if (ext == ".obj") checkObjFaceLines(path, bytes);
    if (ext == ".stl") {
        if (isAsciiStl(bytes))
            checkVertexLines(path, bytes, "vertex");
        else
            checkBinaryStl(path, bytes);
    }

    OpenMeshFaceRecorder read;
    LoadedMesh loaded;
    {
        OpenMeshMessages messages;
        OpenMesh::IO::Options options;  // positions and faces only
        bool ok = false;
        if (ext == ".ply") {
            // OpenMesh parses only the header our grammar wrote, never the file's own.
            std::istringstream in(canonicalPlyHeader(ply) + bytes.substr(ply.bodyOffset),
                                  std::ios::binary);
            ok = OpenMesh::IO::IOManager().read(in, "ply", read, options);
        } else {
            ok = OpenMesh::IO::IOManager().read(path, read, options);
        }
        // OpenMesh's notes quote the file (a material library's name): escaped once, here.
        for (const std::string& note : messages.lines())
            loaded.notes.push_back(printable(note, 200));
        if (!ok) {
            std::string reason = "not a readable " + formatName(ext) + " file";
            if (!loaded.notes.empty()) reason += " (OpenMesh: " + loaded.notes.back() + ")";
            throw Error(path, reason);
        }
    }
    if (ext == ".obj") checkObjVertices(path, bytes, read.points.size());
    if (read.faces.empty())
        throw Error(path, "no faces (" + std::to_string(read.points.size()) +
                              " vertices): not a surface mesh, or not a " + formatName(ext) +
                              " file");
    checkFaces(path, read);
    loaded.mesh = fanTriangulated(path, read);
    loaded.faces = read.faces.size();
    return loaded;
}

}  // namespace eikon
