// eikon view: a window that renders the scene live. Left drag orbits, the wheel zooms, E/Q change
// exposure, [ and ] step frames, Space plays, P saves a screenshot, R resets the view, Esc quits.
// A camera move reruns only the viewing pass (light volumes and uploads are reused).
#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "apps/commands.h"
#include "apps/orbit_camera.h"
#include "apps/scene_driver.h"
#include "apps/scene_input.h"
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
};

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
    Scene scene = sceneFromInput(o.input, "", o.size);
    GlfwWindowContext window(scene.render.width, scene.render.height, "eikon view");
    // "auto": the window's GPU unless it is a software rasterizer (see apps/backend_choice.h).
    const bool gpu =
        o.backend == "gpu" || (o.backend == "auto" && !isSoftwareRenderer(window.rendererName()));
    FrameRenderer renderer(scene, gpu ? Backend::Gpu : Backend::Cpu, &window);
    SceneDriver driver(scene);
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
    Image image;
    std::optional<OrbitCamera> orbit;
    double lastX = 0, lastY = 0;
    bool dragging = false;
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
        double x = 0, y = 0;
        glfwGetCursorPos(window.window(), &x, &y);
        const bool down = glfwGetMouseButton(window.window(), GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        if (down && dragging && orbit && (x != lastX || y != lastY)) {
            orbit->orbit(-0.01f * float(x - lastX), -0.01f * float(y - lastY));
            dirty = true;
        }
        dragging = down;
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

        if (dirty) {
            driver.prepareFrame(renderer, frame);
            if (orbit) renderer.scene().camera = orbit->spec();  // the user's view wins
            image = renderer.render(frame);
            if (!orbit)
                orbit.emplace(scene.camera, renderer.volume().bounds, scene.render.width,
                              scene.render.height);
            const std::string title = "eikon view - frame " + std::to_string(frame) + " - " +
                                      statsLine(renderer.takeStats());
            glfwSetWindowTitle(window.window(), title.c_str());
            ++rendered;
            dirty = false;
        }
        const auto fb = window.framebufferSize();
        display.draw(image, exposure, scene.render.toneCurve, fb.width, fb.height);
        const bool last = o.exitAfter > 0 && rendered >= o.exitAfter;
        if ((last || keys.pressed(GLFW_KEY_P)) && (!o.screenshot.empty() || !last)) {
            const std::string path = o.screenshot.empty() ? "eikon_view.png" : o.screenshot;
            writePngRgb8(path, fb.width, fb.height, display.readPixels(fb.width, fb.height));
            std::printf("wrote %s\n", path.c_str());
        }
        window.swapBuffers();
        if (last) break;
    }
    std::printf("frames rendered %d, uploads %d, resamples %d, light volume updates %d\n", rendered,
                renderer.uploads(), renderer.resamples(), renderer.lightVolumeUpdates());
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
    cmd->callback([o, &exitCode] { exitCode = runView(*o); });
}

}  // namespace eikon::app
