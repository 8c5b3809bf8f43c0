#include "apps/frame_files.h"

#include <cstdio>
#include <filesystem>

#include "core/atomic_write.h"
#include "core/error.h"
#include "core/log.h"

namespace eikon::app {

void parseFrames(const std::string& text, TimeSettings& time) {
    int a = 0, b = 0;
    char dash = 0;
    if (std::sscanf(text.c_str(), "%d%c%d", &a, &dash, &b) == 3 && dash == '-' && a >= 0 &&
        b >= a) {
        time.frameStart = a;
        time.frameEnd = b;
    } else if (std::sscanf(text.c_str(), "%d", &a) == 1 && a >= 0 &&
               text.find('-') == std::string::npos) {
        time.frameStart = time.frameEnd = a;
    } else {
        throw Error("--frames",
                    "expected FIRST-LAST or one frame (e.g. 0-119), got '" + text + "'");
    }
}

std::string framePath(const std::string& directory, const std::string& name, int frame,
                      const char* ext) {
    char number[16];
    std::snprintf(number, sizeof(number), "_%04d.", frame);
    return (std::filesystem::path(directory) / (name + number + ext)).string();
}

int removeStalePartials(const std::string& directory, const std::string& name, int first, int last,
                        const char* ext) {
    int removed = 0;
    for (int frame = first; frame <= last; ++frame) {
        const std::string path = framePath(directory, name, frame, ext);
        if (!removeStalePartial(path)) continue;
        logInfo("removed " + path + ".partial, left by an interrupted run");
        ++removed;
    }
    return removed;
}

}  // namespace eikon::app
