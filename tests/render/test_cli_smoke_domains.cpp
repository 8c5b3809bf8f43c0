// A scene of two smoke domains through the command line: `eikon render` steps both live and
// `eikon simulate` writes one cache per domain, which two "vdb_sequence" sources load back under
// the domains' labelled fields (an alias key "density.left"), giving the same picture byte for
// byte. Each domain has its own material, so the picture holds both.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::quoted;
using eikon::test::readFile;
using eikon::test::runEikon;
using eikon::test::RunResult;
using eikon::test::scratchDir;
using eikon::test::writeFile;

namespace {

std::string twoDomainScene(const std::string& sources) {
    return R"({
  "volume": {"bounds": {"min": [0, 0, 0], "max": [2.5, 1, 1]}, "resolution": [40, 16, 16]},
  "sources": [)" +
           sources + R"(],
  "materials": [
    {"name": "white", "field": "density.left", "scattering": [6, 6, 6], "absorption": [1, 1, 1]},
    {"name": "red", "field": "density.right", "scattering": [8, 1, 1], "absorption": [0.5, 4, 4]}],
  "lights": [{"type": "directional", "direction": [-0.3, -1, -0.2]}],
  "camera": {"position": [1.25, 0.5, 4], "look_at": [1.25, 0.5, 0.5]},
  "render": {"width": 32, "height": 16},
  "output": {"name": "puff", "png": true},
  "time": {"fps": 12, "frame_start": 1, "frame_end": 3},
  "simulation": [
    {"label": "left", "domain": {"min": [0, 0, 0], "max": [1, 1, 1]}, "resolution": 8,
     "sources": [{"type": "sphere", "center": [0.5, 0.2, 0.5], "radius": 0.2, "density_rate": 3,
                  "temperature_rate": 10}]},
    {"label": "right", "domain": {"min": [1.5, 0, 0], "max": [2.5, 1, 1]}, "resolution": 8,
     "sources": [{"type": "box", "min": [1.8, 0.1, 0.3], "max": [2.2, 0.3, 0.7], "density_rate": 2,
                  "temperature_rate": 5}]}]
})";
}

}  // namespace

TEST_CASE("two smoke domains render live as from their two caches", "[cli][smoke]") {
    const std::string dir = scratchDir("cli_smoke_domains");
    const std::string live = dir + "/live.json", cached = dir + "/cached.json";
    writeFile(live, twoDomainScene(R"({"type": "simulation"})"));
    writeFile(cached, twoDomainScene(R"(
    {"type": "vdb_sequence", "file": ")" +
                                     dir + R"(/cache/puff_left_####.vdb",
     "aliases": {"density.left": ["density"], "temperature.left": ["temperature"]}},
    {"type": "vdb_sequence", "file": ")" +
                                     dir + R"(/cache/puff_right_####.vdb",
     "aliases": {"density.right": ["density"], "temperature.right": ["temperature"]}})"));

    const RunResult sim =
        runEikon("simulate " + quoted(live) + " -o " + quoted(dir + "/cache"), dir);
    INFO("stdout:\n" << sim.out << "stderr:\n" << sim.err);
    REQUIRE(sim.exitCode == 0);
    for (const char* label : {"left", "right"})
        for (int frame = 1; frame <= 3; ++frame) {
            const std::string file =
                dir + "/cache/puff_" + label + "_000" + std::to_string(frame) + ".vdb";
            CHECK(std::filesystem::exists(file));
        }
    CHECK(sim.out.find("frame 2 right: ") != std::string::npos);

    const RunResult stepped = runEikon("render " + quoted(live) + " -o " + quoted(dir + "/a"), dir);
    INFO("stdout:\n" << stepped.out << "stderr:\n" << stepped.err);
    REQUIRE(stepped.exitCode == 0);
    const RunResult fromCache =
        runEikon("render " + quoted(cached) + " -o " + quoted(dir + "/c") + " --frames 3", dir);
    INFO("stdout:\n" << fromCache.out << "stderr:\n" << fromCache.err);
    REQUIRE(fromCache.exitCode == 0);
    CHECK(readFile(dir + "/a/puff_0003.png") == readFile(dir + "/c/puff_0003.png"));
    CHECK(readFile(dir + "/a/puff_0001.png") != readFile(dir + "/a/puff_0003.png"));  // it rose

    // Without the right domain's optics the picture changes: both domains are in it.
    std::string leftOnly = twoDomainScene(R"({"type": "simulation"})");
    const std::string red = R"("scattering": [8, 1, 1], "absorption": [0.5, 4, 4])";
    leftOnly.replace(leftOnly.find(red), red.size(), R"("absorption": [0, 0, 0])");
    writeFile(dir + "/left_only.json", leftOnly);
    const RunResult oneLit = runEikon(
        "render " + quoted(dir + "/left_only.json") + " -o " + quoted(dir + "/d") + " --frames 3",
        dir);
    REQUIRE(oneLit.exitCode == 0);
    CHECK(readFile(dir + "/d/puff_0003.png") != readFile(dir + "/a/puff_0003.png"));
}
