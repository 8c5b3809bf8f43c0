// eikon view: a window that renders the scene live. Left drag orbits, the wheel zooms, E/Q change
// exposure, [ and ] step frames, Space plays, P saves a screenshot, R resets the view, Esc quits.
// A camera move reruns only the viewing pass (light volumes and uploads are reused). ARAP handles
// show as rings: a right click picks one, H selects the next, a right drag moves it and the shape
// follows (apps/view_handles.h).
#include <GLFW/glfw3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "apps/commands.h"
#include "apps/orbit_camera.h"
#include "apps/scene_driver.h"
#include "apps/scene_input.h"
#include "apps/view_handles.h"
#include "core/camera.h"
#include "core/error.h"
#include "render/display_pass.h"
#include "render/frame_renderer.h"
#include "render/gl_context.h"

namespace eikon::app {
namespace {

struct ViewOptions {
    std::string input;
    std::string size;
    std::string backend = "auto";
    int exitAfter = 0;  // render this many frames (orbiting 10 degrees each), then quit
    std::string screenshot;
    std::string drag;  // "mesh/handle:DX,DY": drag that handle once, after the first frame
};

// A scripted drag: the handle's name and the pixels it moves by.
struct ScriptedDrag {
    std::string handle;
    glm::vec2 pixels{0.0f};
};

ScriptedDrag parseDrag(const std::string& text) {
    const size_t colon = text.rfind(':');
    ScriptedDrag d;
    char end = 0;
    if (colon == std::string::npos ||
        std::sscanf(text.c_str() + colon + 1, "%f,%f%c", &d.pixels.x, &d.pixels.y, &end) != 2 ||
        !std::isfinite(d.pixels.x) || !std::isfinite(d.pixels.y))
        throw Error("--drag", "'" + text + "' is not MESH/HANDLE:DX,DY (pixels, y down)");
    d.handle = text.substr(0, colon);
    return d;
}

// Keys that act once per press.
class KeyEdges {
public:
    explicit KeyEdges(GLFWwindow* w) : window_(w) {}
    bool pressed(int key) {
        const bool down = glfwGetKey(window_, key) == GLFW_PRESS;
        const bool edge = down && !down_[key];
        down_[key] = down;
        return edge;
    }

private:
    GLFWwindow* window_;
    bool down_[GLFW_KEY_LAST + 1] = {};
};

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

int runView(const ViewOptions& o) {
    std::optional<ScriptedDrag> scripted;
    if (!o.drag.empty()) scripted = parseDrag(o.drag);
    Scene scene = sceneFromInput(o.input, "", o.size);
    // Before the window opens, so that a bad scene or --drag fails without a display.
    SceneDriver driver(scene);
    ViewHandles handles(driver, scene);
    if (scripted) handles.select(scripted->handle);
    GlfwWindowContext window(scene.render.width, scene.render.height, "eikon view");
    // "auto": the window's GPU unless it is a software rasterizer (see apps/backend_choice.h).
    const bool gpu =
        o.backend == "gpu" || (o.backend == "auto" && !isSoftwareRenderer(window.rendererName()));
    FrameRenderer renderer(scene, gpu ? Backend::Gpu : Backend::Cpu, &window);
    std::printf("%s: %s\n", gpu ? "GPU" : "CPU twin (display on OpenGL)",
                window.rendererName().c_str());
    DisplayPass display;
    glfwSetScrollCallback(window.window(),
                          [](GLFWwindow*, double, double dy) { scrollAccumulated += dy; });
    KeyEdges keys(window.window());

    int frame = scene.time.frameStart;
    float exposure = scene.render.exposure;
    bool dirty = true, playing = false;
    int rendered = 0;
    Image image, shown;  // the render, and the render with the handles' markers
    std::optional<OrbitCamera> orbit;
    double lastX = 0, lastY = 0;
    bool orbiting = false, draggingHandle = false;
    glm::vec2 pendingDrag(0.0f);  // image pixels the selected handle still has to move
    double dragMs = -1.0;         // the last drag's solve, for the title; -1: none since
    const int width = scene.render.width;
    auto cameraNow = [&] {
        return makeCameraFrame(renderer.scene().camera, renderer.volume().bounds, width,
                               scene.render.height);
    };
    auto showMarkers = [&] {
        shown = image;
        handles.drawMarkers(shown);
    };
    while (!window.shouldClose()) {
        window.pollEvents();
        if (keys.pressed(GLFW_KEY_ESCAPE)) break;
        if (keys.pressed(GLFW_KEY_E)) exposure += 0.5f;
        if (keys.pressed(GLFW_KEY_Q)) exposure -= 0.5f;
        if (keys.pressed(GLFW_KEY_SPACE)) playing = !playing;
        if (keys.pressed(GLFW_KEY_RIGHT_BRACKET)) ++frame, dirty = true;
        if (keys.pressed(GLFW_KEY_LEFT_BRACKET)) --frame, dirty = true;
        if (keys.pressed(GLFW_KEY_R) && orbit) {
            orbit.emplace(scene.camera, renderer.volume().bounds, scene.render.width,
                          scene.render.height);
            dirty = true;
        }
        if (keys.pressed(GLFW_KEY_H) && rendered > 0) {
            handles.selectNext();
            showMarkers();
        }
        double x = 0, y = 0;
        glfwGetCursorPos(window.window(), &x, &y);
        // The cursor is in window units; the image may be shown larger or smaller.
        int windowWidth = 0, windowHeight = 0;
        glfwGetWindowSize(window.window(), &windowWidth, &windowHeight);
        const float toImage = windowWidth > 0 ? float(width) / float(windowWidth) : 1.0f;
        const glm::vec2 cursor = toImage * glm::vec2(float(x), float(y));
        const glm::vec2 moved = toImage * glm::vec2(float(x - lastX), float(y - lastY));
        const bool left = glfwGetMouseButton(window.window(), GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        if (left && orbiting && orbit && (x != lastX || y != lastY)) {
            orbit->orbit(-0.01f * float(x - lastX), -0.01f * float(y - lastY));
            dirty = true;
        }
        orbiting = left;
        const bool right =
            glfwGetMouseButton(window.window(), GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
        if (right && !draggingHandle && rendered > 0) {
            draggingHandle = true;
            if (handles.pick(cursor)) showMarkers();
        } else if (right && handles.selected() && moved != glm::vec2(0.0f)) {
            pendingDrag += moved;
            dirty = true;
        } else if (!right && draggingHandle) {
            draggingHandle = false;
            if (handles.selected())
                std::printf("%s\n",
                            handles.describeSelected(renderer, driver.timeOfFrame(frame)).c_str());
        }
        lastX = x, lastY = y;
        if (scrollAccumulated != 0.0 && orbit) {
            orbit->zoom(std::pow(0.9f, float(scrollAccumulated)));
            scrollAccumulated = 0.0;
            dirty = true;
        }
        if (playing) ++frame, dirty = true;
        if (frame > scene.time.frameEnd) frame = scene.time.frameStart;
        if (frame < scene.time.frameStart) frame = scene.time.frameEnd;
        if (o.exitAfter > 0 && rendered > 0 && orbit) {
            orbit->orbit(0.1745f, 0.0f);
            dirty = true;
        }
        const bool scriptedNow = scripted && rendered == 1;
        if (scriptedNow) pendingDrag += scripted->pixels, dirty = true;

        if (dirty) {
            driver.prepareFrame(renderer, frame);
            if (orbit) renderer.scene().camera = orbit->spec();  // the user's view wins
            if (pendingDrag != glm::vec2(0.0f) && rendered > 0) {
                const CameraFrame camera = cameraNow();
                handles.locate(renderer, camera, width);
                if (scriptedNow)
                    std::printf(
                        "before the drag: %s\n",
                        handles.describeSelected(renderer, driver.timeOfFrame(frame)).c_str());
                const auto start = std::chrono::steady_clock::now();
                handles.drag(renderer, camera, width, pendingDrag);
                dragMs = std::chrono::duration<double, std::milli>(
                             std::chrono::steady_clock::now() - start)
                             .count();
                pendingDrag = glm::vec2(0.0f);
            }
            image = renderer.render(frame);
            if (!orbit)
                orbit.emplace(scene.camera, renderer.volume().bounds, scene.render.width,
                              scene.render.height);
            handles.locate(renderer, cameraNow(), width);
            if (scriptedNow)
                std::printf("after the drag: %s\n",
                            handles.describeSelected(renderer, driver.timeOfFrame(frame)).c_str());
            showMarkers();
            std::string stats = statsLine(renderer.takeStats());
            if (dragMs >= 0.0) {
                char drag[48];
                std::snprintf(drag, sizeof(drag), "ARAP drag %.1f ms  ", dragMs);
                stats = drag + stats;
                dragMs = -1.0;
            }
            if (scriptedNow) std::printf("the drag's frame: %s\n", stats.c_str());
            const std::string title = "eikon view - frame " + std::to_string(frame) + " - " + stats;
            glfwSetWindowTitle(window.window(), title.c_str());
            ++rendered;
            dirty = false;
        }
        const auto fb = window.framebufferSize();
        display.draw(shown, exposure, scene.render.toneCurve, fb.width, fb.height);
        const bool last = o.exitAfter > 0 && rendered >= o.exitAfter;
        if ((last || keys.pressed(GLFW_KEY_P)) && (!o.screenshot.empty() || !last)) {
            const std::string path = o.screenshot.empty() ? "eikon_view.png" : o.screenshot;
            writePngRgb8(path, fb.width, fb.height, display.readPixels(fb.width, fb.height));
            std::printf("wrote %s\n", path.c_str());
        }
        window.swapBuffers();
        if (last) break;
    }
    const std::string method = renderer.lightTransport().name();
    std::printf("frames rendered %d, uploads %d, resamples %d, %s runs %d\n", rendered,
                renderer.uploads(), renderer.resamples(), method.c_str(),
                renderer.transportRuns(method));
    return 0;
}

}  // namespace

void addViewCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand("view", "Show a scene or VDB cache in a window, live");
    auto o = std::make_shared<ViewOptions>();
    cmd->add_option("input", o->input, "scene.json or cache.vdb")->required();
    cmd->add_option("--size", o->size, "window size WIDTHxHEIGHT");
    cmd->add_option("--backend", o->backend,
                    "auto (GPU unless OpenGL is software), gpu, or cpu (the window still needs "
                    "OpenGL)")
        ->check(CLI::IsMember({"auto", "gpu", "cpu"}));
    cmd->add_option("--exit-after", o->exitAfter,
                    "render this many frames, orbiting 10 degrees each, then quit (for tests)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--screenshot", o->screenshot, "with --exit-after: save the last frame here");
    cmd->add_option("--drag", o->drag,
                    "MESH/HANDLE:DX,DY: after the first frame, drag that ARAP handle by DX,DY "
                    "pixels (y down) as a right drag would, and print where it went (for tests)");
    cmd->callback([o, &exitCode] { exitCode = runView(*o); });
}

}  // namespace eikon::app
