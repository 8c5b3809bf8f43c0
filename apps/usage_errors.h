#pragma once
// Command-line mistakes (an unknown command or option, a missing input, a value CLI11 rejects)
// reported like every other eikon error: one line "eikon: <where>: <reason>", with "did you mean"
// where a known name is close, and one exit status of their own, so scripts can tell a wrong
// command line from a bad file.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace eikon::app {

// Exit statuses of `eikon` (README "Command line").
constexpr int kExitError = 1;     // bad input: a file, a scene, a value out of range (eikon::Error)
constexpr int kExitUsage = 2;     // the command line itself: unknown command or option, missing
                                  // argument, a value CLI11's checks reject
constexpr int kExitInternal = 3;  // a fault of eikon's own (an exception it did not expect)

// The known name closest to `given` when it is a likely typo (edit distance at most 2, or one is
// a prefix of the other: --frame for --frames); "" when none is.
std::string closestName(const std::string& given, const std::vector<std::string>& known);

// Prints the one line for `e` to stderr and returns kExitUsage; help and --version print their
// text to stdout and return 0. `argv` finds what the user typed (CLI11's messages do not name
// the command they were parsing).
int reportParseError(CLI::App& app, const CLI::ParseError& e, int argc, char** argv);

}  // namespace eikon::app
