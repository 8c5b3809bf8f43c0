// Closing holes by minimum-area triangulation: an open cube closes to volume 1, the scanned
// bunny's five holes close into a watertight mesh, and holes above the limit stay open and are
// reported.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "core/error.h"
#include "sim/hole_filling.h"
#include "sim/mesh_check.h"
#include "sim/mesh_io.h"
#include "sim/mesh_test_files.h"
#include "sim/refractive_mesh.h"
#include "support/test_paths.h"

using eikon::checkMesh;
using eikon::closeHoles;
using eikon::HoleFilling;
using eikon::MeshReport;
using eikon::TriangleMesh;
using eikon::test::sharedData;

namespace {

TriangleMesh openCube() {  // the unit cube without its z = 0 face
    TriangleMesh cube;
    const eikon::test::PolygonMesh quads = eikon::test::unitCubeQuads();
    cube.positions = quads.positions;
    for (std::size_t f = 1; f < quads.faces.size(); ++f) {
        const std::vector<int>& q = quads.faces[f];
        cube.triangles.emplace_back(q[0], q[1], q[2]);
        cube.triangles.emplace_back(q[0], q[2], q[3]);
    }
    return cube;
}

}  // namespace

TEST_CASE("closing holes fills an open cube's missing face to volume 1", "[hole_filling]") {
    TriangleMesh cube = openCube();
    REQUIRE(checkMesh(cube).holeSizes == std::vector<std::size_t>{4});

    TriangleMesh untouched = cube;
    const HoleFilling none = closeHoles(untouched, 3);
    CHECK(none.filled.empty());
    CHECK(none.tooLarge == std::vector<std::size_t>{4});
    CHECK(untouched.triangles.size() == cube.triangles.size());

    const HoleFilling filling = closeHoles(cube, 4);
    REQUIRE(filling.filled.size() == 1);
    CHECK(filling.filled[0].edges == 4);
    CHECK(filling.filled[0].triangles == 2);
    CHECK(filling.filled[0].area == Approx(1.0));
    CHECK(filling.leftOpen() == 0);
    const MeshReport r = checkMesh(cube);
    CHECK(r.watertight());
    CHECK(r.inconsistentEdges == 0);
    CHECK(r.vertices == 8);
    CHECK(std::abs(r.signedVolume - 1.0) < 1e-6);
    CHECK(eikon::meshProblems(r).empty());
}

TEST_CASE("closing a three-edge hole adds its one triangle", "[hole_filling]") {
    // A tetrahedron without its face (0, 2, 1).
    TriangleMesh tet;
    tet.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    tet.triangles = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    const HoleFilling filling = closeHoles(tet, 3);
    REQUIRE(filling.filled.size() == 1);
    REQUIRE(tet.triangles.size() == 4);
    const glm::uvec3 t = tet.triangles[3];  // (0, 2, 1) up to rotation
    CHECK(((t == glm::uvec3(0, 2, 1)) || (t == glm::uvec3(2, 1, 0)) || (t == glm::uvec3(1, 0, 2))));
    const MeshReport r = checkMesh(tet);
    CHECK(r.watertight());
    CHECK(r.signedVolume == Approx(1.0 / 6.0));
}

TEST_CASE("closing holes makes the scanned bunny watertight", "[hole_filling]") {
    eikon::LoadedMesh bunny = eikon::loadMesh(sharedData("meshes/stanford-bunny.obj"));
    const MeshReport before = checkMesh(bunny.mesh);
    REQUIRE(before.holeSizes.size() == 5);
    const std::size_t largest = before.holeSizes[0];
    CAPTURE(before.holeSizes);

    TriangleMesh allButLargest = bunny.mesh;
    const HoleFilling partial = closeHoles(allButLargest, largest - 1);
    CHECK(partial.filled.size() == 4);
    CHECK(partial.tooLarge == std::vector<std::size_t>{largest});

    const HoleFilling filling = closeHoles(bunny.mesh, largest);
    CHECK(filling.filled.size() == 5);
    CHECK(filling.leftOpen() == 0);
    const MeshReport r = checkMesh(bunny.mesh);
    CHECK(r.watertight());
    CHECK(r.inconsistentEdges == 0);
    CHECK(r.nonManifoldVertices == 0);
    CHECK(r.degenerateTriangles == before.degenerateTriangles);
    CHECK(r.duplicateTriangles == 0);
    CHECK(r.eulerCharacteristic == 2);  // genus 0, closed
    CHECK(r.signedVolume > 0.0);
    CHECK_NOTHROW(eikon::requireClosedRefractiveMesh(r, "bunny"));
}

TEST_CASE("a refractive mesh file is loaded, closed as asked and checked", "[hole_filling]") {
    const std::string path = sharedData("meshes/stanford-bunny.obj");
    std::string reason;
    try {
        eikon::loadRefractiveMesh(path, {});
    } catch (const eikon::Error& e) {
        CHECK(e.where() == path);
        reason = e.reason();
    }
    CAPTURE(reason);
    const std::string prefix = "not watertight: 223 boundary edges in 5 holes (largest ";
    REQUIRE(reason.rfind(prefix, 0) == 0);
    const std::size_t largest = std::stoul(reason.substr(prefix.size()));
    CHECK(reason == prefix + std::to_string(largest) + " edges); set close_holes to " +
                        std::to_string(largest) + " to fill holes of up to " +
                        std::to_string(largest) + " edges");

    const eikon::RefractiveMesh closed = eikon::loadRefractiveMesh(path, {largest});
    CHECK(closed.report.watertight());
    CHECK(closed.holes.filled.size() == 5);
    CHECK(closed.report.faces == 69451 + 223 - 2 * 5);  // n − 2 triangles per n-edge hole
    CHECK_THROWS_WITH(eikon::loadRefractiveMesh(sharedData("meshes/bun_zipper_res4.ply"), {100}),
                      Catch::Contains("70 non-manifold edges"));
}
