// Data loss in `eikon simulate`, as users met it: a full disk while re-simulating over a good cache
// renamed a truncated frame over a good one and exited 0. The disk is made full by a file-size
// limit (bash's `ulimit -f`, with SIGXFSZ ignored, so a write past it fails with EFBIG the way a
// full disk fails with ENOSPC): it needs no root and no tmpfs, so CI runs it. Afterwards every
// file at a frame's name is a complete frame, the run's frames before the failure are its own,
// no frame of the older run is left after them to mix with it, and the exit status and the one
// error line tell what happened. A kill -9 leaves each frame file whole too, old or new (the
// frames before the kill are the new run's, those after it the old run's, until the next run).
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "core/field_registry.h"
#include "core/vdb_import.h"
#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::quoted;
using eikon::test::readFile;
using eikon::test::runEikon;
using eikon::test::RunResult;
using eikon::test::scratchDir;
using eikon::test::writeFile;
namespace fs = std::filesystem;

namespace {

// A 16³ plume over six frames; `rate` sets how much smoke the source adds, so that two runs
// differ in every frame.
std::string plume(const std::string& rate) {
    return R"({
  "sources": [{"type": "vdb_sequence", "file": "cache/puff_####.vdb"}],
  "materials": [{"name": "smoke", "scattering": [1, 1, 1]}],
  "output": {"name": "puff"},
  "time": {"fps": 24, "frame_start": 1, "frame_end": 6},
  "simulation": {
    "domain": {"min": [0, 0, 0], "max": [1, 1, 1]},
    "resolution": 16,
    "walls": {"+y": "open"},
    "sources": [{"type": "sphere", "center": [0.5, 0.25, 0.5], "radius": 0.15,
                 "density_rate": )" +
           rate + R"(, "temperature_rate": 30}]
  }
})";
}

std::string frameFile(const std::string& dir, int frame) {
    return dir + "/puff_000" + std::to_string(frame) + ".vdb";
}

std::vector<std::string> filesIn(const std::string& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    return names;
}

// Runs eikon in `dir` with files limited to `kib` KiB, as a disk that fills there would.
RunResult runWithFileLimit(const std::string& args, const std::string& dir, std::uintmax_t kib) {
    const std::string launcher = "bash -c " + quoted("trap '' XFSZ; ulimit -f " +
                                                     std::to_string(kib) + "; exec \"$0\" \"$@\"");
    return runEikon(args, dir, launcher);
}

}  // namespace

TEST_CASE("a full disk while re-simulating leaves complete frames and says which",
          "[cli][simulate][data-loss]") {
    const std::string dir = scratchDir("cli_simulate_disk_full");
    const std::string oldScene = dir + "/old.json", newScene = dir + "/new.json";
    writeFile(oldScene, plume("2"));
    writeFile(newScene, plume("4"));
    const std::string cache = dir + "/cache", reference = dir + "/reference";
    fs::remove_all(cache);
    fs::remove_all(reference);

    // The good cache the user has, and what the new run writes when the disk has room.
    REQUIRE(runEikon("simulate " + quoted(oldScene) + " -o " + quoted(cache), dir).exitCode == 0);
    REQUIRE(runEikon("simulate " + quoted(newScene) + " -o " + quoted(reference), dir).exitCode ==
            0);
    std::vector<std::uintmax_t> sizes;
    for (int f = 1; f <= 6; ++f) sizes.push_back(fs::file_size(frameFile(reference, f)));
    // A limit, in whole KiB as ulimit takes it, between the sizes of frames fail − 1 and fail of
    // the new run, where they grow by enough for one to fit: frame `fail` is the first that
    // cannot be written whole. The sizes grow as the smoke spreads, not evenly (export prunes
    // values below 1e-6, so a frame grows where the smoke reaches new voxels).
    int fail = 0;
    std::uintmax_t limitKib = 0;
    for (int f = 3; f <= 6 && fail == 0; ++f) {
        const std::uintmax_t kib = (sizes[size_t(f - 2)] + sizes[size_t(f - 1)]) / 2 / 1024;
        if (kib * 1024 > sizes[size_t(f - 2)] && kib * 1024 < sizes[size_t(f - 1)]) {
            fail = f;
            limitKib = kib;
        }
    }
    INFO("the new run's frame sizes: " << sizes[0] << " " << sizes[1] << " " << sizes[2] << " "
                                       << sizes[3] << " " << sizes[4] << " " << sizes[5]);
    REQUIRE(fail >= 3);
    const int complete = fail - 1;

    const RunResult r =
        runWithFileLimit("simulate " + quoted(newScene) + " -o " + quoted(cache), dir, limitKib);
    INFO("exit " << r.exitCode << "\nstdout:\n" << r.out << "stderr:\n" << r.err);
    CHECK(r.exitCode != 0);
    const std::vector<std::string> errorLines = eikon::test::lines(r.err);
    REQUIRE(errorLines.size() == 1);
    CHECK(errorLines[0].rfind("eikon: " + frameFile(cache, fail) + ": ", 0) == 0);
    CHECK(errorLines[0].find("File too large") != std::string::npos);
    CHECK(errorLines[0].find("frames 1-" + std::to_string(complete) +
                             " of this run are complete") != std::string::npos);
    CHECK(errorLines[0].find("removed " + std::to_string(6 - complete) +
                             " later frame file(s) of an earlier run") != std::string::npos);

    // Frames 1..complete are the new run's, byte for byte; the old run's later ones are gone,
    // not mixed in; nothing partial is left.
    for (int f = 1; f <= complete; ++f)
        CHECK(readFile(frameFile(cache, f)) == readFile(frameFile(reference, f)));
    CHECK(filesIn(cache).size() == size_t(complete));
    for (int f = 1; f <= complete; ++f) {
        eikon::FieldRegistry fields;
        eikon::importVdb(frameFile(cache, f), fields);  // complete: it reads
        CHECK(fields.has("density"));
    }
}

TEST_CASE("a frame that cannot be written at all fails before anything is replaced",
          "[cli][simulate][data-loss]") {
    const std::string dir = scratchDir("cli_simulate_no_room");
    const std::string scene = dir + "/puff.json";
    writeFile(scene, plume("2"));
    const std::string cache = dir + "/cache";
    fs::remove_all(cache);
    REQUIRE(runEikon("simulate " + quoted(scene) + " -o " + quoted(cache), dir).exitCode == 0);
    const std::string frame1 = readFile(frameFile(cache, 1));
    // Room for no frame: the first write fails, and the old run's frames are removed rather than
    // left to look like this run's.
    const RunResult r =
        runWithFileLimit("simulate " + quoted(scene) + " -o " + quoted(cache), dir, 1);
    INFO("exit " << r.exitCode << "\nstderr:\n" << r.err);
    CHECK(r.exitCode != 0);
    CHECK(r.err.find("no frame of this run was written") != std::string::npos);
    CHECK(filesIn(cache).empty());
}

TEST_CASE("a stale partial frame left by a killed run is removed on the next run",
          "[cli][simulate][data-loss]") {
    const std::string dir = scratchDir("cli_simulate_stale_partial");
    const std::string scene = dir + "/puff.json";
    writeFile(scene, plume("2"));
    const std::string cache = dir + "/cache";
    fs::remove_all(cache);
    fs::create_directories(cache);
    writeFile(frameFile(cache, 2) + ".partial", "half a frame");
    writeFile(cache + "/notes.partial", "not ours: kept");
    const RunResult r = runEikon("simulate " + quoted(scene) + " -o " + quoted(cache), dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    REQUIRE(r.exitCode == 0);
    CHECK_FALSE(fs::exists(frameFile(cache, 2) + ".partial"));
    CHECK(fs::exists(cache + "/notes.partial"));
    CHECK(r.err.find("puff_0002.vdb.partial, left by an interrupted run") != std::string::npos);
}

TEST_CASE("a run killed at any point leaves every frame file complete",
          "[cli][simulate][data-loss]") {
    const std::string dir = scratchDir("cli_simulate_killed");
    const std::string oldScene = dir + "/old.json", newScene = dir + "/new.json";
    writeFile(oldScene, plume("2"));
    writeFile(newScene, plume("4"));
    const std::string reference = dir + "/reference", cache = dir + "/cache";
    fs::remove_all(reference);
    REQUIRE(runEikon("simulate " + quoted(newScene) + " -o " + quoted(reference), dir).exitCode ==
            0);
    // kill -9 after these delays (seconds): wherever it lands (before the first frame, inside a
    // write, between frames, after the end), each file at a frame's name is the old run's frame
    // or the new run's, whole, and the next run clears what the killed one left.
    for (const char* delay : {"0.05", "0.3", "0.45", "0.6", "0.9"}) {
        INFO("killed after " << delay << " s");
        fs::remove_all(cache);
        REQUIRE(runEikon("simulate " + quoted(oldScene) + " -o " + quoted(cache), dir).exitCode ==
                0);
        std::vector<std::string> old;
        for (int f = 1; f <= 6; ++f) old.push_back(readFile(frameFile(cache, f)));
        const RunResult killed = runEikon("simulate " + quoted(newScene) + " -o " + quoted(cache),
                                          dir, std::string("timeout -s KILL ") + delay);
        CHECK((killed.exitCode == 0 || killed.exitCode == 137));
        int newFrames = 0, oldFrames = 0;
        for (int f = 1; f <= 6; ++f) {
            const std::string path = frameFile(cache, f);
            REQUIRE(fs::exists(path));
            const std::string bytes = readFile(path);
            const bool isNew = bytes == readFile(frameFile(reference, f));
            CHECK((bytes == old[size_t(f - 1)] || isNew));
            (isNew ? newFrames : oldFrames) += 1;
        }
        // A cache mixing the two runs is marked (core/cache_run_marker.h), and rendering it is
        // one error line saying which frames are the killed run's, until the next run.
        const std::string render = "render " + quoted(newScene) +
                                   " --frames 2 --size 8x8 --backend cpu -o " +
                                   quoted(dir + "/out");
        const bool marked = fs::exists(cache + "/puff.simulating");
        if (newFrames > 0 && oldFrames > 0) CHECK(marked);
        if (marked) {
            const RunResult refused = runEikon(render, dir);
            INFO(readFile(cache + "/puff.simulating") << refused.err);
            CHECK(refused.exitCode == 1);
            CHECK(refused.err.rfind("eikon: " + cache +
                                        "/puff_####.vdb: an eikon simulate run "
                                        "into this cache (pid ",
                                    0) == 0);
            CHECK(refused.err.find("may be from an earlier run") != std::string::npos);
        }
        const RunResult again =
            runEikon("simulate " + quoted(newScene) + " -o " + quoted(cache), dir);
        INFO(again.err);
        REQUIRE(again.exitCode == 0);
        for (const std::string& name : filesIn(cache)) {
            CHECK(name.find(".partial") == std::string::npos);
            CHECK(name.find(".simulating") == std::string::npos);
        }
        for (int f = 1; f <= 6; ++f)
            CHECK(readFile(frameFile(cache, f)) == readFile(frameFile(reference, f)));
        CHECK(runEikon(render, dir).exitCode == 0);
    }
}
