// eikon view: a window that renders the scene live. Left drag orbits, the wheel zooms, E/Q change
// exposure, [ and ] step frames, Space plays, P saves a screenshot, R resets the view, Esc quits.
// A camera move reruns only the viewing pass (light volumes and uploads are reused). ARAP handles
// show as rings: a right click picks one, H selects the next, a right drag moves it and the shape
// follows (apps/view_handles.h). A change is rendered at a quarter of the size first and refined
// to full size while nothing changes (--preview-scale). The loop itself (input, state, render,
// present) is apps/viewer.h.
#include <malloc.h>
#include <climits>
#include <cmath>
#include <cstdio>
#include <memory>

#include "apps/commands.h"
#include "apps/light_gizmos.h"
#include "apps/memory_limit_option.h"
#include "apps/view_handles.h"
#include "apps/viewer.h"
#include "core/error.h"
#include "core/log.h"
#include "pipeline/scene_driver.h"
#include "pipeline/scene_input.h"
#include "render/frame_renderer.h"
#include "render/gl_context.h"

namespace eikon::app {
namespace {

struct ViewOptions {
    std::string input;
    std::string size;
    std::string backend = "auto";
    int exitAfter = 0;  // render this many frames (orbiting 10 degrees each), then quit
    int previewScale = 4;
    double frameBudget = -1.0;  // ms; < 0: kInteractiveFrameBudgetMs interactively, else none
    std::string previewLight = "lighter";
    std::string screenshot;
    std::string panelScreenshot;
    std::string drag;  // "mesh/handle:DX,DY": drag that handle once, after the first frame
    std::vector<std::string> edits;  // "POINTER=V[,V...]": made after the first frame
    bool hold = false;
    bool play = false;
    bool glDebug = false;
    std::string up;
    std::string grid;
};

// The frame budget of an interactive view unless --frame-budget says otherwise: 15 frames a
// second. A scripted one (--exit-after) keeps --preview-scale, so that its counts are exact.
constexpr double kInteractiveFrameBudgetMs = 66.0;

ScriptedDrag parseDrag(const std::string& text) {
    const size_t colon = text.rfind(':');
    ScriptedDrag d;
    char end = 0;
    if (colon == std::string::npos ||
        std::sscanf(text.c_str() + colon + 1, "%f,%f%c", &d.pixels.x, &d.pixels.y, &end) != 2 ||
        !std::isfinite(d.pixels.x) || !std::isfinite(d.pixels.y))
        throw Error("--drag",
                    "'" + text + "' is not MESH/HANDLE:DX,DY or lights/I:DX,DY (pixels, y down)");
    d.handle = text.substr(0, colon);
    return d;
}

// The viewer renders frames of the same sizes again and again. glibc hands blocks above its mmap
// threshold back to the kernel when they are freed, so each frame's volumes (4 MB a vec4 volume
// at 64³) faulted their pages in again, about 10 µs a 4 KiB page in the VM this was measured in
// (a light drag's photon stage: 102 ms, 86 ms with this; medians of five). With the threshold at
// its largest (32 MB) and no trimming, freed blocks stay in the heap for the next frame; the
// viewer's memory stays at its peak, which every frame reaches anyway.
void keepFreedMemoryForTheNextFrame() {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, INT_MAX);
}

int runView(const ViewOptions& o) {
    if (o.glDebug) setGlDebugRequested(true);
    keepFreedMemoryForTheNextFrame();
    ViewerOptions options;
    options.exitAfter = o.exitAfter;
    options.previewScale = o.previewScale;
    options.frameBudgetMs =
        o.frameBudget >= 0.0 ? o.frameBudget : (o.exitAfter > 0 ? 0.0 : kInteractiveFrameBudgetMs);
    options.play = o.play;
    options.lighterPreviews = o.previewLight == "lighter";
    options.screenshot = o.screenshot;
    options.panelScreenshot = o.panelScreenshot;
    if (!o.drag.empty()) options.drag = parseDrag(o.drag);
    InputChoices choices;
    choices.size = o.size;
    choices.hold = o.hold;
    choices.up = o.up;
    choices.grid = o.grid;
    const SceneInput input = readSceneInput(o.input, choices);
    for (const std::string& note : input.notes) logInfo(note);
    Scene scene = input.scene;
    // Before the window opens, so that a bad scene or --drag fails without a display.
    SceneDriver driver(scene);
    ViewHandles handles(driver, scene);
    const bool lightDrag = options.drag && options.drag->handle.rfind("lights/", 0) == 0;
    if (options.drag && !lightDrag) handles.select(options.drag->handle);
    if (lightDrag) LightGizmos{}.select(options.drag->handle, scene.lights.size());  // checks it
    for (const std::string& edit : o.edits) options.edits.add(scene, edit);
    GlfwWindowContext window(scene.render.width, scene.render.height, "eikon view");
    // "auto": the window's GPU unless it is a software rasterizer (see pipeline/backend_choice.h).
    const bool gpu =
        o.backend == "gpu" || (o.backend == "auto" && !isSoftwareRenderer(window.rendererName()));
    FrameRenderer renderer(scene, gpu ? Backend::Gpu : Backend::Cpu, &window);
    std::printf("%s: %s\n", gpu ? "GPU" : "CPU twin (display on OpenGL)",
                window.rendererName().c_str());
    Viewer viewer(scene, driver, handles, window, renderer, options);
    while (!window.shouldClose()) {
        if (!viewer.input()) break;
        viewer.render();
        if (!viewer.present()) break;
    }
    const std::string method = renderer.lightTransport().name();
    const ViewerState& s = viewer.state();
    std::printf(
        "frames rendered %d, refinements %d, uploads %d, resamples %d, gradients %d, "
        "octrees %d, %s runs %d, lighter previews %d\n",
        s.frames, s.refinements, renderer.uploads(), renderer.resamples(),
        renderer.gradientUpdates(), renderer.octreeUpdates(), method.c_str(),
        renderer.transportRuns(method), renderer.previewTransportRuns());
    // Means, for benchmarks of a scripted orbit (--exit-after).
    if (s.frames > 0) {
        char scales[48];  // the changes' preview sizes: one, or a range under a frame budget
        if (s.finestPreview == s.coarsestPreview)  // 0: no change after the first
            std::snprintf(scales, sizeof(scales), "1/%d",
                          s.finestPreview > 0 ? s.finestPreview : o.previewScale);
        else
            std::snprintf(scales, sizeof(scales), "1/%d to 1/%d", s.finestPreview,
                          s.coarsestPreview);
        std::printf(
            "frame time: first frame %.1f ms, then %.1f ms a frame at %s size, %.1f ms "
            "a refinement\n",
            s.firstMs, s.frames > 1 ? s.framesMs / (s.frames - 1) : 0.0, scales,
            s.refinements > 0 ? s.refinementsMs / s.refinements : 0.0);
    }
    return 0;
}

}  // namespace

void addViewCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand("view", "Show a scene or VDB cache in a window, live");
    addMemoryLimitOption(cmd);
    auto o = std::make_shared<ViewOptions>();
    cmd->add_option("input", o->input,
                    "scene.json, cache.vdb, or a VDB sequence (fluid_data_####.vdb, %04d, $F4)")
        ->required();
    cmd->add_option("--size", o->size, "window size WIDTHxHEIGHT");
    cmd->add_option("--up", o->up, "a VDB input's up axis for the automatic camera: x, y or z")
        ->check(CLI::IsMember({"x", "y", "z"}));
    cmd->add_option("--grid", o->grid,
                    "a VDB input's level set to show as a solid (glass over a floor), by name or "
                    "index");
    cmd->add_flag("--hold", o->hold,
                  "where a VDB sequence lacks a frame, show its nearest frame instead of stopping");
    cmd->add_flag("--gl-debug", o->glDebug,
                  "OpenGL debug output (GL_KHR_debug): driver errors and warnings on stderr");
    cmd->add_option("--backend", o->backend,
                    "auto (GPU unless OpenGL is software), gpu, or cpu (the window still needs "
                    "OpenGL)")
        ->check(CLI::IsMember({"auto", "gpu", "cpu"}));
    cmd->add_option("--exit-after", o->exitAfter,
                    "render this many frames, orbiting 10 degrees each, refine the last to full "
                    "size, then quit (for tests)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--edit", o->edits,
                    "POINTER=V[,V,V]: after the first frame, set a light's, material's or clip "
                    "plane's value (a JSON pointer as keyframe tracks name it, e.g. "
                    "/lights/0/intensity=2), and print the JSON Patch that keeps it; repeatable "
                    "(for tests and scripts)");
    cmd->add_flag("--play", o->play, "start playing the frames (as Space does)");
    cmd->add_option("--preview-scale", o->previewScale,
                    "render a change at 1/N of the size first (shown enlarged), then refine to "
                    "full size while nothing changes: 1, 2, 4 (default), 8 or 16; 1: always full "
                    "size")
        ->check(CLI::IsMember({1, 2, 4, 8, 16}));
    cmd->add_option("--frame-budget", o->frameBudget,
                    "MS: after each change, render the next at the finest of those sizes whose "
                    "picture takes at most MS ms (the viewing pass scaled by the pixel count; "
                    "the rest does not depend on the size), starting from --preview-scale; 0: "
                    "the preview scale stays. Default: 66 (15 frames a second) in a window, 0 "
                    "with --exit-after")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--preview-light", o->previewLight,
                    "lighter (default): a preview that must trace the light again (a light, a "
                    "material or the frame changed) traces it with the method's lighter settings "
                    "(photons: half the photons per side; wavefront: patches split at twice the "
                    "width), and the refinement to full size traces it as set; full: previews "
                    "trace it as set")
        ->check(CLI::IsMember({"lighter", "full"}));
    cmd->add_option("--screenshot", o->screenshot,
                    "with --exit-after: save the last frame here (the picture alone)");
    cmd->add_option("--panel-screenshot", o->panelScreenshot,
                    "with --exit-after: save the window with the panel over the last frame here");
    cmd->add_option("--drag", o->drag,
                    "MESH/HANDLE:DX,DY or lights/I:DX,DY: after the first frame, drag that ARAP "
                    "handle or light's gizmo by DX,DY pixels (y down) as a right drag would, and "
                    "print where it went (for tests)");
    cmd->footer(
        "Examples (from the repository root; a display, or xvfb-run -a):\n  eikon view "
        "data/scenes/glass_sphere_fog.json\n  eikon view ../shared/data/vdb/houdini_smoke1.vdb "
        "--size 800x600\n");
    cmd->callback([o, &exitCode] { exitCode = runView(*o); });
}

}  // namespace eikon::app
