#pragma once
// The interactive viewer's loop in its four parts (eikon view, apps/cmd_view.cpp): input (keys,
// mouse, wheel) changes the viewer state; render makes a new picture when the state says the
// scene, the frame or the camera changed; present draws the last picture to the window and
// saves screenshots. The state lives in one struct, so that what a key does is a change of a
// field, and what the loop shows follows from the fields.
// Progressive: a change (the camera, a handle, the frame) is first rendered at 1/previewScale of
// the window's size in each direction, shown enlarged (render/image_resize.h); while nothing
// changes, each pass of the loop renders the same picture at twice the size of the last, up to
// the full size. Light transport does not depend on the picture's size, so the refinements
// reuse it (photons, light volumes, sweeps): they rerun the viewing pass alone. With a frame
// budget, the preview's scale follows the frame times: the finest whose picture fits the budget.
// Playing, the simulation steps on a thread of its own (pipeline/simulation_ahead.h) and the view
// shows the latest frame it finished, so the simulation does not wait for the view (a scene with
// ARAP handles steps in the viewer's thread, since a drag reads the driver's frame). A playing
// picture is replaced by the next frame rather than refined; [ ] and Reset pause.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "apps/light_gizmos.h"
#include "apps/orbit_camera.h"
#include "apps/view_edits.h"
#include "apps/view_handles.h"
#include "apps/view_panel.h"
#include "pipeline/scene_driver.h"
#include "pipeline/simulation_ahead.h"
#include "render/display_pass.h"
#include "render/frame_renderer.h"
#include "render/gl_context.h"
#include "render/image.h"
#include "render/ui_overlay.h"

struct GLFWwindow;

namespace eikon::app {

// A scripted drag (--drag): the handle's name ("mesh/handle", or "lights/<i>" for a light's
// gizmo) and the pixels it moves by.
struct ScriptedDrag {
    std::string handle;
    glm::vec2 pixels{0.0f};
};

struct ViewerOptions {
    // Render this many frames (orbiting 10 degrees each), refine the last to full size, then quit.
    int exitAfter = 0;
    std::string screenshot;       // the picture
    std::string panelScreenshot;  // the window, the panel drawn over the picture
    std::optional<ScriptedDrag> drag;
    int previewScale = 4;  // a power of two; 1: every picture at full size
    // > 0: after each change, the next change's preview scale is chosen so that its picture
    // takes about this many ms (render/preview_budget.h), starting from previewScale.
    double frameBudgetMs = 0.0;
    bool play = false;  // start playing the frames, as Space does
    // Previews that must trace the light again trace it with the method's lighter settings
    // (FrameRenderer::setPreview); the refinement to full size traces it as set.
    bool lighterPreviews = true;
    ViewEdits edits;  // --edit: made after the first frame, as a user's would be
};

// What the user has asked for so far, and what is on screen.
struct ViewerState {
    int frame = 0;
    float exposure = 0.0f;
    bool dirty = true;  // the picture must be rendered again
    bool playing = false;
    int frames = 0;        // pictures of a change (at the preview size)
    int refinements = 0;   // pictures of no change, each at twice the size of the last
    int rendered = 0;      // both
    int scale = 1;         // the last picture was rendered at 1/scale of the full size
    int previewScale = 1;  // the next change is rendered at 1/previewScale (set by the viewer)
    // The finest and coarsest preview scales of the changes after the first, for the summary.
    int finestPreview = 0, coarsestPreview = 0;
    // Times from the frame's inputs (a simulation step, a drag) to its picture: the first frame's
    // (it loads, resamples and lights the scene), then the sums of the later frames' and of the
    // refinements'.
    double firstMs = 0.0, framesMs = 0.0, refinementsMs = 0.0;
    double lastMs = 0.0;  // the last picture's, and its stages, for the panel
    std::vector<StageTime> lastStages;
    bool panel = true;   // the relighting panel (apps/view_panel.h) shows
    Image image, shown;  // the render at full size, and with the handles' markers
    std::optional<OrbitCamera> orbit;
    double lastX = 0, lastY = 0;  // the cursor at the last input, window units
    bool orbiting = false, draggingHandle = false;
    bool draggingLight = false;   // the right drag moves a light's gizmo, not an ARAP handle
    glm::vec2 pendingDrag{0.0f};  // image pixels the selected handle still has to move
    double dragMs = -1.0;         // the last drag's solve, for the title; -1: none since
    bool screenshotAsked = false;
};

class Viewer {
public:
    // The window must be the renderer's context (GPU) or at least current (CPU twin).
    Viewer(const Scene& scene, SceneDriver& driver, ViewHandles& handles, GlfwWindowContext& window,
           FrameRenderer& renderer, ViewerOptions options);
    ~Viewer();

    // Reads the window's events into the state; false when the user quits (Esc).
    bool input();
    // Renders the frame the state asks for, if anything changed.
    void render();
    // Draws the last picture, saves a screenshot when asked (the picture, not the panel), draws
    // the panel over it and takes its requests; false when --exit-after is reached.
    bool present();

    const ViewerState& state() const { return state_; }

private:
    // The camera of `frame` (a frame's scene) over the renderer's volume.
    CameraFrame cameraOf(const Scene& frame) const;
    void showMarkers();
    void keyShortcuts();  // Tab, E, Q, Space, [, ], R, H, P
    void drawPanel();     // the relighting panel over the picture, and what it asks for
    // While playing, the frame the simulation's thread stepped (starting and stopping it).
    std::optional<FrameInputs> takeSteppedFrame();
    bool playing() const;  // frames play (Space, --play), and a script has frames left
    // Where the selected handle or light is, and what keeps its pose.
    std::string describeDragged() const;

    const Scene& scene_;  // as loaded: its camera is the one R resets to
    SceneDriver& driver_;
    ViewHandles& handles_;
    LightGizmos lights_;
    GlfwWindowContext& window_;
    FrameRenderer& renderer_;
    ViewerOptions options_;
    ViewEdits edits_;  // the user's edits so far, written into every frame's scene
    DisplayPass display_;
    std::unique_ptr<UiOverlay> overlay_;  // after the viewer's own callbacks, which it chains
    PanelMemory panelMemory_;
    // Playing steps the simulation on a thread of its own (none with ARAP handles).
    std::unique_ptr<SimulationAhead> ahead_;
    std::optional<FrameInputs> carried_;  // stepped, not shown, when playing stopped
    Scene frameScene_;        // the last frame's scene as the driver made it (tracks, no edits)
    int renderedFrame_ = -1;  // the frame of the picture on screen
    ViewerState state_;
    bool keysDown_[349] = {};  // GLFW_KEY_LAST + 1 (checked in viewer.cpp)
    bool pressed(int key);     // true once per press
};

}  // namespace eikon::app
