#pragma once
// Frame ranges and per-frame file names, shared by the commands that write one file per frame
// (`eikon render`, `eikon simulate`).
#include <string>

#include "core/scene.h"

namespace eikon::app {

// "--frames" text: FIRST-LAST or one frame, into time.frameStart/frameEnd. Throws eikon::Error.
void parseFrames(const std::string& text, TimeSettings& time);

// <directory>/<name>_<frame, 4 digits>.<ext>
std::string framePath(const std::string& directory, const std::string& name, int frame,
                      const char* ext);

// Removes the "<file>.partial" a killed run left beside frames first..last (core/atomic_write.h
// names them so; nothing else does), with a note for each; returns how many there were.
int removeStalePartials(const std::string& directory, const std::string& name, int first, int last,
                        const char* ext);

}  // namespace eikon::app
