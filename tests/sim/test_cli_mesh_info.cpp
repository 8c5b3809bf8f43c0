// `eikon info mesh.obj` as users run it: counts, bounds and every problem on stdout with exit 0
// (a mesh with problems is still a readable file), and one-line errors with a non-zero exit for
// files that cannot be read. Runs the built binary (this suite depends on it).
#include <catch2/catch.hpp>

#include <string>

#include "sim/mesh_test_files.h"
#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::contains;
using eikon::test::quoted;
using eikon::test::runEikon;
using eikon::test::RunResult;
using eikon::test::scratchDir;
using eikon::test::sharedData;

TEST_CASE("eikon info prints a mesh's counts, bounds and problems", "[cli]") {
    const std::string dir = scratchDir("cli_mesh_info");
    const std::string bunny = sharedData("meshes/stanford-bunny.obj");
    const RunResult r = runEikon("info " + quoted(bunny), dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    CHECK(r.exitCode == 0);
    CHECK(r.err.empty());
    CHECK(r.out.rfind(bunny + ": OBJ mesh, 35947 vertices (1113 unreferenced), 69451 faces "
                              "(69451 triangles)\n",
                      0) == 0);
    CHECK(contains(r.out,
                   "  bounds (-0.09469, 0.032987, -0.061874) -> (0.061009, 0.187321, "
                   "0.0588)"));
    CHECK(contains(r.out, "1 component, Euler characteristic -3\n"));
    CHECK(contains(r.out, "  watertight: no; holes of 80, 42, 40, 39, 22 edges\n"));
    CHECK(
        contains(r.out, "    not watertight: 223 boundary edges in 5 holes (largest 80 edges)\n"));
    CHECK(contains(r.out, "set close_holes to 80"));

    const std::string res4 = sharedData("meshes/bun_zipper_res4.ply");
    const RunResult coarse = runEikon("info " + quoted(res4), dir);
    CHECK(coarse.exitCode == 0);
    CHECK(contains(coarse.out, "    70 non-manifold edges"));
    CHECK(contains(coarse.out, "    4 non-manifold vertices"));
    CHECK(contains(coarse.out, "    40 duplicate faces"));
}

TEST_CASE("eikon info on a clean mesh says so, with the reader's notes", "[cli]") {
    const std::string dir = scratchDir("cli_mesh_info_clean");
    const RunResult r = runEikon("info " + quoted(sharedData("meshes/teapot_closed.obj")), dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    CHECK(r.exitCode == 0);
    CHECK(r.err.empty());
    CHECK(contains(r.out, "7850 vertices, 8028 faces (15704 triangles)\n"));
    CHECK(contains(r.out, "2 components"));
    CHECK(contains(r.out, "  watertight: yes\n"));
    CHECK(contains(r.out, "  problems: none\n"));
    CHECK(contains(r.out, "default.mtl' not found"));
}

TEST_CASE("eikon info on an unreadable mesh: one line naming the file, non-zero exit", "[cli]") {
    const std::string dir = scratchDir("cli_mesh_info_bad");
    eikon::test::writeText(dir + "/nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    eikon::test::writeText(dir + "/empty.stl", "");
    for (const std::string& file : {dir + "/absent.ply", dir + "/nan.obj", dir + "/empty.stl"}) {
        const RunResult r = runEikon("info " + quoted(file), dir);
        INFO(file);
        eikon::test::checkOneLineError(r, file);  // a line number may follow (nan.obj:2)
    }
}
