#pragma once
// One case of an `eikon regress` suite: a JSON file in the suite's folder naming an input (a
// scene or a VDB cache), how to run it and what to compare against its references
// (docs/regress.md). Read strictly, with the scene reader's errors (unknown key, did you mean,
// JSON pointer).
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace eikon::app {

// Bounds on how far a new image may be from its reference; each one given is checked.
struct ImageTolerances {
    std::optional<double> rmse;          // at most
    std::optional<double> maxAbs;        // at most
    std::optional<double> meanRelative;  // at most
    std::optional<double> psnr;          // at least, dB
    std::optional<double> ssim;          // at least
};

// "hash" (the bytes, exactly) or metrics.
struct ImageCheck {
    bool hash = false;
    ImageTolerances tolerances;
};

struct CacheCheck {
    bool hash = false;
    double maxAbs = 0.0;             // per voxel, without "hash"
    std::vector<std::string> grids;  // empty: every grid of the reference
};

// |new − reference| ≤ absolute + relative·|reference|.
struct StatTolerance {
    double absolute = 0.0;
    double relative = 0.0;
};

struct RegressCase {
    std::string name;  // the file name without .json
    std::string file;  // the case file, for messages
    std::string description;
    std::string input;  // scene or VDB file, resolved against the case file's folder
    std::string frames;
    std::string size;
    std::vector<std::string> backends{"cpu"};
    int timeoutSeconds = 600;
    std::optional<ImageCheck> png;
    std::optional<ImageCheck> exr;
    std::optional<CacheCheck> cache;
    std::map<std::string, StatTolerance> renderStats;
    std::map<std::string, StatTolerance> simulationStats;
    std::optional<ImageTolerances> acrossBackends;  // each backend against the first

    bool renders() const {
        return png || exr || !renderStats.empty() || acrossBackends.has_value();
    }
    bool simulates() const { return cache.has_value() || !simulationStats.empty(); }
};

// Reads `path`; throws eikon::Error("<path>:<pointer>", reason) on any problem.
RegressCase loadRegressCase(const std::string& path);

// The cases of a suite folder (every *.json directly in it), sorted by name; `only` non-empty:
// those cases, each of which must exist. A case file that cannot be read is still listed, with
// its error, so that the other cases run.
struct SuiteEntry {
    std::string name;
    std::string path;
};
std::vector<SuiteEntry> listSuite(const std::string& suiteDir,
                                  const std::vector<std::string>& only);

}  // namespace eikon::app
