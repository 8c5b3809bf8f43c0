#include "apps/stats_file.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>

#include "core/atomic_write.h"
#include "core/error.h"
#include "core/json_reader.h"

namespace eikon::app {

void StatsFile::record(int frame, const FrameCounters& counters) {
    bool merged = false;
    for (auto& [f, c] : frames_)
        if (f == frame) {
            for (const auto& [key, value] : counters) c[key] = value;
            merged = true;
        }
    if (!merged) frames_.emplace_back(frame, counters);
    json::Json doc;
    doc["frames"] = json::Json::array();
    for (const auto& [f, c] : frames_) {
        json::Json entry;
        entry["frame"] = f;
        for (const auto& [key, value] : c) {
            // Counts as integers (no "41.0"), anything else as the number it is.
            if (std::nearbyint(value) == value && std::fabs(value) < 9e15)
                entry[key] = int64_t(value);
            else
                entry[key] = value;
        }
        doc["frames"].push_back(entry);
    }
    const std::string text = doc.dump(1) + "\n";
    writeAtomically(path_, [&](const std::string& partial) {
        std::ofstream out(partial, std::ios::binary);
        out << text;
        out.close();
        if (!out) throw Error(path_, "could not write the statistics");
    });
}

std::map<int, FrameCounters> readStatsFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path, "cannot open the statistics file");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const json::Json doc = json::parseDocument(text, path);
    const json::Value root(doc, path, "");
    json::Object top(root, "a statistics file");
    std::map<int, FrameCounters> out;
    for (const json::Value& frame :
         top.required("frames", "an array").elements("an array of frames")) {
        json::Object entry(frame, "a frame's counters");
        const int f = int(entry.required("frame", "an integer").integer(INT32_MIN, INT32_MAX));
        FrameCounters counters;
        for (const auto& item : frame.json().items())
            if (item.key() != "frame")
                counters[item.key()] = entry.required(item.key(), "a number").number();
        out[f] = counters;
    }
    top.finish();
    return out;
}

}  // namespace eikon::app
