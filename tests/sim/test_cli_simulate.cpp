// `eikon simulate` as users run it: one VDB file per frame that core's importer reads back, a
// rerun that replaces the cache cleanly, and a blow-up that keeps the frames before it. Runs the
// built binary (tests/CMakeLists.txt makes this suite depend on it).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "core/field_registry.h"
#include "core/vdb_import.h"
#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::quoted;
using eikon::test::runEikon;
using eikon::test::RunResult;
using eikon::test::scratchDir;
using eikon::test::writeFile;
namespace fs = std::filesystem;

namespace {

// A 16³ plume; `extra` adds keys to the simulation section.
std::string tinyScene(const std::string& extra) {
    return R"({
  "sources": [{"type": "vdb_sequence", "file": "out/tiny_####.vdb"}],
  "materials": [{"name": "smoke", "scattering": [1, 1, 1]}],
  "output": {"name": "tiny"},
  "time": {"fps": 24, "frame_start": 1, "frame_end": 2},
  "simulation": {
    "domain": {"min": [0, 0, 0], "max": [1, 1, 1]},
    "resolution": 16,
    "walls": {"+y": "open"},
    "sources": [{"type": "sphere", "center": [0.5, 0.25, 0.5], "radius": 0.15,
                 "density_rate": 4, "temperature_rate": 30)" +
           extra + R"(}]
  }
})";
}

int fileCount(const std::string& dir) {
    int n = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        INFO(entry.path());
        ++n;
    }
    return n;
}

void checkFrameImports(const std::string& path) {
    INFO(path);
    REQUIRE(fs::exists(path));
    eikon::FieldRegistry registry;
    eikon::importVdb(path, registry);
    REQUIRE(registry.has("density"));
    CHECK(registry.get("density").isScalar());
    CHECK(registry.has("temperature"));
    REQUIRE(registry.has("velocity"));
    CHECK(registry.get("velocity").isStaggered());
}

// The active density voxels of a frame file, "i j k value" per line.
std::string densityVoxels(const std::string& path) {
    eikon::FieldRegistry registry;
    eikon::importVdb(path, registry);
    std::ostringstream text;
    text.precision(9);
    for (auto it = registry.floatGrid("density")->cbeginValueOn(); it; ++it) {
        const openvdb::Coord c = it.getCoord();
        text << c.x() << ' ' << c.y() << ' ' << c.z() << ' ' << *it << '\n';
    }
    return text.str();
}

// A whole file's bytes: caches of the same scene are byte-identical (core/vdb_file_id.h).
std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("eikon simulate writes one VDB per frame, and a rerun replaces them cleanly",
          "[cli][simulate]") {
    const std::string dir = scratchDir("cli_simulate");
    const std::string scene = dir + "/tiny.json";
    writeFile(scene, tinyScene(""));
    const std::string out = dir + "/out";
    const std::string args = "simulate " + quoted(scene) + " -o " + quoted(out);

    const RunResult first = runEikon(args, dir);
    INFO("stdout:\n" << first.out << "stderr:\n" << first.err);
    REQUIRE(first.exitCode == 0);
    const std::string f1 = out + "/tiny_0001.vdb";
    const std::string f2 = out + "/tiny_0002.vdb";
    CHECK(first.out.find("frame 1: ") != std::string::npos);
    CHECK(first.out.find("CG iterations") != std::string::npos);
    CHECK(first.out.find("-> " + f2) != std::string::npos);
    CHECK(first.out.find("(1/2, about ") != std::string::npos);  // how far, and what is left
    CHECK(first.out.find("(2/2, about 0 s left)") != std::string::npos);
    checkFrameImports(f1);
    checkFrameImports(f2);
    CHECK(fileCount(out) == 2);  // no partial files
    const std::string bytes1 = fileBytes(f1);
    const std::string bytes2 = fileBytes(f2);
    CHECK_FALSE(densityVoxels(f2).empty());

    // A second run over the same folder: the same frames, whole, nothing else, byte for byte (the
    // solver is deterministic and the files' identifiers are hashes of their contents).
    const RunResult second = runEikon(args, dir);
    INFO("second stdout:\n" << second.out << "stderr:\n" << second.err);
    REQUIRE(second.exitCode == 0);
    checkFrameImports(f1);
    checkFrameImports(f2);
    CHECK(fileCount(out) == 2);
    CHECK(fileBytes(f1) == bytes1);
    CHECK(fileBytes(f2) == bytes2);

    // --quiet: for scripts, nothing printed, the same files written.
    const std::string hushed = dir + "/quiet";
    const RunResult quiet =
        runEikon("simulate " + quoted(scene) + " -o " + quoted(hushed) + " --quiet", dir);
    REQUIRE(quiet.exitCode == 0);
    CHECK(quiet.out.empty());
    CHECK(quiet.err.empty());
    CHECK(fileBytes(hushed + "/tiny_0002.vdb") == bytes2);

    // --frames writes only the frames asked for, stepping through the ones before.
    const std::string only = dir + "/only2";
    const RunResult cut =
        runEikon("simulate " + quoted(scene) + " -o " + quoted(only) + " --frames 2", dir);
    REQUIRE(cut.exitCode == 0);
    CHECK(fileCount(only) == 1);
    CHECK(fileBytes(only + "/tiny_0002.vdb") == bytes2);
    // A cache has no gaps: a list with one is refused before anything is written.
    const std::string gap = dir + "/gap";
    const RunResult gapped =
        runEikon("simulate " + quoted(scene) + " -o " + quoted(gap) + " --frames 1,3", dir);
    CHECK(gapped.exitCode != 0);
    CHECK_THAT(gapped.err, Catch::Contains("eikon: --frames: expected one run of frames"));
    CHECK((!fs::exists(gap) || fileCount(gap) == 0));
}

TEST_CASE("a simulation that blows up writes no runaway frame and exits non-zero",
          "[cli][simulate]") {
    const std::string dir = scratchDir("cli_simulate_blowup");
    const std::string scene = dir + "/tiny.json";
    // The source drives the velocity to 1000 units/s in frame 1; frame 2 would need hundreds of
    // substeps, beyond the cap of 2: frame 1 already holds the runaway velocity, so it is the
    // blow-up, found before it is written (frames before a blow-up are kept: see the
    // data-loss tests).
    std::string text = tinyScene(R"(, "velocity": [0, 1000, 0], "velocity_rate": 1e6)");
    text.replace(text.find("\"resolution\""), 0, "\"max_substeps\": 2, ");
    writeFile(scene, text);
    const std::string out = dir + "/out";
    const RunResult r = runEikon("simulate " + quoted(scene) + " -o " + quoted(out), dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    CHECK(r.exitCode != 0);
    CHECK(r.err.rfind("eikon: smoke step", 0) == 0);
    CHECK(r.err.find("end of frame") != std::string::npos);
    CHECK(r.err.find("blew up") != std::string::npos);
    CHECK(r.err.find("no frame of this run was written") != std::string::npos);
    CHECK(fileCount(out) == 0);
}

TEST_CASE("a keyframed source: a frame cut out with --frames equals the same frame of a full run",
          "[cli][simulate][animation]") {
    const std::string dir = scratchDir("cli_simulate_keyframed");
    // The tiny plume's source swept along x through frames 1 and 2 (t = 1/24 .. 1/12 s), with a
    // CFL number so small that frame 2 takes several substeps, each with the source at its time.
    std::string text = tinyScene("");
    text.replace(text.find("\"resolution\""), 0, "\"cfl\": 0.01, ");
    const std::string track = R"(,
  "animation": [{"target": "/simulation/sources/0/center", "times": [0, 0.0833333],
                 "values": [[0.3, 0.25, 0.5], [0.7, 0.25, 0.5]]}]
})";
    text.replace(text.rfind("\n}"), 2, track);
    const std::string scene = dir + "/keyed.json";
    writeFile(scene, text);
    const std::string stillScene = dir + "/still.json";
    std::string stillText = tinyScene("");
    stillText.replace(stillText.find("\"resolution\""), 0, "\"cfl\": 0.01, ");
    writeFile(stillScene, stillText);

    const RunResult full =
        runEikon("simulate " + quoted(scene) + " -o " + quoted(dir + "/full"), dir);
    INFO("stdout:\n" << full.out << "stderr:\n" << full.err);
    REQUIRE(full.exitCode == 0);
    CHECK(full.out.find("frame 2: 1 substeps") == std::string::npos);
    CHECK(full.out.find("frame 2: ") != std::string::npos);
    const RunResult cut = runEikon(
        "simulate " + quoted(scene) + " -o " + quoted(dir + "/cut") + " --frames 2-2", dir);
    REQUIRE(cut.exitCode == 0);
    const RunResult still =
        runEikon("simulate " + quoted(stillScene) + " -o " + quoted(dir + "/still"), dir);
    REQUIRE(still.exitCode == 0);

    const std::string frame2 = fileBytes(dir + "/full/tiny_0002.vdb");
    REQUIRE_FALSE(frame2.empty());
    CHECK(fileBytes(dir + "/cut/tiny_0002.vdb") == frame2);
    CHECK(fileCount(dir + "/cut") == 1);
    // The track changed the smoke: the unanimated scene's frame 2 differs.
    CHECK(fileBytes(dir + "/still/tiny_0002.vdb") != frame2);
}
