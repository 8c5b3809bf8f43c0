#pragma once
// What `eikon render` and `eikon view` take as input: a scene file, or a VDB cache rendered with
// the default scene (automatic camera and light), with command-line overrides applied.
#include <string>

#include "core/scene.h"

namespace eikon::app {

// `size` is "" or WIDTHxHEIGHT; `outputDir` is "" or a folder. Throws eikon::Error.
Scene sceneFromInput(const std::string& input, const std::string& outputDir,
                     const std::string& size);

}  // namespace eikon::app
