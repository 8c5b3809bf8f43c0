// Loading OBJ, OFF, PLY and STL through OpenMesh into TriangleMesh: every format gives the same
// cube, the shared real meshes come back with SOURCES.md's counts, and broken files give one
// eikon::Error naming the file.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "sim/mesh_io.h"
#include "sim/mesh_test_files.h"
#include "support/test_paths.h"

using eikon::Error;
using eikon::LoadedMesh;
using eikon::loadMesh;
using namespace eikon::test;

namespace {

// The error loading `path` gives, checked to name the file first.
std::string loadError(const std::string& path) {
    try {
        loadMesh(path);
    } catch (const Error& e) {
        INFO(e.what());
        CHECK(e.where().rfind(path, 0) == 0);
        return e.reason();
    }
    FAIL("loading " << path << " did not throw");
    return {};
}

void checkIsUnitCube(const LoadedMesh& loaded, std::size_t vertices, std::size_t faces) {
    CHECK(loaded.mesh.positions.size() == vertices);
    CHECK(loaded.faces == faces);
    CHECK(loaded.mesh.triangles.size() == 12);
    CHECK(eikon::signedVolume(loaded.mesh) == Approx(1.0).epsilon(1e-12));
    const eikon::Bounds3 b = eikon::boundsOf(loaded.mesh);
    CHECK(b.min == glm::vec3(0.0f));
    CHECK(b.max == glm::vec3(1.0f));
}

}  // namespace

TEST_CASE("every mesh format reads the same cube, polygons fan-triangulated", "[mesh_io]") {
    const std::string dir = scratchDir("mesh_io_formats");
    const PolygonMesh quads = unitCubeQuads(), triangles = unitCubeTriangles();
    writeObj(dir + "/cube.obj", quads);
    writeOff(dir + "/cube.off", quads);
    writePlyAscii(dir + "/cube.ply", quads);
    writeText(dir + "/cube_binary.PLY", plyBinaryBytes(quads));  // extensions in any case
    writeStlAscii(dir + "/cube.stl", triangles);
    writeText(dir + "/cube_binary.stl", stlBinaryBytes(triangles));
    // Some exporters start a binary STL's header with "solid", as if it were ASCII.
    writeText(dir + "/cube_solid_binary.stl", "solid" + stlBinaryBytes(triangles).substr(5));
    checkIsUnitCube(loadMesh(dir + "/cube.obj"), 8, 6);
    checkIsUnitCube(loadMesh(dir + "/cube.off"), 8, 6);
    checkIsUnitCube(loadMesh(dir + "/cube.ply"), 8, 6);
    checkIsUnitCube(loadMesh(dir + "/cube_binary.PLY"), 8, 6);
    // STL stores corners, not indices; OpenMesh's reader welds equal positions.
    checkIsUnitCube(loadMesh(dir + "/cube.stl"), 8, 12);
    checkIsUnitCube(loadMesh(dir + "/cube_binary.stl"), 8, 12);
    checkIsUnitCube(loadMesh(dir + "/cube_solid_binary.stl"), 8, 12);
}

TEST_CASE("the shared meshes load with SOURCES.md's vertex and triangle counts", "[mesh_io]") {
    struct Expected {
        const char* file;
        std::size_t vertices, faces, triangles;
    };
    const Expected all[] = {
        {"stanford-bunny.obj", 35947, 69451, 69451},
        {"bun_zipper_res4.ply", 453, 948, 948},
        {"bunny_closed.obj", 3301, 6598, 6598},
        {"armadillo.obj", 14587, 29170, 29170},
        {"spot.obj", 2930, 5856, 5856},
        {"teapot_closed.obj", 7850, 8028, 15704},
        {"teapot_closed_tri.obj", 7850, 15704, 15704},
        {"wine_glass.obj", 8066, 8064, 16128},
        {"wine_glass_tri.obj", 8066, 16128, 16128},
    };
    for (const Expected& e : all) {
        INFO(e.file);
        const LoadedMesh loaded = loadMesh(sharedData(std::string("meshes/") + e.file));
        CHECK(loaded.mesh.positions.size() == e.vertices);
        CHECK(loaded.faces == e.faces);
        CHECK(loaded.mesh.triangles.size() == e.triangles);
    }
}

TEST_CASE("mesh loading tolerates the teapot's CRLF lines and missing material file", "[mesh_io]") {
    const LoadedMesh teapot = loadMesh(sharedData("meshes/teapot_closed.obj"));
    const eikon::Bounds3 b = eikon::boundsOf(teapot.mesh);
    CHECK(b.min.x == Approx(-71.892532));
    CHECK(b.max.x == Approx(82.293999));
    CHECK(b.max.y == Approx(79.006561));
    CHECK(b.max.z == Approx(47.928356));
    bool mentionsMaterial = false;
    for (const std::string& note : teapot.notes) mentionsMaterial |= contains(note, "default.mtl");
    CHECK(mentionsMaterial);
}

TEST_CASE("the coarse bunny keeps the faces OpenMesh's half-edge mesh refuses", "[mesh_io]") {
    // Read into an OpenMesh TriMesh, 115 of its faces get private vertex copies (798 vertices);
    // the loader keeps the file's 453 and every index as written.
    const LoadedMesh res4 = loadMesh(sharedData("meshes/bun_zipper_res4.ply"));
    CHECK(res4.mesh.positions.size() == 453);
    CHECK(res4.mesh.triangles.size() == 948);
    for (const glm::uvec3& t : res4.mesh.triangles)
        CHECK(glm::all(glm::lessThan(t, glm::uvec3(453))));
}

TEST_CASE("unknown, missing, empty and unreadable mesh files are errors naming the file",
          "[mesh_io]") {
    const std::string dir = scratchDir("mesh_io_unreadable");
    writeText(dir + "/cube.xyz", "v 0 0 0\n");
    CHECK(contains(loadError(dir + "/cube.xyz"), "unknown mesh format '.xyz'"));
    CHECK(contains(loadError(dir + "/missing.obj"), "cannot open"));
    writeText(dir + "/empty.off", "");
    CHECK(contains(loadError(dir + "/empty.off"), "empty file"));
    writeText(dir + "/junk.off", "hello world\n");
    CHECK(contains(loadError(dir + "/junk.off"), "not a readable OFF file"));
    writeText(dir + "/junk.ply", "hello world\n");
    CHECK(contains(loadError(dir + "/junk.ply"), "not a PLY file"));
    writeText(dir + "/junk.obj", std::string("\x00\x01\x02", 3));
    CHECK(contains(loadError(dir + "/junk.obj"), "no faces"));
}

TEST_CASE("a mesh file without faces is an error", "[mesh_io]") {
    const std::string dir = scratchDir("mesh_io_no_faces");
    PolygonMesh points = unitCubeQuads();
    points.faces.clear();
    writeObj(dir + "/points.obj", points);
    CHECK(contains(loadError(dir + "/points.obj"), "no faces (8 vertices)"));
    writePlyAscii(dir + "/points.ply", points);
    CHECK(contains(loadError(dir + "/points.ply"), "no faces"));
}

TEST_CASE("truncated and corrupt mesh files are errors, not garbage or a hang", "[mesh_io]") {
    const std::string dir = scratchDir("mesh_io_truncated");
    const PolygonMesh cube = unitCubeTriangles();

    const std::string stl = stlBinaryBytes(cube);
    writeText(dir + "/cut.stl", stl.substr(0, stl.size() - 20));
    CHECK(contains(loadError(dir + "/cut.stl"), "declares 12 triangles"));
    writeText(dir + "/short.stl", stl.substr(0, 40));
    CHECK(contains(loadError(dir + "/short.stl"), "too short for a binary STL"));

    // OpenMesh loops forever on a PLY header that never ends.
    const std::string ply = plyBinaryBytes(cube);
    writeText(dir + "/cut_header.ply", ply.substr(0, ply.find("end_header") - 5));
    CHECK(contains(loadError(dir + "/cut_header.ply"), "header never ends"));
    writeText(dir + "/cut_data.ply", ply.substr(0, ply.find("end_header") + 11 + 60));
    CHECK(contains(loadError(dir + "/cut_data.ply"),
                   "element 'vertex' declares 8 items, which need at least 96 bytes, but the file "
                   "has 60 bytes left for it: truncated or corrupt"));

    writeOff(dir + "/whole.off", cube);
    const std::string off = readText(dir + "/whole.off");
    writeText(dir + "/cut.off", off.substr(0, off.size() - 12));
    CHECK(contains(loadError(dir + "/cut.off"), "truncated"));

    // Counts the file cannot back: OpenMesh's OFF reader looped over them past `timeout 20`.
    writeText(dir + "/huge.off", "OFF\n4000000000 4000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    CHECK(loadError(dir + "/huge.off") ==
          "the OFF header declares 4000000000 vertices and 4000000000 faces, which need at least "
          "32000000000 bytes, but 27 follow the counts: truncated or corrupt");
    writeText(dir + "/bad_counts.off", "OFF\n3 -1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    CHECK(loadError(dir + "/bad_counts.off") ==
          "expected the vertex, face and edge counts after 'OFF', got '3 -1 0'");
    // Raw bytes quoted from a file are escaped.
    writeText(dir + "/escape.obj", "v 0 0 0\nv \x1b[2J 0 0\nv 0 1 0\nf 1 2 3\n");
    CHECK(contains(loadError(dir + "/escape.obj"), "vertex 2 ('v \\x1b[2J 0 0')"));

    writeText(dir + "/bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
    CHECK(contains(loadError(dir + "/bad_index.obj"), "face 1 refers to a vertex"));
}

TEST_CASE("NaN and infinite mesh vertices are errors naming the file and the vertex", "[mesh_io]") {
    const std::string dir = scratchDir("mesh_io_nan");
    // OpenMesh's OBJ reader would skip these lines silently and shift later indices.
    writeText(dir + "/nan.obj", "v 0 0 0\nv nan 1 0\nv 0 1 0\nv 1 1 1\nf 1 3 4\n");
    const std::string nanReason = loadError(dir + "/nan.obj");
    CHECK(contains(nanReason, "vertex 2 ('v nan 1 0') is not three finite numbers"));
    writeText(dir + "/inf.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1e39 0\r\nf 1 2 3\r\n");
    CHECK(contains(loadError(dir + "/inf.obj"), "vertex 3 ('v 0 1e39 0')"));
    try {
        loadMesh(dir + "/nan.obj");
    } catch (const Error& e) {
        CHECK(e.where() == dir + "/nan.obj:2");
    }

    PolygonMesh cube = unitCubeTriangles();
    cube.positions[5].y = std::numeric_limits<float>::quiet_NaN();
    writeText(dir + "/nan.ply", plyBinaryBytes(cube));
    CHECK(contains(loadError(dir + "/nan.ply"), "vertex 6 is not finite"));
    cube.positions[5].y = std::numeric_limits<float>::infinity();
    writeText(dir + "/inf.stl", stlBinaryBytes(cube));
    CHECK(contains(loadError(dir + "/inf.stl"), "is not finite"));
    writeText(dir + "/nan.stl",
              stlBinaryBytes(unitCubeTriangles()).replace(84 + 12, 4, "\xff\xff\xff\x7f"));
    CHECK(contains(loadError(dir + "/nan.stl"), "triangle 1 corner 1 is not finite"));
    writeText(dir + "/nan_ascii.stl",
              "solid t\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex nan 0 0\n"
              "vertex 0 1 0\nendloop\nendfacet\nendsolid t\n");
    CHECK(contains(loadError(dir + "/nan_ascii.stl"), "vertex 2 ('vertex nan 0 0')"));
}

TEST_CASE("OpenMesh's notes that quote the file are escaped", "[mesh_io]") {
    // A material library name with an escape sequence would otherwise reach the terminal raw in
    // `eikon info`'s reader notes.
    const std::string dir = scratchDir("mesh_io_notes");
    writeText(dir + "/esc.obj", "mtllib \x1b[31mred.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const LoadedMesh loaded = loadMesh(dir + "/esc.obj");
    REQUIRE(loaded.notes.size() == 1);
    CHECK(contains(loaded.notes[0], "\\x1b[31mred.mtl"));
    CHECK(loaded.notes[0].find('\x1b') == std::string::npos);
}
