#pragma once
// Runs the built `eikon` command line as users and scripts do, for the CLI tests: the test target
// must depend on the `eikon` target so that the binary is current.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace eikon::test {

struct RunResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

// Single-quotes `s` for /bin/sh.
inline std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void writeFile(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// Runs `eikon <args>` (arguments already quoted), stdout and stderr to files in `dir`.
inline RunResult runEikon(const std::string& args, const std::string& dir) {
    namespace fs = std::filesystem;
    const std::string binary = std::string(EIKON_BINARY_DIR) + "/apps/eikon";
    REQUIRE(fs::exists(binary));
    const std::string out = dir + "/stdout.txt";
    const std::string err = dir + "/stderr.txt";
    const std::string command =
        quoted(binary) + " " + args + " >" + quoted(out) + " 2>" + quoted(err) + " </dev/null";
    const int status = std::system(command.c_str());
    RunResult r;
    REQUIRE(status != -1);
    REQUIRE(WIFEXITED(status));
    r.exitCode = WEXITSTATUS(status);
    r.out = readFile(out);
    r.err = readFile(err);
    fs::remove(out);
    fs::remove(err);
    return r;
}

}  // namespace eikon::test
