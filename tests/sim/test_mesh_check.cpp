// Mesh topology and sanity: the shared real meshes match SOURCES.md's numbers, and generated bad
// meshes (open, non-manifold, empty, NaN, degenerate, absurdly scaled) give the promised reports
// and errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <tuple>

#include "core/error.h"
#include "sim/mesh_check.h"
#include "sim/mesh_io.h"
#include "sim/mesh_test_files.h"
#include "support/test_paths.h"

using eikon::checkMesh;
using eikon::MeshReport;
using eikon::requireClosedRefractiveMesh;
using eikon::TriangleMesh;
using eikon::test::contains;
using eikon::test::sharedData;

namespace {

TriangleMesh toTriangles(const eikon::test::PolygonMesh& m) {
    TriangleMesh t;
    t.positions = m.positions;
    for (const std::vector<int>& f : m.faces)
        for (std::size_t k = 1; k + 1 < f.size(); ++k)
            t.triangles.emplace_back(f[0], f[k], f[k + 1]);
    return t;
}

TriangleMesh unitCube() {
    return toTriangles(eikon::test::unitCubeTriangles());
}

// The union of two meshes with equal positions welded into one vertex, so that shapes touching
// at an edge or a corner share those vertices.
TriangleMesh weldedUnion(const TriangleMesh& a, const TriangleMesh& b) {
    TriangleMesh out;
    std::map<std::tuple<float, float, float>, unsigned> index;
    auto add = [&](const TriangleMesh& m) {
        std::vector<unsigned> remap;
        for (const glm::vec3& p : m.positions) {
            auto [it, inserted] = index.emplace(std::make_tuple(p.x, p.y, p.z), 0u);
            if (inserted) {
                it->second = unsigned(out.positions.size());
                out.positions.push_back(p);
            }
            remap.push_back(it->second);
        }
        for (const glm::uvec3& t : m.triangles)
            out.triangles.emplace_back(remap[t.x], remap[t.y], remap[t.z]);
    };
    add(a);
    add(b);
    return out;
}

TriangleMesh translated(TriangleMesh m, glm::vec3 offset) {
    for (glm::vec3& p : m.positions) p += offset;
    return m;
}

std::string refractiveError(const MeshReport& report) {
    try {
        requireClosedRefractiveMesh(report, "test.obj");
    } catch (const eikon::Error& e) {
        CHECK(e.where() == "test.obj");
        return e.reason();
    }
    FAIL("requireClosedRefractiveMesh did not throw");
    return {};
}

}  // namespace

TEST_CASE("mesh check reproduces SOURCES.md's topology of every shared mesh", "[mesh_check]") {
    struct Expected {
        const char* file;
        std::size_t triangles, boundaryEdges, holes, nonManifoldEdges, duplicates;
        int volumeSign;  // of a watertight mesh; 0 where it is open
        std::size_t components;
    };
    const Expected all[] = {
        {"stanford-bunny.obj", 69451, 223, 5, 0, 0, 0, 1},
        {"bun_zipper_res4.ply", 948, 26, 4, 70, 40, 0, 0},
        {"bunny_closed.obj", 6598, 0, 0, 0, 0, +1, 1},
        {"armadillo.obj", 29170, 0, 0, 0, 0, +1, 1},
        {"spot.obj", 5856, 0, 0, 0, 0, +1, 1},
        {"teapot_closed.obj", 15704, 0, 0, 0, 0, +1, 2},
        {"teapot_closed_tri.obj", 15704, 0, 0, 0, 0, +1, 2},
        {"wine_glass.obj", 16128, 0, 0, 0, 0, +1, 1},
        {"wine_glass_tri.obj", 16128, 0, 0, 0, 0, +1, 1},
    };
    for (const Expected& e : all) {
        INFO(e.file);
        const MeshReport r =
            checkMesh(eikon::loadMesh(sharedData(std::string("meshes/") + e.file)));
        CHECK(r.triangles == e.triangles);
        CHECK(r.boundaryEdges == e.boundaryEdges);
        CHECK(r.holeSizes.size() == e.holes);
        CHECK(r.nonManifoldEdges == e.nonManifoldEdges);
        CHECK(r.duplicateTriangles == e.duplicates);
        CHECK(r.inconsistentEdges == 0);
        CHECK(r.watertight() == (e.volumeSign != 0));
        if (e.volumeSign != 0) {
            CHECK(r.signedVolume * e.volumeSign > 0.0);
            CHECK_NOTHROW(requireClosedRefractiveMesh(r, e.file));
        } else {
            CHECK_THROWS_AS(requireClosedRefractiveMesh(r, e.file), eikon::Error);
        }
        if (e.components != 0) CHECK(r.components == e.components);
        CHECK(r.scaleProblem.empty());
    }
}

TEST_CASE("mesh check gives SOURCES.md's details of the two open bunnies", "[mesh_check]") {
    const MeshReport scan = checkMesh(eikon::loadMesh(sharedData("meshes/stanford-bunny.obj")));
    CHECK(scan.vertices == 35947);
    CHECK(scan.unreferencedVertices == 1113);
    CHECK(scan.eulerCharacteristic == -3);
    CHECK(scan.nonManifoldVertices == 0);
    CHECK(scan.complexHoles == 0);
    CAPTURE(scan.holeSizes);
    CHECK(scan.bounds.min.x == Approx(-0.09469));
    CHECK(scan.bounds.max.y == Approx(0.187321));
    const std::string reason = refractiveError(scan);
    CHECK(contains(reason, "not watertight: 223 boundary edges in 5 holes (largest " +
                               std::to_string(scan.holeSizes[0]) + " edges); set close_holes to " +
                               std::to_string(scan.holeSizes[0])));

    const MeshReport res4 = checkMesh(eikon::loadMesh(sharedData("meshes/bun_zipper_res4.ply")));
    CHECK(res4.nonManifoldVertices == 4);
    // Its 26 boundary edges: one 4-edge loop, two loops touching at non-manifold vertices
    // (13 edges), and two chains (7 and 2 edges) that end where non-manifold edges begin.
    CHECK(res4.holeSizes == std::vector<std::size_t>{13, 7, 4, 2});
    CHECK(res4.complexHoles == 3);
    CHECK(res4.largestSimpleHole == 4);
    CHECK(res4.degenerateTriangles == 0);
    const std::string res4Reason = refractiveError(res4);
    CHECK(contains(res4Reason, "26 boundary edges in 4 holes"));
    CHECK(contains(res4Reason, "70 non-manifold edges"));
    CHECK(contains(res4Reason, "4 non-manifold vertices"));
    CHECK(contains(res4Reason, "3 holes are not simple loops"));
    CHECK(!contains(res4Reason, "duplicate"));  // reported, but harmless on its own
    const std::vector<std::string> problems = eikon::meshProblems(res4);
    CHECK(std::count(problems.begin(), problems.end(),
                     "40 duplicate faces (same vertices as an earlier face)") == 1);
}

TEST_CASE("a closed unit cube is a clean refractive mesh", "[mesh_check]") {
    const MeshReport r = checkMesh(unitCube());
    CHECK(r.watertight());
    CHECK(r.eulerCharacteristic == 2);
    CHECK(r.components == 1);
    CHECK(r.signedVolume == Approx(1.0));
    CHECK(eikon::meshProblems(r).empty());
    CHECK_NOTHROW(requireClosedRefractiveMesh(r, "cube"));
}

TEST_CASE("an open cube is not watertight and says how to close it", "[mesh_check]") {
    TriangleMesh open = unitCube();
    open.triangles.erase(open.triangles.begin(), open.triangles.begin() + 2);  // the z = 0 face
    const MeshReport r = checkMesh(open);
    CHECK(r.boundaryEdges == 4);
    CHECK(r.holeSizes == std::vector<std::size_t>{4});
    CHECK(refractiveError(r) ==
          "not watertight: 4 boundary edges in 1 hole (largest 4 edges); set close_holes to 4 to "
          "fill holes of up to 4 edges");
}

TEST_CASE("two cubes sharing an edge or a corner are non-manifold", "[mesh_check]") {
    const MeshReport edge = checkMesh(weldedUnion(unitCube(), translated(unitCube(), {1, 1, 0})));
    CHECK(edge.vertices == 14);
    CHECK(edge.nonManifoldEdges == 1);
    CHECK(edge.boundaryEdges == 0);
    CHECK(!edge.watertight());
    CHECK(refractiveError(edge) == "1 non-manifold edge (used by more than two faces)");

    const MeshReport corner = checkMesh(weldedUnion(unitCube(), translated(unitCube(), {1, 1, 1})));
    CHECK(corner.nonManifoldEdges == 0);
    CHECK(corner.nonManifoldVertices == 1);
    CHECK(corner.watertight());  // every edge has two faces; the corner is still not a surface
    CHECK(refractiveError(corner) ==
          "1 non-manifold vertex (the faces around each form more than one fan)");
}

TEST_CASE("empty and NaN meshes cannot be refractive objects", "[mesh_check]") {
    CHECK(refractiveError(checkMesh(TriangleMesh{})) == "no triangles");
    TriangleMesh nan = unitCube();
    nan.positions[6].z = std::numeric_limits<float>::quiet_NaN();
    const MeshReport r = checkMesh(nan);
    CHECK(r.nonFiniteVertices == 1);
    CHECK(contains(refractiveError(r), "1 vertex is not finite (NaN or infinite)"));
}

TEST_CASE("degenerate triangles are reported but do not stop a closed mesh", "[mesh_check]") {
    // Split the cube's triangle (2,3,0) at the midpoint m of its edge 3-0 and close the slit
    // against the unsplit neighbour (0,3,1) with the zero-area triangle (3,0,m): still closed.
    TriangleMesh cube = unitCube();
    REQUIRE(cube.triangles[0] == glm::uvec3(0, 2, 3));
    REQUIRE(cube.triangles[1] == glm::uvec3(0, 3, 1));
    const unsigned m = unsigned(cube.positions.size());
    cube.positions.push_back(0.5f * (cube.positions[3] + cube.positions[0]));
    cube.triangles[0] = {2, 3, m};
    cube.triangles.push_back({2, m, 0});
    cube.triangles.push_back({3, 0, m});
    const MeshReport r = checkMesh(cube);
    CHECK(r.watertight());
    CHECK(r.degenerateTriangles == 1);
    CHECK(r.signedVolume == Approx(1.0));
    CHECK(eikon::meshProblems(r) ==
          std::vector<std::string>{"1 degenerate triangle (zero area or a repeated vertex)"});
    CHECK_NOTHROW(requireClosedRefractiveMesh(r, "cube"));

    cube.triangles.push_back({4, 4, 5});  // a repeated index is degenerate too (and leaves an edge)
    CHECK(checkMesh(cube).degenerateTriangles == 2);
}

TEST_CASE("inward winding and absurd scale are refused", "[mesh_check]") {
    TriangleMesh inside = unitCube();
    for (glm::uvec3& t : inside.triangles) std::swap(t.y, t.z);
    CHECK(contains(refractiveError(checkMesh(inside)), "wound inward: signed volume -1"));

    TriangleMesh tiny = unitCube();
    for (glm::vec3& p : tiny.positions) p *= 1e-7f;
    CHECK(contains(refractiveError(checkMesh(tiny)),
                   "absurd scale: bounding-box diagonal 1.732e-07"));
    TriangleMesh huge = unitCube();
    for (glm::vec3& p : huge.positions) p *= 1e7f;
    CHECK(contains(refractiveError(checkMesh(huge)),
                   "absurd scale: bounding-box diagonal 1.732e+07"));
    TriangleMesh needle = unitCube();
    for (glm::vec3& p : needle.positions) p.x *= 1e-7f;
    CHECK(contains(refractiveError(checkMesh(needle)), "absurd scale: extents 1e-07 x 1 x 1"));
}
