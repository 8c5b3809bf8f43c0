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

}  // namespace eikon::app
