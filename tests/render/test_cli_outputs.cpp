// `eikon render`'s inputs and outputs as users of vdb_render, Blender and Houdini expect (issue
// 20): -o as a file, a pattern or a folder; single frames without a frame number; sequences from
// a pattern (####, %04d, $F4) or from one numbered file with --frames; frames a cache lacks as an
// error unless held; files told apart by content, not extension; NanoVDB files. Each bad input is
// one line and writes nothing.
#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <string>

#include <nanovdb/util/IO.h>
#include <nanovdb/util/OpenToNanoVDB.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/LevelSetUtil.h>

#include "render/image.h"
#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::checkOneLineError;
using eikon::test::contains;
using eikon::test::quoted;
using eikon::test::readFile;
using eikon::test::runEikon;
using eikon::test::RunResult;
using eikon::test::scratchDir;
using eikon::test::sharedData;
using eikon::test::writeFile;
namespace fs = std::filesystem;

namespace {

// The file names in `dir` (empty when it does not exist).
std::set<std::string> filesIn(const std::string& dir) {
    std::set<std::string> names;
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) return names;
    for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename());
    return names;
}

// A three-frame cache, smoke_0001..0003.vdb, made of links to Blender's frames 1, 2 and 10 (real
// Mantaflow files; links, so nothing is copied).
std::string makeSequence(const std::string& dir) {
    const std::string cache = dir + "/cache";
    fs::create_directories(cache);
    const char* blender[] = {"fluid_data_0001.vdb", "fluid_data_0002.vdb", "fluid_data_0010.vdb"};
    for (int i = 0; i < 3; ++i) {
        const std::string link = cache + "/smoke_000" + std::to_string(i + 1) + ".vdb";
        if (!fs::exists(link))
            fs::create_symlink(sharedData(std::string("vdb/blender_smoke_c42/") + blender[i]),
                               link);
    }
    return cache;
}

RunResult render(const std::string& args, const std::string& dir) {
    return runEikon("render " + args + " --size 16x12 --backend cpu", dir);
}

}  // namespace

TEST_CASE("render -o names a file, a pattern or a folder, as other renderers do", "[cli][output]") {
    const std::string dir = scratchDir("cli_outputs");
    const std::string cache = makeSequence(dir);
    const std::string one = quoted(cache + "/smoke_0002.vdb");
    SECTION("a file: that one file, its format from its extension") {
        RunResult r = render(one + " -o " + quoted(dir + "/still.png"), dir);
        INFO(r.out << r.err);
        REQUIRE(r.exitCode == 0);
        CHECK(fs::is_regular_file(dir + "/still.png"));  // a file, not a folder named still.png
        r = render(one + " -o " + quoted(dir + "/hdr/still.exr"), dir);
        REQUIRE(r.exitCode == 0);
        CHECK(filesIn(dir + "/hdr") == std::set<std::string>{"still.exr"});
        CHECK(readFile(dir + "/hdr/still.exr").compare(0, 4, "\x76\x2f\x31\x01") == 0);
        r = render(one + " -o " + quoted(dir + "/both/still.png") + " --exr", dir);
        REQUIRE(r.exitCode == 0);
        CHECK(filesIn(dir + "/both") == std::set<std::string>{"still.png", "still.exr"});
    }
    SECTION("a pattern: one file per frame, the number in place of ####, %04d or $F4") {
        int run = 0;
        for (const char* pattern : {"shot_####.png", "shot_%04d.png", "shot_$F4.png"}) {
            const std::string out = dir + "/shots_" + std::to_string(run++);
            const RunResult r = render(
                quoted(cache + "/smoke_####.vdb") + " -o " + quoted(out + "/" + pattern), dir);
            INFO(pattern << "\n" << r.out << r.err);
            REQUIRE(r.exitCode == 0);
            CHECK(filesIn(out) ==
                  std::set<std::string>{"shot_0001.png", "shot_0002.png", "shot_0003.png"});
        }
    }
    SECTION("a folder: a single frame has no number; a numbered file keeps its own") {
        RunResult r = render(one + " -o " + quoted(dir + "/f/"), dir);
        REQUIRE(r.exitCode == 0);
        CHECK(filesIn(dir + "/f") == std::set<std::string>{"smoke_0002.png"});
        writeFile(dir + "/plain.json", R"({"sources": [{"type": "box", "min": [-1, -1, -1],
            "max": [1, 1, 1]}], "materials": [{"name": "smoke", "absorption": [1, 1, 1]}],
            "output": {"name": "cube"}})");
        fs::create_directories(dir + "/existing");
        r = render(quoted(dir + "/plain.json") + " -o " + quoted(dir + "/existing"), dir);
        REQUIRE(r.exitCode == 0);
        CHECK(filesIn(dir + "/existing") == std::set<std::string>{"cube.png"});
        // A name that is no image's is a folder, dots and all.
        r = render(quoted(dir + "/plain.json") + " -o " + quoted(dir + "/v1.2"), dir);
        REQUIRE(r.exitCode == 0);
        CHECK(filesIn(dir + "/v1.2") == std::set<std::string>{"cube.png"});
        // A frame picked from an animation keeps its number.
        r = render(quoted(dir + "/plain.json") + " -o " + quoted(dir + "/g/") + " --frames 0,2",
                   dir);
        REQUIRE(r.exitCode == 0);
        CHECK(filesIn(dir + "/g") == std::set<std::string>{"cube_0000.png", "cube_0002.png"});
    }
    SECTION("bad values are one line and write nothing") {
        checkOneLineError(
            render(quoted(cache + "/smoke_####.vdb") + " -o " + quoted(dir + "/bad/one.png"), dir),
            "-o: ");
        const RunResult many =
            render(quoted(cache + "/smoke_####.vdb") + " -o " + quoted(dir + "/bad/one.png"), dir);
        CHECK(contains(many.err, "names one file, but 3 frames are rendered"));
        CHECK(contains(many.err, "one_####.png"));
        checkOneLineError(render(one + " -o " + quoted(dir + "/bad/still.jpg"), dir), "-o: ");
        checkOneLineError(render(one + " -o " + quoted(dir + "/bad/shot_####"), dir), "-o: ");
        checkOneLineError(render(one + " -o " + quoted(dir + "/bad/a_##_$F4.png"), dir), "-o: ");
        CHECK_FALSE(fs::exists(dir + "/bad"));
    }
}

TEST_CASE("a sequence from a pattern or from one numbered file with --frames", "[cli][output]") {
    const std::string dir = scratchDir("cli_sequence_input");
    const std::string cache = makeSequence(dir);
    SECTION("patterns of Blender, printf and Houdini render every frame, named as the cache") {
        int run = 0;
        for (const char* pattern : {"smoke_####.vdb", "smoke_%04d.vdb", "smoke_$F4.vdb"}) {
            const std::string out = dir + "/out_" + std::to_string(run++);
            const RunResult r = render(quoted(cache + "/" + pattern) + " -o " + quoted(out), dir);
            INFO(pattern << "\n" << r.out << r.err);
            REQUIRE(r.exitCode == 0);
            CHECK(filesIn(out) ==
                  std::set<std::string>{"smoke_0001.png", "smoke_0002.png", "smoke_0003.png"});
        }
    }
    SECTION("one numbered file with --frames: its sequence, said in one line") {
        const RunResult r = render(
            quoted(cache + "/smoke_0001.vdb") + " --frames 2-3 -o " + quoted(dir + "/s"), dir);
        INFO(r.out << r.err);
        REQUIRE(r.exitCode == 0);
        CHECK(filesIn(dir + "/s") == std::set<std::string>{"smoke_0002.png", "smoke_0003.png"});
        CHECK(contains(r.err, "smoke_0001.vdb is a frame of " + cache +
                                  "/smoke_####.vdb (frames 1-3): --frames renders frames of "
                                  "that sequence"));
        // Different frames make different pictures (not one file written three times).
        CHECK(readFile(dir + "/s/smoke_0002.png") != readFile(dir + "/s/smoke_0003.png"));
    }
    SECTION("a file that is no frame of a sequence cannot take --frames") {
        fs::create_directories(dir + "/lone");
        if (!fs::exists(dir + "/lone/smoke.vdb"))
            fs::create_symlink(sharedData("vdb/blender_smoke_c42/fluid_data_0001.vdb"),
                               dir + "/lone/smoke.vdb");
        const RunResult r = render(
            quoted(dir + "/lone/smoke.vdb") + " --frames 1-15 -o " + quoted(dir + "/lone/out"),
            dir);
        checkOneLineError(r, dir + "/lone/smoke.vdb: ");
        CHECK(contains(r.err, "not a frame of a sequence"));
        CHECK_FALSE(fs::exists(dir + "/lone/out"));
    }
}

TEST_CASE("frames a cache lacks are an error naming what it has, unless held", "[cli][output]") {
    const std::string dir = scratchDir("cli_frames_outside");
    const std::string cache = makeSequence(dir);
    const std::string input = quoted(cache + "/smoke_####.vdb");
    const RunResult r = render(input + " --frames 2-5 -o " + quoted(dir + "/a"), dir);
    checkOneLineError(r, cache + "/smoke_####.vdb: ");
    CHECK(contains(r.err, "has frames 1-3; 4-5 outside them"));
    CHECK(contains(r.err, "--hold"));
    CHECK_FALSE(fs::exists(dir + "/a"));  // nothing written, not even frames 2 and 3

    const RunResult held = render(input + " --frames 2-5 --hold -o " + quoted(dir + "/b"), dir);
    INFO(held.out << held.err);
    REQUIRE(held.exitCode == 0);
    CHECK(contains(held.err, "ends at frame 3; it stands in for the frames after"));
    CHECK(filesIn(dir + "/b") == std::set<std::string>{"smoke_0002.png", "smoke_0003.png",
                                                       "smoke_0004.png", "smoke_0005.png"});
    CHECK(readFile(dir + "/b/smoke_0005.png") == readFile(dir + "/b/smoke_0003.png"));
}

TEST_CASE("inputs are told apart by content, not by extension", "[cli][output][bad-input]") {
    const std::string dir = scratchDir("cli_sniff");
    const std::string upper = dir + "/smoke.VDB";
    if (!fs::exists(upper))
        fs::create_symlink(sharedData("vdb/blender_smoke_c42/fluid_data_0001.vdb"), upper);
    RunResult r = render(quoted(upper) + " -o " + quoted(dir + "/a"), dir);
    INFO(r.out << r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(filesIn(dir + "/a") == std::set<std::string>{"smoke.png"});
    // A scene saved with another extension is still a scene.
    writeFile(dir + "/scene.txt", R"(  {"sources": [{"type": "box", "min": [-1, -1, -1],
        "max": [1, 1, 1]}], "materials": [{"name": "smoke", "absorption": [1, 1, 1]}],
        "output": {"name": "boxed"}})");
    r = render(quoted(dir + "/scene.txt") + " -o " + quoted(dir + "/b"), dir);
    REQUIRE(r.exitCode == 0);
    CHECK(filesIn(dir + "/b") == std::set<std::string>{"boxed.png"});

    // --up is for a VDB input's automatic camera; a scene's camera is its own.
    r = render(quoted(dir + "/scene.txt") + " --up z", dir);
    checkOneLineError(r, "--up: ");
    CHECK(contains(r.err, "is a scene, whose camera is its own"));

    writeFile(dir + "/picture.vdb", std::string("\x89PNG\r\n\x1a\n", 8) + "rest");
    r = render(quoted(dir + "/picture.vdb"), dir);
    checkOneLineError(r, dir + "/picture.vdb: ");
    CHECK(contains(r.err,
                   "neither a scene (JSON), an OpenVDB nor a NanoVDB file: it starts with "
                   "\"\\x89PNG\\x0d\\x0a\\x1a\\x0a\""));
    writeFile(dir + "/empty.vdb", "");
    r = render(quoted(dir + "/empty.vdb"), dir);
    checkOneLineError(r, dir + "/empty.vdb: ");
    CHECK(contains(r.err, "empty (0 bytes)"));
    // eikon info too: it said "basic_ios::clear: iostream error" for an empty file.
    r = runEikon("info " + quoted(dir + "/empty.vdb"), dir);
    checkOneLineError(r, dir + "/empty.vdb: ");
    CHECK(contains(r.err, "empty (0 bytes)"));
    r = runEikon("info " + quoted(dir + "/scene.txt"), dir);
    checkOneLineError(r, dir + "/scene.txt: ");
    CHECK(contains(r.err, "a scene file (JSON)"));
    writeFile(dir + "/grid.nvdb", "NanoVDB0 and the rest");
    checkOneLineError(render(quoted(dir + "/grid.nvdb"), dir), dir + "/grid.nvdb: ");
    r = render(quoted(dir + "/absent.vdb"), dir);
    checkOneLineError(r, dir + "/absent.vdb: ");
    CHECK(contains(r.err, "no such file"));
}

TEST_CASE("a NanoVDB file renders and eikon info lists its grid", "[cli][nanovdb]") {
    const std::string dir = scratchDir("cli_nanovdb");
    openvdb::initialize();
    auto ball = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(0.4f, {0, 0, 0}, 0.05f);
    openvdb::tools::sdfToFogVolume(*ball);
    ball->setName("density");
    const std::string file = dir + "/ball.nvdb";
    nanovdb::io::writeGrid(file, nanovdb::openToNanoVDB(*ball));
    RunResult r = render(quoted(file) + " -o " + quoted(dir + "/out/"), dir);
    INFO(r.out << r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(filesIn(dir + "/out") == std::set<std::string>{"ball.png"});
    // The ball shows: the centre pixel is lit, the corner is not.
    r = runEikon(
        "render " + quoted(file) + " --size 16x12 --backend cpu -o " + quoted(dir + "/ball.exr"),
        dir);
    REQUIRE(r.exitCode == 0);
    const eikon::Image image = eikon::readExr(dir + "/ball.exr");
    CHECK(image.pixels[size_t(6 * 16 + 8)].r > 10.0f * image.pixels[0].r + 1e-3f);
    r = runEikon("info " + quoted(file), dir);
    REQUIRE(r.exitCode == 0);
    CHECK(contains(r.out, file + ": NanoVDB, 1 grid"));
    CHECK(contains(r.out, "  density  float, class fog volume"));
}
