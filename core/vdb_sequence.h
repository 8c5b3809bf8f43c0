#pragma once
// Frame sequences of VDB files: name_####.vdb, name.####.vdb and name####.vdb (or .nvdb, NanoVDB
// files, read by the same importer), with the frames
// missing between the first and the last listed. Whether rendering a missing frame, or one
// before the first or after the last, is an error (the default) or shows the nearest frame is
// the scene's choice (core/scene_sources.cpp).
#include <map>
#include <string>
#include <vector>

namespace eikon {

struct VdbSequence {
    std::string directory;
    std::string prefix;                 // "fluid_data_" (separator included)
    int digits = 0;                     // zero padding of the frame numbers seen
    std::string extension = ".vdb";     // or ".nvdb": one sequence is of one kind
    std::map<int, std::string> frames;  // frame -> path
    std::vector<int> missing;           // frames between the first and last that are absent

    int first() const { return frames.begin()->first; }
    int last() const { return frames.rbegin()->first; }
    // The pattern for messages: "dir/fluid_data_####.vdb".
    std::string pattern() const;
    // The missing frames as ranges, "3-9, 12".
    std::string missingText() const;
    // The frames present as ranges, "1-2, 10".
    std::string framesText() const;
    // The file for `frame`: itself, or the nearest earlier one when it is missing, or the first
    // frame when `frame` precedes the sequence.
    const std::string& fileForFrame(int frame) const;
};

// Frames as ranges, "3-9, 12" (ascending, each once).
std::string describeFrameRanges(const std::vector<int>& frames);

// `fileOrPattern` is one frame of the sequence ("cache/fluid_data_0001.vdb") or a pattern with
// ####, %04d or $F4 (core/frame_pattern.h) in place of the number. Throws eikon::Error when no
// frame is found.
VdbSequence findVdbSequence(const std::string& fileOrPattern);

}  // namespace eikon
