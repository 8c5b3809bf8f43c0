#include "apps/frame_files.h"

#include <cstdio>
#include <filesystem>

#include "core/atomic_write.h"
#include "core/error.h"
#include "core/frame_list.h"
#include "core/log.h"

namespace eikon::app {

std::vector<int> parseFrames(const std::string& text, TimeSettings& time) {
    std::vector<int> frames = parseFrameList(text);
    time.frameStart = frames.front();
    time.frameEnd = frames.back();
    return frames;
}

void parseFrameRange(const std::string& text, TimeSettings& time) {
    TimeSettings parsed = time;
    if (!isContiguous(parseFrames(text, parsed)))
        throw Error("--frames",
                    "expected one run of frames, FIRST-LAST or one frame (a cache "
                    "has no gaps), got '" +
                        text + "'");
    time = parsed;
}

int removeStalePartials(const std::string& directory, const std::string& name, int first, int last,
                        const char* ext) {
    std::vector<std::string> paths;
    for (int frame = first; frame <= last; ++frame)
        paths.push_back(framePath(directory, name, frame, ext));
    return removeStalePartials(paths);
}

int removeStalePartials(const std::vector<std::string>& paths) {
    int removed = 0;
    for (const std::string& path : paths) {
        if (!removeStalePartial(path)) continue;
        logInfo("removed " + path + ".partial, left by an interrupted run");
        ++removed;
    }
    return removed;
}

}  // namespace eikon::app
