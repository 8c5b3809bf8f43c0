// `eikon render`'s progress (issue 20): a line per frame on stderr with the count, elapsed and
// remaining time when several frames are rendered, plain when stderr is a file; a status line
// naming the stage on a terminal; --quiet prints nothing but errors and warnings.
#include <catch2/catch.hpp>

#include <cstdlib>
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
using eikon::test::sourcePath;

namespace {

std::string cubeArgs(const std::string& out) {
    return "render " + quoted(sourcePath("data/scenes/homogeneous_cube.json")) +
           " --frames 0-2 --size 16x12 --backend cpu -o " + quoted(out);
}

}  // namespace

TEST_CASE("several frames: a parseable line each on stderr with count and times",
          "[cli][progress]") {
    const std::string dir = scratchDir("cli_progress_lines");
    const RunResult r = runEikon(cubeArgs(dir + "/a/"), dir);
    INFO(r.out << r.err);
    REQUIRE(r.exitCode == 0);
    const std::vector<std::string> ls = lines(r.err);
    REQUIRE(ls.size() == 3);
    for (int i = 0; i < 3; ++i) {
        const std::string head =
            "frame " + std::to_string(i + 1) + "/3 (000" + std::to_string(i) + ") ";
        CHECK(ls[size_t(i)].rfind(head, 0) == 0);
        CHECK(contains(ls[size_t(i)], " s; elapsed "));
        CHECK(contains(ls[size_t(i)], " left"));
    }
    CHECK_FALSE(contains(r.err, "\r"));  // no terminal: no status line
    CHECK(contains(r.out, "wrote "));
}

TEST_CASE("render with --quiet prints nothing on success", "[cli][progress]") {
    const std::string dir = scratchDir("cli_progress_quiet");
    const RunResult r = runEikon(cubeArgs(dir + "/q/") + " --quiet", dir);
    REQUIRE(r.exitCode == 0);
    CHECK(r.out.empty());
    CHECK(r.err.empty());
    CHECK(readFile(dir + "/q/homogeneous_cube_0002.png").size() > 0);
}

TEST_CASE("on a terminal a status line names the stage, and is erased", "[cli][progress]") {
    // script(1) (util-linux, Essential in Debian) gives the command a terminal.
    const std::string dir = scratchDir("cli_progress_tty");
    const std::string binary = std::string(EIKON_BINARY_DIR) + "/apps/eikon";
    const std::string log = dir + "/tty.txt";
    const std::string command = "script -qec " +
                                quoted(quoted(binary) + " " + cubeArgs(dir + "/t/")) +
                                " /dev/null > " + quoted(log) + " 2>&1 </dev/null";
    REQUIRE(std::system(command.c_str()) == 0);
    const std::string text = readFile(log);
    INFO(text);
    CHECK(contains(text, "\r\033[Kframe 1/3 (0000): load"));
    CHECK(contains(text, "\r\033[Kframe 3/3 (0002): view"));
    CHECK(contains(text, "frame 3/3 (0002) "));
}
