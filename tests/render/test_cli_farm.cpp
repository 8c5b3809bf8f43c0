// Rendering a frame range in pieces, as a farm does (issue 21): chunks of a render together are
// the one-process render, byte for byte, their manifests merged are its manifest; a live
// simulation's frames come from `eikon simulate`'s cache with --from-cache, the same pictures;
// --resume keeps the frames the manifest vouches for and renders again, with a warning naming
// it, each file that is missing, cut short, overwritten or from another render.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::contains;
using eikon::test::lines;
using eikon::test::quoted;
using eikon::test::readFile;
using eikon::test::runEikon;
using eikon::test::RunResult;
using eikon::test::scratchDir;
using eikon::test::writeFile;
namespace fs = std::filesystem;

namespace {

// Live smoke (a "simulation" source), 8 frames; the scene the Slurm test renders at 640²
// (tests/scripts/test_slurm_farm.sh), here at 24² (--size).
void writeScene(const std::string& dir) {
    fs::copy_file(eikon::test::sourcePath("tests/scripts/farm_smoke.json"), dir + "/smoke.json");
}

RunResult render(const std::string& dir, const std::string& args) {
    return runEikon("render " + quoted(dir + "/smoke.json") + " --backend cpu --size 24x24 " + args,
                    dir);
}

// The header of a manifest and its frame lines sorted by frame: what merging the tasks' gives.
std::string merged(const std::vector<std::string>& manifests) {
    std::string header;
    std::vector<std::pair<int, std::string>> frames;
    for (const std::string& path : manifests) {
        const std::vector<std::string> ls = lines(readFile(path));
        REQUIRE(ls.size() >= 6);
        header.clear();
        for (size_t i = 0; i < 6; ++i) header += ls[i] + "\n";
        for (size_t i = 6; i < ls.size(); ++i) frames.emplace_back(std::stoi(ls[i]), ls[i]);
    }
    std::stable_sort(frames.begin(), frames.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [frame, line] : frames) header += line + "\n";
    return header;
}

std::set<std::string> pngsIn(const std::string& dir) {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".png") names.insert(e.path().filename());
    return names;
}

}  // namespace

TEST_CASE("chunks rendered from the cache are the one-process live render, byte for byte",
          "[cli][farm]") {
    const std::string dir = scratchDir("cli_farm_chunks");
    writeScene(dir);
    RunResult r = render(dir, "-o " + quoted(dir + "/local/") + " --quiet --manifest " +
                                  quoted(dir + "/local/manifest.tsv"));
    INFO(r.out << r.err);
    REQUIRE(r.exitCode == 0);
    // --from-cache before the cache exists: one line saying to simulate first.
    r = render(dir, "--from-cache -o " + quoted(dir + "/early/"));
    CHECK(r.exitCode == 1);
    REQUIRE(lines(r.err).size() == 1);
    CHECK(contains(r.err, "run it on the scene first"));
    CHECK_FALSE(fs::exists(dir + "/early/smoke_0001.png"));

    r = runEikon("simulate " + quoted(dir + "/smoke.json") + " --quiet", dir);
    REQUIRE(r.exitCode == 0);
    std::vector<std::string> manifests;
    for (int k = 1; k <= 3; ++k) {
        const std::string manifest = dir + "/farm/manifest_" + std::to_string(k) + ".tsv";
        r = render(dir, "--from-cache --chunk " + std::to_string(k) + "/3 -o " +
                            quoted(dir + "/farm/") + " --manifest " + quoted(manifest));
        REQUIRE(r.exitCode == 0);
        CHECK(contains(r.err, "chunk " + std::to_string(k) + "/3: frames "));
        manifests.push_back(manifest);
    }
    CHECK(contains(readFile(manifests[1]), "\n3\tsmoke_0003.png\t"));  // chunk 2/3: frames 3-5
    CHECK_FALSE(contains(readFile(manifests[1]), "\n6\t"));
    const std::set<std::string> local = pngsIn(dir + "/local");
    REQUIRE(local.size() == 8);
    CHECK(pngsIn(dir + "/farm") == local);
    for (const std::string& name : local) {
        INFO(name);
        CHECK(readFile(dir + "/farm/" + name) == readFile(dir + "/local/" + name));
    }
    CHECK(merged(manifests) == readFile(dir + "/local/manifest.tsv"));

    // More chunks than frames: an empty chunk renders nothing and says so.
    r = render(dir, "--from-cache --frames 1-3 --chunk 1/5 -o " + quoted(dir + "/empty/"));
    REQUIRE(r.exitCode == 0);
    CHECK(contains(r.err, "chunk 1/5: no frames (5 chunks of 3 frames)"));
    CHECK(pngsIn(dir + "/empty").empty());
}

TEST_CASE("resuming keeps the frames the manifest vouches for and redoes the rest", "[cli][farm]") {
    const std::string dir = scratchDir("cli_farm_resume");
    writeScene(dir);
    const std::string out = dir + "/out/";
    const std::string manifest = quoted(dir + "/out/manifest.tsv");
    RunResult r = render(dir, "--frames 1-5 -o " + quoted(out) + " --quiet --manifest " + manifest);
    REQUIRE(r.exitCode == 0);
    std::map<int, std::string> good;
    for (int f = 1; f <= 5; ++f) good[f] = readFile(out + "smoke_000" + std::to_string(f) + ".png");
    // A task killed midway and worse: frame 2 cut short, 3 overwritten by another picture, 4 gone
    // with a partial file where it was being written; 1 and 5 as they were.
    fs::resize_file(out + "smoke_0002.png", 100);
    fs::copy_file(out + "smoke_0001.png", out + "smoke_0003.png",
                  fs::copy_options::overwrite_existing);
    fs::remove(out + "smoke_0004.png");
    writeFile(out + "smoke_0004.png.partial", "half a picture");
    r = render(dir, "--frames 1-5 -o " + quoted(out) + " --manifest " + manifest + " --resume");
    INFO(r.out << r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(contains(r.err, "kept frame 1 (--resume)"));
    CHECK(contains(r.err, "kept frame 5 (--resume)"));
    CHECK(contains(r.err, "smoke_0002.png: its bytes differ from those recorded"));
    CHECK(contains(r.err, "smoke_0003.png: its bytes differ from those recorded"));
    CHECK_FALSE(contains(r.err, "kept frame 4"));
    CHECK(contains(r.out, "wrote " + out + "smoke_0004.png"));
    CHECK_FALSE(contains(r.out, "smoke_0001.png"));  // kept, not rewritten
    CHECK_FALSE(fs::exists(out + "smoke_0004.png.partial"));
    for (int f = 1; f <= 5; ++f)
        CHECK(readFile(out + "smoke_000" + std::to_string(f) + ".png") == good[f]);

    // Another render's frames at these names (another view step): every one is redone, and said so.
    r = render(
        dir, "--frames 1-5 -o " + quoted(out) + " --step 0.5 --manifest " + manifest + " --resume");
    REQUIRE(r.exitCode == 0);
    CHECK(contains(r.err, "from another render (its settings line differs)"));
    CHECK(contains(r.err, "smoke_0005.png: not recorded as this render's"));
    CHECK_FALSE(contains(r.err, "kept frame"));

    // Misuse, one line each, nothing written.
    r = render(dir, "-o " + quoted(out) + " --resume");
    eikon::test::checkOneLineError(r, "--resume: ");
    r = render(dir, "-o " + quoted(out) + " --chunk 4/3");
    eikon::test::checkOneLineError(r, "--chunk: ");
    r = render(dir, "-o " + quoted(out) + " --chunk auto");
    eikon::test::checkOneLineError(r, "--chunk: ");
    CHECK(contains(r.err, "SLURM_ARRAY_TASK_ID"));
    writeFile(dir + "/notes.txt", "my notes\n");
    r = render(dir,
               "-o " + quoted(dir + "/elsewhere/") + " --manifest " + quoted(dir + "/notes.txt"));
    CHECK(r.exitCode == 1);
    CHECK(contains(r.err, "not an eikon render manifest"));
    CHECK(readFile(dir + "/notes.txt") == "my notes\n");
    writeFile(dir + "/still.json", R"({"sources": [{"type": "sphere", "radius": 0.3}],
        "materials": [{"name": "fog", "field": "density", "absorption": [1, 1, 1]}]})");
    r = runEikon(
        "render " + quoted(dir + "/still.json") + " --from-cache -o " + quoted(dir + "/x.png"),
        dir);
    eikon::test::checkOneLineError(r, "--from-cache: ");
}
