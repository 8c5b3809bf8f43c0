#pragma once
// The viewer's relighting panel (Dear ImGui over the picture, render/ui_overlay.h; Tab shows and
// hides it): the picture's size and time, each stage's milliseconds, play, pause and reset of the
// frames, the light-transport method and its settings (as JSON), and the lights' and materials'
// values. A widget moved is an edit (apps/view_edits.h),
// the same path as --edit, so the renderer reruns only the stages the value reaches; "Copy as
// JSON" puts the edits' JSON Patch on the clipboard and prints it.
#include <string>
#include <vector>

#include "apps/view_edits.h"
#include "core/scene.h"
#include "render/gpu_timer.h"

namespace eikon::app {

// What the panel shows besides the scene.
struct PanelFigures {
    int frame = 0;
    bool playing = false;
    int scale = 1;                  // the picture was rendered at 1/scale of the full size
    double frameMs = 0.0;           // the last picture's time
    double frameBudgetMs = 0.0;     // the preview's frame budget (0: the preview scale stays)
    std::vector<StageTime> stages;  // the last picture's stages
};

// What the panel keeps from frame to frame: the light-transport settings being typed, and why
// the last ones were refused.
struct PanelMemory {
    std::string transportText;
    std::string transportError;
};

// What the user asked for in the panel this frame.
struct PanelRequests {
    bool edited = false;          // an edit was made: render again
    bool togglePlay = false;      // the Play / Pause button
    bool reset = false;           // back to the first frame
    double frameBudgetMs = -1.0;  // ≥ 0: the frame budget the slider was set to
};

// Lays out the panel (between UiOverlay::begin and end) for `shown`, the scene of the picture on
// screen (the edits in it), making the user's edits in `edits`.
PanelRequests drawViewPanel(const Scene& shown, ViewEdits& edits, const PanelFigures& figures,
                            PanelMemory& memory);

}  // namespace eikon::app
