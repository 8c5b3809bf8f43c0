#include "core/vdb_sequence.h"

#include <cctype>
#include <filesystem>
#include <optional>

#include "core/cache_run_marker.h"
#include "core/error.h"
#include "core/frame_pattern.h"
#include "core/log.h"

namespace fs = std::filesystem;

namespace eikon {
namespace {

// Splits "fluid_data_0007.vdb" into prefix "fluid_data_", number "0007" and extension ".vdb"
// (or ".nvdb", NanoVDB's); the number is the run of digits right before the extension. A "####"
// run is accepted in its place.
bool splitFrameName(const std::string& name, std::string& prefix, std::string& number,
                    std::string& ext) {
    auto endsWith = [&](const std::string& e) {
        return name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0;
    };
    if (endsWith(".nvdb"))
        ext = ".nvdb";
    else if (endsWith(".vdb"))
        ext = ".vdb";
    else
        return false;
    const std::string stem = name.substr(0, name.size() - ext.size());
    size_t start = stem.size();
    const bool hashes = !stem.empty() && stem.back() == '#';
    while (start > 0 && (hashes ? stem[start - 1] == '#'
                                : std::isdigit(static_cast<unsigned char>(stem[start - 1]))))
        --start;
    if (start == stem.size()) return false;
    prefix = stem.substr(0, start);
    number = stem.substr(start);
    return true;
}

}  // namespace

std::string describeFrameRanges(const std::vector<int>& frames) {
    std::string out;
    for (size_t i = 0; i < frames.size();) {
        size_t j = i;
        while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
        if (!out.empty()) out += ", ";
        out += std::to_string(frames[i]);
        if (j > i) out += "-" + std::to_string(frames[j]);
        i = j + 1;
    }
    return out;
}

std::string VdbSequence::missingText() const {
    return describeFrameRanges(missing);
}

std::string VdbSequence::framesText() const {
    std::vector<int> present;
    for (const auto& entry : frames) present.push_back(entry.first);
    return describeFrameRanges(present);
}

std::string VdbSequence::pattern() const {
    return (fs::path(directory) / (prefix + std::string(std::max(digits, 1), '#') + extension))
        .string();
}

const std::string& VdbSequence::fileForFrame(int frame) const {
    auto it = frames.upper_bound(frame);
    if (it == frames.begin()) return it->second;
    return std::prev(it)->second;
}

namespace {

// A cache that an `eikon simulate` run killed midway wrote into (core/cache_run_marker.h) mixes
// that run's frames with an earlier run's, each file complete: refused while the mark stands and
// the sequence holds frames the run did not finish. A run still going is fine (a cache watched
// while it is written).
void checkNoStoppedRun(const VdbSequence& seq) {
    std::string cacheName = seq.prefix;
    if (!cacheName.empty() && (cacheName.back() == '_' || cacheName.back() == '.'))
        cacheName.pop_back();
    const std::string markPath = cacheRunMarkerPath(seq.directory, cacheName);
    const std::optional<CacheRunMarker> mark = readCacheRunMarker(markPath);
    if (!mark || cacheRunIsAlive(*mark)) return;
    const auto after = seq.frames.upper_bound(mark->finishedThrough);
    if (after == seq.frames.end() || after->first > mark->lastFrame) return;
    throw Error(seq.pattern(), stoppedRunText(*mark) + "; re-run eikon simulate, or delete " +
                                   markPath + " to use the cache as it is");
}

}  // namespace

VdbSequence findVdbSequence(const std::string& fileOrPattern) {
    // printf's %04d and Houdini's $F4 become ####.
    const fs::path asGiven(fileOrPattern);
    const fs::path given =
        asGiven.parent_path() / toHashPattern(asGiven.filename().string(), fileOrPattern);
    VdbSequence seq;
    seq.directory = given.parent_path().empty() ? "." : given.parent_path().string();
    std::string number;
    if (!splitFrameName(given.filename().string(), seq.prefix, number, seq.extension))
        throw Error(fileOrPattern,
                    "not a frame of a sequence: expected name_####.vdb, name.####.vdb or "
                    "name####.vdb, or .nvdb (the frame number right before the extension; "
                    "####, %04d or $F4 for it in a pattern)");
    std::error_code ec;
    if (!fs::is_directory(seq.directory, ec))
        throw Error(fileOrPattern, "folder '" + seq.directory + "' does not exist");

    for (const auto& entry : fs::directory_iterator(seq.directory, ec)) {
        std::string prefix, digits, ext;
        if (!entry.is_regular_file() ||
            !splitFrameName(entry.path().filename().string(), prefix, digits, ext) ||
            prefix != seq.prefix || ext != seq.extension || digits.front() == '#')
            continue;
        // A frame number that does not fit an int is not a frame of ours.
        if (digits.size() > 9) continue;
        seq.frames[std::stoi(digits)] = entry.path().string();
        seq.digits = std::max(seq.digits, int(digits.size()));
    }
    if (seq.frames.empty())  // seq.pattern() needs a frame's digits: name the pattern as given
        throw Error(fileOrPattern,
                    "no frames of " + given.filename().string() + " found in " + seq.directory);
    for (int f = seq.first(); f <= seq.last(); ++f)
        if (!seq.frames.count(f)) seq.missing.push_back(f);
    checkNoStoppedRun(seq);
    return seq;
}

}  // namespace eikon
