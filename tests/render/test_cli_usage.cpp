// Command-line mistakes (issue 20): one line "eikon: <where>: <reason>" with "did you mean" where
// a known name is close, exit status 2 (documented in --help and the README), help per command
// with examples, and --version. CLI11's own messages were two lines and exits 105-109.
#include <catch2/catch.hpp>

#include <string>

#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::checkOneLineError;
using eikon::test::contains;
using eikon::test::runEikon;
using eikon::test::RunResult;
using eikon::test::scratchDir;

namespace {

// A usage error: the one-line form at `where`, with `reason` in it, and exit status 2.
// `dir` is the test case's own folder: ctest runs cases in parallel, and runEikon keeps its output
// files there.
void checkUsage(const std::string& dir, const std::string& args, const std::string& where,
                const std::string& reason) {
    const RunResult r = runEikon(args, dir);
    INFO("eikon " << args);
    checkOneLineError(r, where);
    CHECK(r.exitCode == 2);  // apps/usage_errors.h kExitUsage
    CHECK(contains(r.err, reason));
}

}  // namespace

TEST_CASE("typos name the closest command or option", "[cli][usage]") {
    const std::string dir = scratchDir("cli_usage_typos");
    checkUsage(dir, "rendr scene.json", "rendr: ", "unknown command; did you mean 'render'?");
    checkUsage(dir, "bench smok", "smok: ", "did you mean 'smoke'?");
    checkUsage(dir, "render scene.json --sise 64x48",
               "render: ", "--sise: unknown option; did you mean --size?");
    checkUsage(dir, "render scene.json --frame 3", "render: ", "did you mean --frames?");
    checkUsage(dir, "render scene.json --size=64x48 --exrr", "render: ", "did you mean --exr?");
    checkUsage(dir, "render scene.json --zzzzzz",
               "render: ", "--zzzzzz: unknown option (eikon render");
    // Far from every name: no guess.
    checkUsage(dir, "render scene.json --colour 1", "render: ", "--colour: unknown option (eikon");
}

TEST_CASE("missing and rejected arguments are one line too", "[cli][usage]") {
    const std::string dir = scratchDir("cli_usage_missing");
    checkUsage(
        dir, "", "eikon: ",
        "a command is required: info, convert, render, diff, view, simulate, regress, bench");
    checkUsage(dir, "convert", "convert: ", "scan is required (eikon convert --help)");
    checkUsage(dir, "render", "render: ", "input is required (eikon render --help)");
    checkUsage(dir, "render scene.json --backend vulkan", "render: ", "--backend");
    checkUsage(dir, "render a.json b.json", "render: ", "'b.json': unexpected argument");
    checkUsage(dir, "bench", "bench: ", "a command is required: smoke,");
    checkUsage(dir, "render cache.vdb --up w", "render: ", "--up: w not in {x,y,z}");
}

TEST_CASE("help per command shows examples, and --version the version", "[cli][usage]") {
    const std::string dir = scratchDir("cli_usage_help");
    const RunResult help = runEikon("render --help", dir);
    CHECK(help.exitCode == 0);
    CHECK(contains(help.out, "--hold"));
    CHECK(contains(help.out, "Examples (from the repository root):"));
    CHECK(contains(help.out, "eikon render data/scenes/glass_sphere_fog.json -o out/"));
    const RunResult top = runEikon("--help", dir);
    CHECK(top.exitCode == 0);
    CHECK(contains(top.out, "2 a wrong command line"));
    const RunResult version = runEikon("--version", dir);
    CHECK(version.exitCode == 0);
    CHECK(version.out.rfind("eikon 0.", 0) == 0);
    CHECK(contains(version.out, "OpenVDB"));
}
