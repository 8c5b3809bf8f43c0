// The `eikon` command line as users and scripts see it: output on stdout, one-line errors
// "eikon: <where>: <reason>" on stderr with a non-zero exit, and no image written or replaced by
// a render that fails. Runs the built binary (the test target depends on it).
#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "render/image.h"
#include "support/arap_ball_scene.h"
#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::checkOneLineError;
using eikon::test::contains;
using eikon::test::lines;
using eikon::test::quoted;
using eikon::test::readFile;
using eikon::test::runEikon;
using eikon::test::RunResult;
using eikon::test::scratchDir;
using eikon::test::sharedData;
using eikon::test::sourcePath;
using eikon::test::writeFile;
namespace fs = std::filesystem;

namespace {

// Width and height from a PNG's IHDR chunk (big-endian, at bytes 16 and 20).
std::pair<int, int> pngSize(const std::string& path) {
    const std::string b = readFile(path);
    REQUIRE(b.size() > 24);
    REQUIRE(b.compare(1, 3, "PNG") == 0);
    auto be32 = [&](size_t at) {
        return int((unsigned char)b[at]) << 24 | int((unsigned char)b[at + 1]) << 16 |
               int((unsigned char)b[at + 2]) << 8 | int((unsigned char)b[at + 3]);
    };
    return {be32(16), be32(20)};
}

}  // namespace

TEST_CASE("eikon info prints the grids of a Houdini cache", "[cli]") {
    const std::string dir = scratchDir("cli_info");
    const std::string file = sharedData("vdb/houdini_smoke1.vdb");
    const RunResult r = runEikon("info " + quoted(file), dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    CHECK(r.exitCode == 0);
    CHECK(r.err.empty());
    CHECK(r.out.rfind(file + ": VDB ", 0) == 0);
    CHECK(contains(r.out, "1 grid\n"));
    CHECK(contains(r.out, "  density  float (stored as half), class fog volume\n"));
    CHECK(contains(r.out, "voxel size (0.476"));
    CHECK(contains(r.out, "index bounds (1, 2, 1) -> (111, 223, 112)\n"));
    CHECK(contains(r.out, "world bounds ("));
    CHECK(contains(r.out, "active voxels 1049275\n"));
}

TEST_CASE("eikon info on a bad file: one line naming the file, non-zero exit", "[cli]") {
    const std::string dir = scratchDir("cli_info_bad");

    SECTION("missing") {
        const std::string file = dir + "/absent.vdb";
        checkOneLineError(runEikon("info " + quoted(file), dir), file + ": ");
    }
    SECTION("truncated") {
        const std::string source = readFile(sharedData("vdb/houdini_smoke1.vdb"));
        REQUIRE(source.size() > 100000);
        const std::string file = dir + "/truncated.vdb";
        writeFile(file, source.substr(0, source.size() / 2));
        checkOneLineError(runEikon("info " + quoted(file), dir), file + ": ");
    }
    SECTION("a text file") {
        const std::string file = dir + "/notes.vdb";
        writeFile(file, "this is not a VDB file, just text\n");
        checkOneLineError(runEikon("info " + quoted(file), dir), file + ": ");
    }
}

TEST_CASE("eikon render of a scene with a misspelt key names the JSON path", "[cli]") {
    const std::string dir = scratchDir("cli_render_misspelt");
    const std::string scene = dir + "/misspelt.json";
    writeFile(scene, R"({
  "sources": [{"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1]}],
  "materials": [{"name": "smoke", "absorbtion": [1, 1, 1]}],
  "render": {"width": 16, "height": 12},
  "output": {"name": "misspelt", "png": true, "exr": true}
})");
    const std::string outDir = dir + "/out";
    const RunResult r = runEikon("render " + quoted(scene) + " -o " + quoted(outDir), dir);
    checkOneLineError(r, scene + ":/materials/0/absorbtion: ");
    CHECK(contains(r.err, "'absorption'"));  // the "did you mean" hint
    // No image anywhere: not in the output folder, not beside the scene.
    CHECK_FALSE(fs::exists(outDir + "/misspelt.png"));
    CHECK_FALSE(fs::exists(outDir + "/misspelt.exr"));
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        CHECK(entry.path().extension() != ".png");
}

TEST_CASE("eikon render writes the homogeneous cube as PNG and EXR", "[cli]") {
    const std::string dir = scratchDir("cli_render_cube");
    const std::string outDir = dir + "/out";
    const RunResult r =
        runEikon("render " + quoted(sourcePath("data/scenes/homogeneous_cube.json")) + " -o " +
                     quoted(outDir) + " --size 32x24",
                 dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    CHECK(r.exitCode == 0);
    const std::string png = outDir + "/homogeneous_cube.png";
    const std::string exr = outDir + "/homogeneous_cube.exr";
    REQUIRE(fs::exists(png));
    REQUIRE(fs::exists(exr));  // the scene asks for EXR too
    CHECK(pngSize(png) == std::make_pair(32, 24));
    CHECK(readFile(exr).compare(0, 4, "\x76\x2f\x31\x01") == 0);  // the OpenEXR magic number
    CHECK(contains(r.out, "wrote " + png));
    CHECK(contains(r.out, "wrote " + exr));
    // Only the two images: no temporary files left behind.
    int files = 0;
    for (const auto& entry : fs::directory_iterator(outDir)) {
        INFO(entry.path());
        ++files;
    }
    CHECK(files == 2);
}

TEST_CASE("a render that fails never replaces an existing image", "[cli]") {
    // The scene parses, the output folder exists, then loading the sources fails: the VDB file
    // it names is not there. Images from an earlier run stay as they were.
    const std::string dir = scratchDir("cli_render_fails");
    const std::string scene = dir + "/broken.json";
    writeFile(scene, R"({
  "sources": [{"type": "vdb", "file": "missing_cache.vdb"}],
  "materials": [{"name": "smoke", "absorption": [1, 1, 1]}],
  "camera": "auto",
  "render": {"width": 16, "height": 12},
  "output": {"name": "broken", "png": true, "exr": true}
})");
    const std::string outDir = dir + "/out";
    fs::create_directories(outDir);
    const std::string png = outDir + "/broken.png";
    const std::string exr = outDir + "/broken.exr";
    writeFile(png, "an earlier image, not to be overwritten");
    writeFile(exr, "an earlier EXR, not to be overwritten");

    const RunResult r = runEikon("render " + quoted(scene) + " -o " + quoted(outDir), dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    CHECK(r.exitCode != 0);
    CHECK_FALSE(contains(r.out, "wrote"));
    // The error is the last line on stderr (a GL driver may print before it) and names the file.
    const std::vector<std::string> errLines = lines(r.err);
    REQUIRE_FALSE(errLines.empty());
    CHECK(errLines.back().rfind("eikon: ", 0) == 0);
    CHECK(contains(errLines.back(), "missing_cache.vdb: no such file"));
    CHECK(contains(errLines.back(), ":/sources/0)"));
    CHECK(readFile(png) == "an earlier image, not to be overwritten");
    CHECK(readFile(exr) == "an earlier EXR, not to be overwritten");
    CHECK_FALSE(fs::exists(png + ".partial"));
}

TEST_CASE("eikon render picks and names its backend", "[cli]") {
    const std::string dir = scratchDir("cli_backend");
    const std::string scene = quoted(sourcePath("data/scenes/fog_sphere_spot.json"));
    const RunResult gpu = runEikon(
        "render " + scene + " -o " + quoted(dir + "/gpu") + " --size 40x30 --backend gpu", dir);
    const RunResult cpu = runEikon(
        "render " + scene + " -o " + quoted(dir + "/cpu") + " --size 40x30 --backend cpu", dir);
    const RunResult automatic =
        runEikon("render " + scene + " -o " + quoted(dir + "/auto") + " --size 40x30", dir);
    INFO(gpu.out << cpu.out << automatic.out << gpu.err << cpu.err << automatic.err);
    REQUIRE(gpu.exitCode == 0);
    REQUIRE(cpu.exitCode == 0);
    REQUIRE(automatic.exitCode == 0);
    CHECK(gpu.out.rfind("GPU: ", 0) == 0);
    CHECK(cpu.out.rfind("CPU twin", 0) == 0);
    // auto takes the GPU unless OpenGL is a software rasterizer, and says which and why.
    const bool software = contains(gpu.out, "llvmpipe") || contains(gpu.out, "softpipe");
    CHECK(contains(automatic.out, software ? "software rasterizer" : "GPU: "));
    // (Pixel agreement of the two backends is tested in test_view_pass.cpp.)
    CHECK(pngSize(dir + "/gpu/fog_sphere_spot.png") == std::make_pair(40, 30));
    CHECK(pngSize(dir + "/cpu/fog_sphere_spot.png") == std::make_pair(40, 30));
}

TEST_CASE("eikon render plays a scene's keyframes on the scene's clock", "[cli][animation]") {
    const std::string dir = scratchDir("cli_render_animation");
    const std::string scene = dir + "/moving.json";
    // An emitting ball that steps from left to right at 1 s; 1 frame per second.
    writeFile(scene, R"({
  "volume": {"bounds": {"min": [-1, -1, -1], "max": [1, 1, 1]}, "resolution": 16},
  "meshes": [{"name": "ball", "shape": {"type": "icosphere", "radius": 0.3, "subdivisions": 2},
              "emission": [2, 1, 0.5], "absorption": [1, 1, 1]}],
  "animation": [{"target": "/meshes/0/translate", "interpolation": "step", "times": [0, 1],
                 "values": [[-0.5, 0, 0], [0.5, 0, 0]]}],
  "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
  "render": {"width": 24, "height": 16},
  "output": {"name": "moving", "png": true},
  "time": {"fps": 1, "frame_start": 0, "frame_end": 1}
})");
    const RunResult r = runEikon("render " + quoted(scene) + " -o " + quoted(dir + "/a"), dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    REQUIRE(r.exitCode == 0);
    const std::string first = readFile(dir + "/a/moving_0000.png");
    const std::string second = readFile(dir + "/a/moving_0001.png");
    CHECK(!first.empty());
    CHECK(first != second);  // the ball moved
    // Frame 1 alone, in a fresh process, is the same frame: state depends on the time only.
    const RunResult again =
        runEikon("render " + quoted(scene) + " -o " + quoted(dir + "/b") + " --frames 1-1", dir);
    REQUIRE(again.exitCode == 0);
    CHECK(readFile(dir + "/b/moving_0001.png") == second);
    // --frames lists (core/frame_list.h): a comma list renders those frames, a step skips.
    const RunResult listed =
        runEikon("render " + quoted(scene) + " -o " + quoted(dir + "/c") + " --frames 1,0", dir);
    REQUIRE(listed.exitCode == 0);
    CHECK(readFile(dir + "/c/moving_0000.png") == first);
    CHECK(readFile(dir + "/c/moving_0001.png") == second);
    const RunResult stepped =
        runEikon("render " + quoted(scene) + " -o " + quoted(dir + "/d") + " --frames 0-1x2", dir);
    REQUIRE(stepped.exitCode == 0);
    CHECK(readFile(dir + "/d/moving_0000.png") == first);
    CHECK_FALSE(fs::exists(dir + "/d/moving_0001.png"));
    // A malformed list is one line showing the grammar, and nothing is written.
    const RunResult bad =
        runEikon("render " + quoted(scene) + " -o " + quoted(dir + "/e") + " --frames 1:3", dir);
    CHECK(bad.exitCode != 0);
    CHECK(bad.err ==
          "eikon: --frames: expected frames as 7, 1-10, 1-10x2 (every 2nd) or a comma list of "
          "those (1,3,5-7), got '1:3'\n");
    CHECK_FALSE(fs::exists(dir + "/e/moving_0001.png"));
}

TEST_CASE("eikon render steps a scene's water surface frame by frame", "[cli][water]") {
    const std::string dir = scratchDir("cli_render_water");
    const std::string scene = dir + "/pool.json";
    writeFile(scene, R"({
  "volume": {"bounds": {"min": [-1.1, -0.1, -1.1], "max": [1.1, 0.5, 1.1]}, "resolution": [20, 8, 20]},
  "meshes": [{"name": "water", "shape": {"type": "water", "size": [2, 2], "cells": [24, 24],
              "depth": 0.3, "droplets": [{"time": 0, "position": [0, 0], "radius": 0.2, "depth": 0.1}]},
              "ior": 1.33, "absorption": [0.5, 0.2, 0.1]}],
  "lights": [{"type": "directional", "direction": [0, -1, 0]}],
  "camera": {"position": [0, 2, 2], "look_at": [0, 0, 0]},
  "environment": {"type": "gradient", "zenith": [0.2, 0.3, 0.6], "horizon": [0.9, 0.9, 0.8],
                  "ground": [0.5, 0.3, 0.1]},
  "render": {"width": 24, "height": 16, "light_transport": {"method": "light_volumes"}},
  "output": {"name": "pool", "png": true},
  "time": {"fps": 24, "frame_start": 0, "frame_end": 2}
})");
    const RunResult r = runEikon("render " + quoted(scene) + " -o " + quoted(dir + "/a"), dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(readFile(dir + "/a/pool_0000.png") != readFile(dir + "/a/pool_0002.png"));
    const RunResult alone =
        runEikon("render " + quoted(scene) + " -o " + quoted(dir + "/b") + " --frames 2-2", dir);
    REQUIRE(alone.exitCode == 0);
    CHECK(readFile(dir + "/b/pool_0002.png") == readFile(dir + "/a/pool_0002.png"));
}

TEST_CASE("eikon render steps a jelly mesh on the scene's clock", "[cli][jelly]") {
    const std::string dir = scratchDir("cli_render_jelly");
    const std::string scene = dir + "/jelly.json";
    writeFile(scene, R"({
  "volume": {"bounds": {"min": [-1, -1, -1], "max": [1, 1, 1]}, "resolution": 16},
  "meshes": [{"name": "blob", "shape": {"type": "icosphere", "radius": 0.4, "subdivisions": 2},
              "translate": [0, 0.2, 0], "emission": [1, 0.6, 0.3], "absorption": [2, 2, 2],
              "deformer": {"type": "jelly", "floor": -0.8, "damping": 1}}],
  "camera": {"position": [0, 0, 3], "look_at": [0, 0, 0]},
  "render": {"width": 24, "height": 16},
  "output": {"name": "blob", "png": true},
  "time": {"fps": 12, "frame_start": 0, "frame_end": 3}
})");
    const RunResult r = runEikon("render " + quoted(scene) + " -o " + quoted(dir + "/a"), dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(readFile(dir + "/a/blob_0000.png") != readFile(dir + "/a/blob_0003.png"));  // it fell
    const RunResult alone =
        runEikon("render " + quoted(scene) + " -o " + quoted(dir + "/b") + " --frames 3-3", dir);
    REQUIRE(alone.exitCode == 0);
    CHECK(readFile(dir + "/b/blob_0003.png") == readFile(dir + "/a/blob_0003.png"));
}

TEST_CASE("eikon render reads mesh files: closed ones render, open ones fail until closed",
          "[cli][meshes]") {
    const std::string dir = scratchDir("cli_render_mesh_file");
    // Shared data paths hold no quotes or backslashes, so they go into JSON as they are.
    auto sceneWith = [&](const std::string& mesh, const std::string& extra) {
        const std::string path = dir + "/scene.json";
        writeFile(path, R"({
  "meshes": [{"name": "bunny", "file": ")" +
                            sharedData("meshes/" + mesh) +
                            R"(", "ior": 1.5, "absorption": [1, 2, 3], "scale": 10)" + extra +
                            R"(}],
  "volume": {"resolution": 24},
  "environment": {"color": [0.5, 0.6, 0.8]},
  "render": {"width": 24, "height": 16},
  "output": {"name": "bunny", "png": true}
})");
        return quoted(path);
    };
    const RunResult closed =
        runEikon("render " + sceneWith("bunny_closed.obj", "") + " -o " + quoted(dir + "/a"), dir);
    INFO("stdout:\n" << closed.out << "stderr:\n" << closed.err);
    CHECK(closed.exitCode == 0);
    CHECK(fs::exists(dir + "/a/bunny.png"));
    const RunResult open = runEikon(
        "render " + sceneWith("stanford-bunny.obj", "") + " -o " + quoted(dir + "/b"), dir);
    checkOneLineError(
        open, fs::path(sharedData("meshes/stanford-bunny.obj")).lexically_normal().string());
    CHECK(contains(open.err, "not watertight"));
    CHECK_FALSE(fs::exists(dir + "/b/bunny.png"));
    const RunResult filled =
        runEikon("render " + sceneWith("stanford-bunny.obj", R"(, "close_holes": 80)") + " -o " +
                     quoted(dir + "/c"),
                 dir);
    INFO("stdout:\n" << filled.out << "stderr:\n" << filled.err);
    CHECK(filled.exitCode == 0);
}

TEST_CASE("eikon render fills the shared wine glass with a liquid that rises with its fill",
          "[cli][meshes]") {
    const std::string dir = scratchDir("cli_render_liquid");
    auto sceneWith = [&](const std::string& container, const std::string& fill) {
        const std::string path = dir + "/wine_" + fill + ".json";
        writeFile(path, R"({
  "meshes": [)" + container +
                            R"(,
             {"name": "wine", "shape": {"type": "liquid", "container": "glass", "fill": )" +
                            fill + R"(}, "emission": [1, 0.3, 0.2], "absorption": [0.5, 0.5, 0.5]}],
  "volume": {"resolution": 32},
  "camera": {"position": [0, 0.4, 3], "look_at": [0, 0.4, 0]},
  "render": {"width": 24, "height": 32},
  "output": {"name": "wine", "png": false, "exr": true}
})");
        return quoted(path);
    };
    const std::string glass =
        R"({"name": "glass", "file": ")" + sharedData("meshes/wine_glass.obj") +
        R"(", "scale": 0.5, "translate": [0, -0.2, 0], "absorption": [0.2, 0.2, 0.2]})";
    // The liquid glows: its light in the image grows with how much of the bowl it fills.
    auto glow = [&](const std::string& fill) {
        const RunResult r = runEikon("render " + sceneWith(glass, fill) + " -o " +
                                         quoted(dir + "/" + fill) + " --backend cpu",
                                     dir);
        INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
        REQUIRE(r.exitCode == 0);
        double red = 0.0;
        for (const glm::vec4& p : eikon::readExr(dir + "/" + fill + "/wine.exr").pixels) red += p.r;
        return red;
    };
    const double low = glow("0.3"), high = glow("0.9");
    CHECK(low > 0.0);
    CHECK(high > 2.0 * low);

    // A container without a cavity: one line naming the liquid's place in the scene.
    const RunResult ball = runEikon(
        "render " +
            sceneWith(
                R"({"name": "glass", "shape": {"type": "icosphere", "radius": 0.5}, "ior": 1.5})",
                "0.5") +
            " -o " + quoted(dir + "/ball"),
        dir);
    checkOneLineError(ball, dir + "/wine_0.5.json:/meshes/1: ");
    CHECK(contains(ball.err, "no cavity"));
}

TEST_CASE("eikon render drags a mesh by keyframed ARAP handles", "[cli][arap]") {
    const std::string dir = scratchDir("cli_render_arap");
    const std::string scene = dir + "/squeeze.json";
    writeFile(scene, eikon::test::arapBallScene(24, 16, R"(,
  "time": {"fps": 12, "frame_start": 0, "frame_end": 3},
  "animation": [{"target": "/meshes/0/deformer/handles/1/translate",
                 "times": [0, 0.25], "values": [[0, 0, 0], [0.3, -0.3, 0]]}])"));
    const RunResult r = runEikon("render " + quoted(scene) + " -o " + quoted(dir + "/a"), dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(readFile(dir + "/a/ball_0000.png") != readFile(dir + "/a/ball_0003.png"));  // squeezed
    const RunResult alone =
        runEikon("render " + quoted(scene) + " -o " + quoted(dir + "/b") + " --frames 3-3", dir);
    REQUIRE(alone.exitCode == 0);
    CHECK(readFile(dir + "/b/ball_0003.png") == readFile(dir + "/a/ball_0003.png"));

    // A handle whose region misses the mesh: one line naming it.
    std::string text = readFile(scene);
    text.replace(text.find("[0, 0.5, 0], \"radius\": 0.2"), 26, "[0, 3, 0], \"radius\": 0.2");
    writeFile(scene, text);
    const RunResult miss = runEikon("render " + quoted(scene) + " -o " + quoted(dir + "/c"), dir);
    checkOneLineError(miss, scene + ":/meshes/0/deformer/handles/1: ");
    CHECK(contains(miss.err, "holds no vertex"));
}

TEST_CASE("a live simulation source renders the frame eikon simulate caches", "[cli][smoke]") {
    const std::string dir = scratchDir("cli_render_live_smoke");
    // One scene, two ways to get its smoke: stepped live by `eikon render`, or from the cache
    // `eikon simulate` wrote. Same fields, so the same image, byte for byte.
    auto sceneWith = [&](const std::string& source) {
        return R"({
  "volume": {"bounds": {"min": [0, 0, 0], "max": [1, 1, 1]}, "resolution": 16},
  "sources": [)" +
               source + R"(],
  "materials": [{"name": "smoke", "field": "density", "scattering": [6, 6, 6], "absorption": [1, 1, 1]}],
  "lights": [{"type": "directional", "direction": [-0.3, -1, -0.2]}],
  "camera": {"position": [0.5, 0.5, 3], "look_at": [0.5, 0.5, 0.5]},
  "render": {"width": 20, "height": 20},
  "output": {"name": "puff", "png": true},
  "time": {"fps": 12, "frame_start": 1, "frame_end": 4},
  "simulation": {"domain": {"min": [0, 0, 0], "max": [1, 1, 1]}, "resolution": 12,
    "sources": [{"type": "sphere", "center": [0.5, 0.2, 0.5], "radius": 0.15, "density_rate": 3,
                 "temperature_rate": 10}]}
})";
    };
    const std::string live = dir + "/live.json", cached = dir + "/cached.json";
    writeFile(live, sceneWith(R"({"type": "simulation"})"));
    writeFile(cached, sceneWith(R"({"type": "vdb_sequence", "file": ")" + dir +
                                R"(/cache/puff_####.vdb"})"));
    const RunResult sim =
        runEikon("simulate " + quoted(live) + " -o " + quoted(dir + "/cache"), dir);
    INFO("stdout:\n" << sim.out << "stderr:\n" << sim.err);
    REQUIRE(sim.exitCode == 0);
    const RunResult fromCache =
        runEikon("render " + quoted(cached) + " -o " + quoted(dir + "/c") + " --frames 3", dir);
    REQUIRE(fromCache.exitCode == 0);
    const RunResult stepped = runEikon("render " + quoted(live) + " -o " + quoted(dir + "/a"), dir);
    INFO("stdout:\n" << stepped.out << "stderr:\n" << stepped.err);
    REQUIRE(stepped.exitCode == 0);
    const RunResult alone =
        runEikon("render " + quoted(live) + " -o " + quoted(dir + "/b") + " --frames 3", dir);
    REQUIRE(alone.exitCode == 0);
    CHECK(readFile(dir + "/a/puff_0003.png") == readFile(dir + "/c/puff_0003.png"));
    CHECK(readFile(dir + "/b/puff_0003.png") == readFile(dir + "/a/puff_0003.png"));
    CHECK(readFile(dir + "/a/puff_0001.png") != readFile(dir + "/a/puff_0004.png"));  // it rose
}
