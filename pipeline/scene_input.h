#pragma once
// What `eikon render`, `eikon view` and `eikon bench soak` take as input, told apart by content
// (core/file_kind.h), not by extension: a scene file; one VDB file; or a VDB sequence, named by a
// pattern (fluid_data_####.vdb, %04d, $F4) or, with --frames, by any one of its frames. The VDB
// inputs render with the default scene (automatic camera and light). Command-line overrides
// applied.
#include <string>
#include <vector>

#include "core/scene.h"

namespace eikon {

struct InputChoices {
    std::string size;          // "" or WIDTHxHEIGHT
    bool framesGiven = false;  // --frames: a numbered VDB file stands for its whole sequence
    bool hold = false;         // --hold: every sequence holds its nearest frame where it has none
    std::string up;            // --up x|y|z for a VDB input's automatic camera; "" lets it choose
    std::string grid;          // --grid NAME|INDEX: a VDB input's level set to render as a solid
};

struct SceneInput {
    Scene scene;
    // The input is one picture's worth: one VDB file, or a scene whose frame_start is its
    // frame_end (apps/output_files.h then writes no frame number).
    bool oneFrame = false;
    // What the command should say once its checks pass: which sequence a numbered file given
    // with --frames stands for, how a VDB input's camera chose its up axis.
    std::vector<std::string> notes;
};

// Throws eikon::Error for a missing or unreadable input, an unknown kind of file, a bad scene,
// --frames on a VDB file that is not a frame of a sequence, and --up or --grid with a scene
// (--grid also with a sequence: level-set sequences are not rendered without a scene).
SceneInput readSceneInput(const std::string& input, const InputChoices& choices);

}  // namespace eikon
