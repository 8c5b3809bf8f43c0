// The inputs issue 14's fuzzing found, as users meet them: `eikon info` on a mesh and `eikon
// render` / `eikon simulate` on a scene, under `timeout 20`. Before the fixes these crashed (SEGV),
// ran past the timeout allocating gigabytes, or printed "internal error" naming nothing; each must
// now be one line "eikon: <where>: <reason>" on stderr, nothing on stdout, a non-zero exit.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "sim/mesh_test_files.h"
#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::checkOneLineError;
using eikon::test::quoted;
using eikon::test::runEikon;
using eikon::test::RunResult;
using eikon::test::scratchDir;
using eikon::test::writeText;

namespace {

const std::string kTriangle =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
    "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    return text.replace(text.find(from), from.size(), to);
}

// A scene with one glass sphere of `radius`, the extra top-level keys `extra` and the extra output
// keys `output`.
std::string scene(const std::string& radius, const std::string& extra,
                  const std::string& output = "") {
    return R"({"sources": [{"type": "box", "field": "density", "min": [-1, -1, -1],
                "max": [1, 1, 1], "value": 1, "voxel_size": 0.1}],
  "materials": [{"name": "fog", "field": "density", "absorption": [0.1, 0.1, 0.1]}],
  "meshes": [{"name": "glass", "shape": {"type": "icosphere", "radius": )" +
           radius + R"(, "subdivisions": 1}, "ior": 1.5}],
  "volume": {"bounds": {"min": [-1, -1, -1], "max": [1, 1, 1]}, "resolution": 16},
  "render": {"width": 16, "height": 16},
  "output": {"directory": "out", "png": true)" +
           output + "}" + extra + "}";
}

}  // namespace

TEST_CASE("eikon info on fuzzed mesh files: one line each, no crash, no hang", "[cli]") {
    const std::string dir = scratchDir("cli_hostile_meshes");
    const std::string binaryCube = eikon::test::plyBinaryBytes(eikon::test::unitCubeTriangles());
    const struct {
        const char* name;
        std::string text;
        const char* where;  // after the path
    } cases[] = {
        {"property_first.ply",
         "ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n0\n", ":3: "},
        {"no_version.ply", "ply\nformat ascii\n" + kTriangle, ":2: "},
        {"inf_version.ply", "ply\nformat ascii -inf\n" + kTriangle, ":2: "},
        {"glued_end.ply",
         "ply\nformat ascii 1.0\n" + kTriangle.substr(0, kTriangle.find("end_header")) + "x" +
             kTriangle.substr(kTriangle.find("end_header")),
         ": "},
        {"float_indices.ply", replaced(binaryCube, "list uchar int", "list int float"), ":8: "},
        {"many_faces.ply",
         "ply\nformat ascii 1.0\n" + replaced(kTriangle, "face 1", "face 99999999"), ": "},
        {"huge.off", "OFF\n4000000000 4000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", ": "},
    };
    for (const auto& c : cases) {
        INFO(c.name);
        writeText(dir + "/" + c.name, c.text);
        const RunResult r = runEikon("info " + quoted(dir + "/" + c.name), dir, "timeout 20");
        checkOneLineError(r, dir + "/" + c.name + c.where);
    }
}

TEST_CASE("eikon info on the issue's corrupt VDB: one line, no heap overflow", "[cli]") {
    // houdini_vel_constant.vdb with a leaf's compressed byte count garbled: OpenVDB read past
    // the leaf ("free(): invalid next size", SIGABRT) before core/vdb_grid_check.cpp.
    const std::string dir = scratchDir("cli_hostile_vdb");
    std::string bytes =
        eikon::test::readFile(eikon::test::sharedData("vdb/houdini_vel_constant.vdb"));
    REQUIRE(bytes.size() == 117684);
    bytes.replace(100353, 4, std::string("\xff\xff\0\0", 4));
    const std::string path = dir + "/bad.vdb";
    eikon::test::writeFile(path, bytes);
    const RunResult r = runEikon("info " + quoted(path), dir, "timeout 20");
    checkOneLineError(r, path + ": grid 'vel' could not be read; the file is truncated or corrupt");
}

TEST_CASE("eikon info on the fuzzing regressions: a report or one error line", "[cli]") {
    // Every input under tests/fuzz/regressions/ that crashed a reader, hung it or ran it out of
    // memory (RELIABILITY.md), VDB and mesh alike (the scene ones go through loadScene in
    // tests/core/test_scene_hostile_input.cpp). Some are now read (a point grid is listed, not
    // decoded); the others are one error line. Never a crash, a timeout or "internal error".
    const std::string dir = scratchDir("cli_fuzz_regressions");
    int inputs = 0;
    for (const char* format : {"vdb", "obj", "off", "ply", "stl", "nrrd"}) {
        const std::filesystem::path folder =
            eikon::test::sourcePath(std::string("tests/fuzz/regressions/") + format);
        if (!std::filesystem::is_directory(folder)) continue;
        for (const auto& entry : std::filesystem::directory_iterator(folder)) {
            const std::string path = entry.path().string();
            INFO(path);
            ++inputs;
            const RunResult r = runEikon("info " + quoted(path), dir, "timeout 20");
            if (r.exitCode == 0)
                CHECK(r.err.empty());
            else
                checkOneLineError(r, path);
        }
    }
    CHECK(inputs >= 8);
}

TEST_CASE("eikon render and simulate on fuzzed scenes: one line naming the pointer", "[cli]") {
    const std::string dir = scratchDir("cli_hostile_scenes");
    const struct {
        const char* name;
        std::string text;
        const char* command;
        const char* where;  // after the path
    } cases[] = {
        {"nul_name.json", scene("0.5", "", R"(, "name": "a\u0000b")"), "render", ":/output/name: "},
        {"overflow.json", scene("1e400", ""), "render", ":/meshes/0/shape/radius: "},
        {"deep.json", std::string(100000, '[') + std::string(100000, ']'), "render", ": "},
        {"tiny_domain.json", scene("0.5", R"(, "simulation": {"domain": {"min": [0, 0, 0],
               "max": [1e-30, 1e-30, 1e-30]}, "resolution": 8})"),
         "simulate", ":/simulation/domain: "},
        {"huge_mesh.json", scene("1e30", ""), "render", ":/meshes/0 (mesh 'glass'): "},
        // Fault 5: 2,500 voxels across a sphere (35 GB in OpenVDB) ended in std::bad_alloc
        // thrown again in OpenVDB's Tree destructor, SIGABRT. Now refused before allocating, at
        // a limit set below (16G) so that a machine with more memory refuses it too.
        {"fine_sphere.json", R"({"sources": [{"type": "sphere", "field": "n", "radius": 0.25,
               "voxel_size": 0.0002}], "materials": [{"name": "glass", "field": "n", "ior": 1.5}]})",
         "render", ":/sources/0/voxel_size: "},
    };
    for (const auto& c : cases) {
        INFO(c.name);
        writeText(dir + "/" + c.name, c.text);
        const std::string backend = std::string(c.command) == "render" ? " --backend cpu" : "";
        const RunResult r =
            runEikon(std::string(c.command) + " " + quoted(dir + "/" + c.name) + backend, dir,
                     "EIKON_MEMORY_LIMIT=16G timeout 60");
        // The huge mesh fails when voxelized, after `render` has said on stdout which backend
        // it runs ("CPU twin (TBB), as asked"); stderr must still be the one line.
        RunResult checked = r;
        if (std::string(c.name) == "huge_mesh.json") checked.out.clear();
        checkOneLineError(checked, dir + "/" + c.name + c.where);
    }
}
