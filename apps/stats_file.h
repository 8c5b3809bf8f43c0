#pragma once
// `--stats-json FILE` of eikon render and eikon simulate: each frame's counters (photons traced,
// their steps, CG iterations, ...) as JSON, for scripts and for the stats checks of
// `eikon regress`. Only counts that do not depend on timing go in, so two runs of one build write
// the same file; times stay on --stats. Rewritten atomically after every frame:
//     {"frames": [{"frame": 1, "substeps": 2, "cg_iterations": 41, ...}, ...]}
#include <map>
#include <string>
#include <vector>

namespace eikon::app {

using FrameCounters = std::map<std::string, double>;

class StatsFile {
public:
    explicit StatsFile(std::string path) : path_(std::move(path)) {}
    // Adds (or, for a frame already there, merges into) one frame's counters and saves.
    void record(int frame, const FrameCounters& counters);

private:
    std::string path_;
    std::vector<std::pair<int, FrameCounters>> frames_;
};

// Reads a file StatsFile wrote: frame → counters. Throws eikon::Error naming the file.
std::map<int, FrameCounters> readStatsFile(const std::string& path);

}  // namespace eikon::app
