#pragma once
// Running one regression case: the eikon commands its comparisons need, as child processes of
// this same binary (apps/subprocess.h), into a work folder of its own, and the outputs they left
// there. Every output has a key, "CASE/<relative path>": "CASE/cpu/frame_0001.png",
// "CASE/cache/density_0003.vdb", "CASE/simulation_stats.json". Its reference has the same key.
#include <map>
#include <string>

#include "apps/regress_case.h"

namespace eikon::app {

struct CaseRun {
    bool ok = false;
    std::string reason;   // why not: the command's last error line, or how it ended
    std::string logPath;  // every command's output
    double seconds = 0.0;
    // key → path of the new file, for the kinds the case compares.
    std::map<std::string, std::string> outputs;
    // backend → (frame file name → linear EXR or PNG path), for comparisons across backends.
    std::map<std::string, std::map<std::string, std::string>> frames;
};

// Runs `c` with `eikon` (the binary) in `workDir` (emptied first).
CaseRun runCase(const RegressCase& c, const std::string& eikon, const std::string& workDir);

// The kind of an output key, as the case's "compare" names it: "png", "exr", "cache",
// "render_stats", "simulation_stats" (empty for anything else).
std::string outputKind(const std::string& key);

}  // namespace eikon::app
