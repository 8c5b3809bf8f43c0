// The mark `eikon simulate` leaves while it writes a cache (core/cache_run_marker.h): read back as
// written, alive only for the process that wrote it (not a zombie, not a later process given the
// same pid), and a cache whose run stopped midway is refused as a sequence while it holds frames
// the run did not finish.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/cache_run_marker.h"
#include "core/error.h"
#include "core/vdb_sequence.h"
#include "support/test_paths.h"

using namespace eikon;
using Catch::Matchers::Contains;
using eikon::test::scratchDir;
namespace fs = std::filesystem;

TEST_CASE("a cache run's mark reads back, and only its own live process is alive", "[cache]") {
    const std::string dir = scratchDir("cache_run_marker");
    const std::string path = cacheRunMarkerPath(dir, "puff");
    CHECK(path == dir + "/puff.simulating");
    const CacheRunMarker mine = thisRunMarker(1, 12, 7);
    writeCacheRunMarker(path, mine);
    const auto read = readCacheRunMarker(path);
    REQUIRE(read);
    CHECK(read->pid == long(getpid()));
    CHECK(read->started == mine.started);
    CHECK((read->firstFrame == 1 && read->lastFrame == 12 && read->finishedThrough == 7));
    CHECK(cacheRunIsAlive(*read));

    CacheRunMarker reused = *read;  // this pid, another start: a later process, not the run
    reused.started += 1;
    CHECK_FALSE(cacheRunIsAlive(reused));

    // A child that has exited and that nobody has reaped yet is a zombie: not running, though
    // its pid and start time still match.
    const pid_t child = fork();
    if (child == 0) _exit(0);
    REQUIRE(child > 0);
    CacheRunMarker zombie;
    zombie.pid = child;
    char state = 0;
    for (int tries = 0; tries < 400 && state != 'Z'; ++tries) {
        std::ifstream stat("/proc/" + std::to_string(child) + "/stat");
        std::string line;
        std::getline(stat, line);
        std::istringstream fields(line.substr(line.rfind(')') + 1));
        fields >> state;
        std::string skipped;
        for (int f = 4; f < 22; ++f) fields >> skipped;
        fields >> zombie.started;
        if (state != 'Z') usleep(5000);
    }
    REQUIRE(state == 'Z');
    CHECK_FALSE(cacheRunIsAlive(zombie));
    waitpid(child, nullptr, 0);
    CHECK_FALSE(cacheRunIsAlive(zombie));  // gone altogether

    std::ofstream(path) << "not a mark\n";
    CHECK_FALSE(readCacheRunMarker(path));
    removeCacheRunMarker(path);
    CHECK_FALSE(fs::exists(path));
}

TEST_CASE("a sequence a stopped run wrote into is refused until the mark goes", "[cache]") {
    const std::string dir = scratchDir("cache_run_stopped");
    for (int f = 1; f <= 6; ++f) std::ofstream(dir + "/puff_000" + std::to_string(f) + ".vdb");
    CacheRunMarker stopped;
    stopped.pid = 1;  // init: alive, but started long before this mark says
    stopped.started = 1;
    stopped.firstFrame = 1;
    stopped.lastFrame = 6;
    stopped.finishedThrough = 4;
    const std::string mark = cacheRunMarkerPath(dir, "puff");
    writeCacheRunMarker(mark, stopped);
    CHECK_THROWS_WITH(findVdbSequence(dir + "/puff_0001.vdb"),
                      Contains(dir + "/puff_####.vdb: an eikon simulate run into this cache") &&
                          Contains("frames 1-4 are complete, frames 5-6 may be from an earlier "
                                   "run; re-run eikon simulate, or delete " +
                                   mark));
    // Every frame the sequence holds was finished: nothing mixes.
    stopped.finishedThrough = 6;
    writeCacheRunMarker(mark, stopped);
    CHECK(findVdbSequence(dir + "/puff_0001.vdb").frames.size() == 6);
    removeCacheRunMarker(mark);
    stopped.finishedThrough = 2;
    CHECK(findVdbSequence(dir + "/puff_0001.vdb").frames.size() == 6);
}
