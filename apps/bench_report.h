#pragma once
// What every `eikon bench` report starts with, so that a table can be read (and rerun) without
// its context: the command line, the machine, its load and the build.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <tbb/global_control.h>

namespace eikon::app {

// argv joined with spaces (arguments with spaces or quotes single-quoted), as main() got it.
std::string joinCommandLine(int argc, char** argv);
// The command line main() was called with (set by main before parsing).
const std::string& benchCommandLine();
void setBenchCommandLine(std::string line);

// "# command: ...", "# machine: ...", "# load average: ...", "# build: ...", "# threads: ...".
void printBenchHeader(std::FILE* out, int threads);

// Caps TBB's threads for the lifetime of the returned object (threads ≤ 0: no cap).
std::unique_ptr<tbb::global_control> limitThreads(int threads);

// The median of the values (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> values);

// "a,b,,c" -> {"a", "b", "c"}: comma-separated names, empty items dropped.
std::vector<std::string> splitList(const std::string& text);

// "16,32" -> {16, 32}. Throws eikon::Error naming `option` on anything else.
std::vector<int> parseSizeList(const std::string& text, const char* option);

}  // namespace eikon::app
