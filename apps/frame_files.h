#pragma once
// Frame ranges and per-frame file names, shared by the commands that write one file per frame
// (`eikon render`, `eikon simulate`).
#include <string>
#include <vector>

#include "core/frame_list.h"  // framePath
#include "core/scene.h"

namespace eikon::app {

// "--frames" text (core/frame_list.h) that must name one run of frames, FIRST-LAST or one frame
// (`eikon simulate` writes a cache without gaps), into time.frameStart/frameEnd. Throws
// eikon::Error.
void parseFrameRange(const std::string& text, TimeSettings& time);

// "--frames" text (core/frame_list.h): its frames, ascending, each once; time.frameStart and
// frameEnd become the first and the last. Throws eikon::Error.
std::vector<int> parseFrames(const std::string& text, TimeSettings& time);

// Removes the "<file>.partial" a killed run left beside frames first..last (core/atomic_write.h
// names them so; nothing else does), with a note for each; returns how many there were.
int removeStalePartials(const std::string& directory, const std::string& name, int first, int last,
                        const char* ext);
// The same for the files `paths`.
int removeStalePartials(const std::vector<std::string>& paths);

}  // namespace eikon::app
