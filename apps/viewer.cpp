#include "apps/viewer.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "apps/view_panel.h"
#include "core/camera.h"
#include "render/image_resize.h"
#include "render/preview_budget.h"

namespace eikon::app {
namespace {

static_assert(GLFW_KEY_LAST + 1 == 349, "Viewer::keysDown_ must hold every GLFW key");

double scrollAccumulated = 0.0;  // the wheel arrives through a callback

std::string statsLine(const std::vector<StageTime>& stages) {
    std::string line;
    for (const StageTime& s : stages) {
        char buf[64];
        std::snprintf(buf, sizeof(buf), "%s %.0f ms  ", s.name.c_str(),
                      s.gpuMs > 0 ? s.gpuMs : s.cpuMs);
        line += buf;
    }
    return line;
}

// A side of `full` pixels at 1/scale, rounded, at least one pixel.
int scaledSide(int full, int scale) {
    return std::max(1, int(std::lround(double(full) / double(scale))));
}

// The viewing pass's time among a frame's stages (the GPU's where it has one); 0: none.
double viewStageMs(const std::vector<StageTime>& stages) {
    for (const StageTime& s : stages)
        if (s.name == "view") return s.gpuMs > 0 ? s.gpuMs : s.cpuMs;
    return 0.0;
}

}  // namespace

Viewer::Viewer(const Scene& scene, SceneDriver& driver, ViewHandles& handles,
               GlfwWindowContext& window, FrameRenderer& renderer, ViewerOptions options)
    : scene_(scene),
      driver_(driver),
      handles_(handles),
      window_(window),
      renderer_(renderer),
      options_(std::move(options)) {
    state_.frame = scene.time.frameStart;
    state_.exposure = scene.render.exposure;
    state_.playing = options_.play;
    state_.previewScale = options_.previewScale;
    if (options_.drag && options_.drag->handle.rfind("lights/", 0) == 0) {
        lights_.select(options_.drag->handle, scene.lights.size());
        state_.draggingLight = true;
    }
    glfwSetScrollCallback(window_.window(),
                          [](GLFWwindow*, double, double dy) { scrollAccumulated += dy; });
    overlay_ = std::make_unique<UiOverlay>(window_.window());
    // ARAP handles read the driver's frame as the viewer drags them: they keep the simulation in
    // the viewer's thread.
    if (driver_.arapHandles().empty()) ahead_ = std::make_unique<SimulationAhead>(driver_, scene_);
}

Viewer::~Viewer() {
    ahead_.reset();    // stops stepping before the driver goes
    overlay_.reset();  // gives the window its callbacks back
    glfwSetScrollCallback(window_.window(), nullptr);
}

bool Viewer::pressed(int key) {
    const bool down = glfwGetKey(window_.window(), key) == GLFW_PRESS;
    const bool edge = down && !keysDown_[key];
    keysDown_[key] = down;
    return edge;
}

CameraFrame Viewer::cameraOf(const Scene& frame) const {
    return makeCameraFrame(frame.camera, renderer_.volume().bounds, scene_.render.width,
                           scene_.render.height);
}

void Viewer::showMarkers() {
    state_.shown = state_.image;
    handles_.drawMarkers(state_.shown);
    if (state_.panel) lights_.drawMarkers(state_.shown);  // the gizmos hide with the panel
}

void Viewer::keyShortcuts() {
    ViewerState& s = state_;
    if (pressed(GLFW_KEY_TAB)) {
        s.panel = !s.panel;
        if (s.rendered > 0) showMarkers();
    }
    if (pressed(GLFW_KEY_E)) s.exposure += 0.5f;
    if (pressed(GLFW_KEY_Q)) s.exposure -= 0.5f;
    if (pressed(GLFW_KEY_SPACE)) s.playing = !s.playing;
    // Stepping pauses: the frame stepped from is the one on screen.
    if (pressed(GLFW_KEY_RIGHT_BRACKET)) ++s.frame, s.dirty = true, s.playing = false;
    if (pressed(GLFW_KEY_LEFT_BRACKET)) --s.frame, s.dirty = true, s.playing = false;
    if (pressed(GLFW_KEY_R) && s.orbit) {
        s.orbit.emplace(scene_.camera, renderer_.volume().bounds, scene_.render.width,
                        scene_.render.height);
        s.dirty = true;
    }
    if (pressed(GLFW_KEY_H) && s.rendered > 0) {
        handles_.selectNext();
        s.draggingLight = false;
        showMarkers();
    }
    s.screenshotAsked = pressed(GLFW_KEY_P);
}

bool Viewer::input() {
    ViewerState& s = state_;
    GLFWwindow* w = window_.window();
    // Nothing to render (the picture refined, nothing playing, no script): sleep until an event
    // or a tenth of a second, rather than redraw the same picture at full speed.
    const bool idle = !s.dirty && s.scale == 1 && !s.playing && options_.exitAfter == 0 &&
                      s.pendingDrag == glm::vec2(0.0f);
    if (idle)
        glfwWaitEventsTimeout(0.1);
    else
        window_.pollEvents();
    if (pressed(GLFW_KEY_ESCAPE)) return false;
    // What the panel takes (the cursor over it, a field being typed in) the view leaves alone.
    const bool panelKeys = s.panel && overlay_->wantsKeyboard();
    const bool panelMouse = s.panel && overlay_->wantsMouse();
    if (panelKeys) {
        for (bool& down : keysDown_) down = false;  // no shortcut fires for the panel's typing
        s.screenshotAsked = false;
    } else {
        keyShortcuts();
    }
    double x = 0, y = 0;
    glfwGetCursorPos(w, &x, &y);
    // The cursor is in window units; the image may be shown larger or smaller.
    int windowWidth = 0, windowHeight = 0;
    glfwGetWindowSize(w, &windowWidth, &windowHeight);
    const float toImage = windowWidth > 0 ? float(scene_.render.width) / float(windowWidth) : 1.0f;
    const glm::vec2 cursor = toImage * glm::vec2(float(x), float(y));
    const glm::vec2 moved = toImage * glm::vec2(float(x - s.lastX), float(y - s.lastY));
    const bool left = !panelMouse && glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    if (left && s.orbiting && s.orbit && (x != s.lastX || y != s.lastY)) {
        s.orbit->orbit(-0.01f * float(x - s.lastX), -0.01f * float(y - s.lastY));
        s.dirty = true;
    }
    s.orbiting = left;
    const bool right = !panelMouse && glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    if (right && !s.draggingHandle && s.rendered > 0) {
        s.draggingHandle = true;
        // An ARAP handle first, a light's gizmo second; neither: the last selection is dragged.
        if (handles_.pick(cursor)) {
            s.draggingLight = false;
            lights_.deselect();
            showMarkers();
        } else if (lights_.pick(cursor)) {
            s.draggingLight = true;
            showMarkers();
        }
    } else if (right && (s.draggingLight ? lights_.selected() : handles_.selected()) &&
               moved != glm::vec2(0.0f)) {
        s.pendingDrag += moved;
        s.dirty = true;
    } else if (!right && s.draggingHandle) {
        s.draggingHandle = false;
        if (s.draggingLight ? lights_.selected() : handles_.selected())
            std::printf("%s\n", describeDragged().c_str());
    }
    s.lastX = x, s.lastY = y;
    if (panelMouse) scrollAccumulated = 0.0;  // the panel scrolls itself
    if (scrollAccumulated != 0.0 && s.orbit) {
        s.orbit->zoom(std::pow(0.9f, float(scrollAccumulated)));
        scrollAccumulated = 0.0;
        s.dirty = true;
    }
    // A scripted run (--exit-after) stops moving after its frames, so that the last one refines.
    const bool scriptDone = options_.exitAfter > 0 && s.frames >= options_.exitAfter;
    // Playing: frame by frame here when the simulation cannot run ahead (takeSteppedFrame).
    if (playing() && s.frames > 0 && !ahead_) ++s.frame, s.dirty = true;
    if (s.frame > scene_.time.frameEnd) s.frame = scene_.time.frameStart;
    if (s.frame < scene_.time.frameStart) s.frame = scene_.time.frameEnd;
    if (options_.exitAfter > 0 && s.frames > 0 && !scriptDone && s.orbit) {
        s.orbit->orbit(0.1745f, 0.0f);
        s.dirty = true;
    }
    return true;
}

bool Viewer::playing() const {
    const bool scriptDone = options_.exitAfter > 0 && state_.frames >= options_.exitAfter;
    return state_.playing && !scriptDone;
}

std::optional<FrameInputs> Viewer::takeSteppedFrame() {
    ViewerState& s = state_;
    if (!ahead_) return std::nullopt;
    const bool scripted = options_.exitAfter > 0;
    const bool play = playing() && s.frames > 0;
    if (play && !ahead_->running())
        ahead_->start(s.frame >= scene_.time.frameEnd ? scene_.time.frameStart : s.frame + 1,
                      scripted ? options_.exitAfter - s.frames : -1);
    if (!play && ahead_->running()) {
        // Paused (or a frame asked for): what was stepped and not shown goes with the next
        // frame's inputs, so the renderer is given everything the driver handed out. A pause
        // shows the last frame stepped, where the driver is, rather than stepping it back to the
        // one on screen; a frame the user asked for ([ ], Reset) is kept.
        ahead_->stop();
        if (std::optional<FrameInputs> left = ahead_->take(false)) {
            if (s.frame == renderedFrame_) s.frame = left->frame, s.dirty = true;
            if (carried_)
                mergeFrameInputs(*carried_, std::move(*left));
            else
                carried_ = std::move(left);
        }
        return std::nullopt;
    }
    if (!ahead_->running() && !play) return std::nullopt;
    std::optional<FrameInputs> stepped = ahead_->take(scripted);
    if (stepped) s.frame = stepped->frame, s.dirty = true;
    return stepped;
}

void Viewer::render() {
    ViewerState& s = state_;
    // The frame's time counts its simulation step (or the wait for the simulation's thread) and a
    // drag's solve with the render.
    const auto start = std::chrono::steady_clock::now();
    std::optional<FrameInputs> stepped = takeSteppedFrame();
    const bool scriptedNow = options_.drag && s.frames == 1;
    if (scriptedNow) s.pendingDrag += options_.drag->pixels, s.dirty = true;
    if (!options_.edits.empty() && s.frames == 1) {
        edits_.adopt(scene_, options_.edits);
        options_.edits = ViewEdits{};
        std::printf("edited; to keep the edits, patch the scene with %s\n",
                    edits_.jsonPatch().c_str());
        s.dirty = true;
    }
    // A change starts at the preview size; no change refines the last picture, to full size.
    int scale = 1;
    if (s.dirty)
        scale = s.previewScale;
    else if (s.scale > 1 && !playing())  // a playing picture is replaced, not refined
        scale = s.scale / 2;
    else
        return;
    const int width = scene_.render.width, height = scene_.render.height;
    FrameInputs inputs;
    if (stepped) {
        inputs = std::move(*stepped);
    } else if (ahead_ && ahead_->running()) {
        inputs = FrameInputs(s.frame, frameScene_);  // the driver is the thread's: same frame
    } else {
        inputs = driver_.frameInputs(s.frame, scene_);
        if (carried_) {
            mergeFrameInputs(*carried_, std::move(inputs));
            inputs = std::move(*carried_);
            carried_.reset();
        }
    }
    frameScene_ = inputs.scene;
    renderedFrame_ = inputs.frame;
    edits_.apply(inputs.scene);  // over the tracks: the user's edits win, as the view does
    if (s.orbit) inputs.scene.camera = s.orbit->spec();  // the user's view wins
    if (s.pendingDrag != glm::vec2(0.0f) && s.rendered > 0) {
        const CameraFrame camera = cameraOf(inputs.scene);
        handles_.locate(camera, width);
        lights_.locate(inputs.scene, renderer_.volume().bounds, camera, width);
        if (scriptedNow) std::printf("before the drag: %s\n", describeDragged().c_str());
        const auto dragStart = std::chrono::steady_clock::now();
        if (s.draggingLight) {
            lights_.drag(inputs.scene, camera, width, s.pendingDrag, edits_);
            edits_.apply(inputs.scene);
        } else {
            handles_.drag(inputs, camera, width, s.pendingDrag);
        }
        s.dragMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - dragStart)
                .count();
        s.pendingDrag = glm::vec2(0.0f);
    }
    inputs.scene.render.width = scaledSide(width, scale);
    inputs.scene.render.height = scaledSide(height, scale);
    // A change's preview may trace the light lighter; a refinement traces it as the scene says.
    renderer_.setPreview(options_.lighterPreviews && s.dirty && scale > 1);
    const Image picture = renderer_.render(inputs);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    s.image = resizeBilinear(picture, width, height);
    if (!s.orbit) s.orbit.emplace(scene_.camera, renderer_.volume().bounds, width, height);
    handles_.locate(cameraOf(renderer_.scene()), width);  // in the full size's pixels
    lights_.locate(renderer_.scene(), renderer_.volume().bounds, cameraOf(renderer_.scene()),
                   width);
    if (scriptedNow) std::printf("after the drag: %s\n", describeDragged().c_str());
    showMarkers();
    s.lastStages = renderer_.takeStats();
    s.lastMs = ms;
    std::string stats = statsLine(s.lastStages);
    if (s.dragMs >= 0.0) {
        char drag[48];
        std::snprintf(drag, sizeof(drag), "%s drag %.1f ms  ", s.draggingLight ? "light" : "ARAP",
                      s.dragMs);
        stats = drag + stats;
        s.dragMs = -1.0;
    }
    if (scriptedNow) std::printf("the drag's frame: %s\n", stats.c_str());
    char size[64];
    if (scale == 1)
        std::snprintf(size, sizeof(size), "full size, %.0f ms", ms);
    else
        std::snprintf(size, sizeof(size), "1/%d size, %.0f ms", scale, ms);
    const std::string title =
        "eikon view - frame " + std::to_string(s.frame) + " - " + size + " - " + stats;
    glfwSetWindowTitle(window_.window(), title.c_str());
    if (s.dirty && s.frames == 0) {
        ++s.frames, s.firstMs = ms;
    } else if (s.dirty) {
        ++s.frames, s.framesMs += ms;
        s.finestPreview = s.finestPreview == 0 ? scale : std::min(s.finestPreview, scale);
        s.coarsestPreview = std::max(s.coarsestPreview, scale);
        // The first frame loads and lights the scene: not what a change costs, so not a guide.
        s.previewScale =
            budgetedPreviewScale(scale, ms, viewStageMs(s.lastStages), options_.frameBudgetMs);
    } else {
        ++s.refinements, s.refinementsMs += ms;
    }
    ++s.rendered;
    s.scale = scale;
    s.dirty = false;
}

std::string Viewer::describeDragged() const {
    if (state_.draggingLight) return lights_.describeSelected(edits_);
    return handles_.describeSelected(driver_.timeOfFrame(state_.frame));
}

void Viewer::drawPanel() {
    ViewerState& s = state_;
    overlay_->begin();
    const PanelFigures figures{s.frame,     s.playing, s.scale, s.lastMs, options_.frameBudgetMs,
                               s.lastStages};
    const PanelRequests asked = drawViewPanel(renderer_.scene(), edits_, figures, panelMemory_);
    overlay_->end();
    if (asked.edited) s.dirty = true;
    if (asked.togglePlay) s.playing = !s.playing;
    if (asked.reset) s.frame = scene_.time.frameStart, s.dirty = true, s.playing = false;
    if (asked.frameBudgetMs >= 0.0) options_.frameBudgetMs = asked.frameBudgetMs;
}

bool Viewer::present() {
    ViewerState& s = state_;
    const auto fb = window_.framebufferSize();
    display_.draw(s.shown, s.exposure, scene_.render.toneCurve, fb.width, fb.height);
    // The last frame is shown once it is refined to full size.
    const bool last = options_.exitAfter > 0 && s.frames >= options_.exitAfter && s.scale == 1;
    if ((last || s.screenshotAsked) && (!options_.screenshot.empty() || !last)) {
        const std::string path =
            options_.screenshot.empty() ? "eikon_view.png" : options_.screenshot;
        writePngRgb8(path, fb.width, fb.height, display_.readPixels(fb.width, fb.height));
        std::printf("wrote %s\n", path.c_str());
    }
    if (s.panel) drawPanel();
    if (last && !options_.panelScreenshot.empty()) {
        writePngRgb8(options_.panelScreenshot, fb.width, fb.height,
                     display_.readPixels(fb.width, fb.height));
        std::printf("wrote %s\n", options_.panelScreenshot.c_str());
    }
    window_.swapBuffers();
    return !last;
}

}  // namespace eikon::app
