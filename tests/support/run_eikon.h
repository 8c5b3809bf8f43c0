#pragma once
// Runs the built `eikon` command line as users and scripts do, for the CLI tests: the test target
// must depend on the `eikon` target so that the binary is current.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "support/contains.h"

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

// Runs `eikon <args>` (arguments already quoted), stdout and stderr to files in `dir`;
// `launcher` (quoted) runs it, e.g. under xvfb-run for `eikon view`.
inline RunResult runEikon(const std::string& args, const std::string& dir,
                          const std::string& launcher = "") {
    namespace fs = std::filesystem;
    const std::string binary = std::string(EIKON_BINARY_DIR) + "/apps/eikon";
    REQUIRE(fs::exists(binary));
    const std::string out = dir + "/stdout.txt";
    const std::string err = dir + "/stderr.txt";
    const std::string command = launcher + " " + quoted(binary) + " " + args + " >" + quoted(out) +
                                " 2>" + quoted(err) + " </dev/null";
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

inline std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

// A failed command: non-zero exit, nothing on stdout, exactly one line on stderr that reads
// "eikon: <where>: <reason>", where `where` is "<where>: " (the location and its separator).
inline void checkOneLineError(const RunResult& r, const std::string& where) {
    INFO("exit " << r.exitCode << "\nstdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.exitCode != 0);
    CHECK(r.out.empty());
    const std::vector<std::string> ls = lines(r.err);
    REQUIRE(ls.size() == 1);
    CHECK(r.err.back() == '\n');
    const std::string prefix = "eikon: " + where;
    CHECK(ls[0].rfind(prefix, 0) == 0);
    CHECK(ls[0].size() > prefix.size());  // a reason follows the location
}

}  // namespace eikon::test
