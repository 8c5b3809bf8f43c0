#pragma once
// Where `eikon render` writes its images, following the renderers users know (Blender's
// `-o //shot_####`, vdb_render's `vdb_render in.vdb out.png`):
//   -o still.png | still.exr        that one file; an error when more than one frame is rendered
//   -o shot_####.png (%04d, $F4)   one file per frame, its number in place of the #s
//   -o folder/, an existing folder,
//   or a name with no image extension (renders/v1.2)
//                                   <folder>/<name>.png for a single frame, <name>_####.png for
//                                   frames of an animation or a sequence
//   no -o                           the scene's output.directory, named as for a folder
// Other image extensions (.jpg, .tif, ...) are refused rather than taken for a folder. "A single
// frame" is one frame of an input that has one (a scene whose frame_start is its frame_end, one VDB
// file); a frame picked from an animation keeps its number, and a name that is already a pattern (a
// sequence's fluid_data_####) keeps its own.
#include <string>
#include <vector>

#include "core/scene.h"

namespace eikon::app {

struct OutputFiles {
    std::string directory;
    std::string nameTemplate;  // file name without its extension; a run of '#' takes the frame
    bool png = true;
    bool exr = false;

    // <directory>/<nameTemplate with the frame>.<ext>
    std::string path(int frame, const char* ext) const;
    // Every file `frames` write, PNG and EXR as enabled.
    std::vector<std::string> paths(const std::vector<int>& frames) const;
};

// `dashO` is -o as given ("" when absent); `output` the scene's settings (its png and exr flags
// hold --exr); `frames` those rendered; `inputHasOneFrame` as above. Throws eikon::Error at "-o"
// for an unusable value, before anything is written.
OutputFiles resolveOutputFiles(const std::string& dashO, const OutputSettings& output,
                               const std::vector<int>& frames, bool inputHasOneFrame);

}  // namespace eikon::app
