#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "apps/backend_choice.h"
#include "apps/commands.h"
#include "apps/frame_files.h"
#include "apps/memory_limit_option.h"
#include "apps/scene_driver.h"
#include "apps/scene_input.h"
#include "core/error.h"
#include "core/scene.h"
#include "render/frame_renderer.h"
#include "render/gl_context.h"
#include "render/gpu_timer.h"
#include "render/light_transport_registry.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

struct RenderOptions {
    std::string input;
    std::string outputDir;
    std::string frames;
    std::string size;
    bool stats = false;
    std::string backend = "auto";
    bool exr = false;
    std::string shadows;
    float step = 0.0f;
    float shadowStep = 0.0f;
};

// The command line's choices on top of the scene as written; the frames --frames lists (empty:
// the scene's frame_start to frame_end).
std::vector<int> applyOptions(const RenderOptions& o, Scene& scene) {
    std::vector<int> listed;
    if (!o.frames.empty()) listed = parseFrames(o.frames, scene.time);
    if (o.exr) scene.output.exr = true;
    if (o.step > 0.0f) scene.render.stepVoxels = o.step;
    // Settings of the light_volumes method (render.light_transport.light_volumes): they change
    // nothing where the scene's method is another.
    if (o.shadowStep > 0.0f) {
        char step[32];
        std::snprintf(step, sizeof(step), "%.9g", double(o.shadowStep));  // exact for a float
        patchLightTransport(
            scene, std::string("{\"light_volumes\": {\"shadow_step_voxels\": ") + step + "}}");
    }
    if (!o.shadows.empty())
        patchLightTransport(scene, "{\"light_volumes\": {\"shadows\": \"" + o.shadows + "\"}}");
    return listed;
}

void printStats(const std::vector<StageTime>& stages, double writeMs, bool softwareGl) {
    std::printf("  %-10s %10s %10s\n", "stage", "cpu ms", "gpu ms");
    for (const StageTime& s : stages) {
        if (s.gpuMs >= 0)
            std::printf("  %-10s %10.1f %10.1f\n", s.name.c_str(), s.cpuMs, s.gpuMs);
        else
            std::printf("  %-10s %10.1f %10s\n", s.name.c_str(), s.cpuMs, "-");
    }
    std::printf("  %-10s %10.1f %10s\n", "write", writeMs, "-");
    if (softwareGl)
        std::printf(
            "  (a software GL driver does the GPU work inside the GL calls; its timer queries"
            " read ~0, the cpu column is the cost)\n");
}

// The light-transport method's particles traced this frame (photons), their steps and steps per
// second of the stage named after the method's particles (the larger of its GPU and CPU columns:
// hardware GPUs run the trace after the call returns, while llvmpipe runs it inside the GL calls
// and its timer queries read about 0). Nothing when none were traced.
void printTransportStats(const FrameRenderer& renderer, const std::vector<StageTime>& stats,
                         int64_t stepsBefore) {
    const int64_t steps = renderer.transportSteps() - stepsBefore;
    if (steps == 0) return;
    const std::string method = renderer.lightTransport().name();
    double ms = 0.0;
    for (const StageTime& s : stats)
        if (s.name == method) ms += std::max(s.gpuMs, s.cpuMs);
    const TransportStats last = renderer.lastTransportStats();
    std::printf(
        "  %s: %lld traced, %lld steps (%.1f per particle), %.2f M steps/s; %lld cut, %d "
        "rounds\n",
        method.c_str(), static_cast<long long>(last.particlesTraced), static_cast<long long>(steps),
        last.particlesTraced > 0 ? double(steps) / double(last.particlesTraced) : 0.0,
        ms > 0.0 ? double(steps) / (ms * 1e3) : 0.0, static_cast<long long>(last.particlesCut),
        last.rounds);
}

int runRender(const RenderOptions& o) {
    Scene scene = sceneFromInput(o.input, o.outputDir, o.size);
    // Before --frames: a live simulation starts at the frame_start the scene gives, whichever
    // frames are rendered. It reads the mesh files too: a bad one fails before anything else.
    SceneDriver driver(scene);
    const std::vector<int> listed = applyOptions(o, scene);
    std::error_code ec;
    fs::create_directories(scene.output.directory, ec);
    if (ec) throw Error(scene.output.directory, "cannot create the output folder: " + ec.message());
    for (const char* ext : {"png", "exr"}) {
        if (listed.empty())
            removeStalePartials(scene.output.directory, scene.output.name, scene.time.frameStart,
                                scene.time.frameEnd, ext);
        for (int frame : listed)
            removeStalePartials(scene.output.directory, scene.output.name, frame, frame, ext);
    }

    BackendChoice choice = chooseBackend(o.backend);
    FrameRenderer renderer(scene, choice.backend, choice.context.get());
    std::printf("%s\n", choice.description.c_str());
    const bool softwareGl =
        renderer.context() && isSoftwareRenderer(renderer.context()->rendererName());
    int64_t transportSteps = 0;  // before this frame
    const auto renderFrame = [&](int frame) {
        const Image image = renderer.render(driver.frameInputs(frame, scene));
        const auto t0 = std::chrono::steady_clock::now();
        if (scene.output.png) {
            const std::string path =
                framePath(scene.output.directory, scene.output.name, frame, "png");
            writePng(path, image, scene.render.exposure, scene.render.toneCurve);
            std::printf("wrote %s\n", path.c_str());
        }
        if (scene.output.exr) {
            const std::string path =
                framePath(scene.output.directory, scene.output.name, frame, "exr");
            writeExr(path, image);
            std::printf("wrote %s\n", path.c_str());
        }
        const double writeMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        const auto stats = renderer.takeStats();
        if (o.stats) {
            const RenderVolume& v = renderer.volume();
            std::printf("frame %d: %dx%d pixels, volume %dx%dx%d\n", frame, image.width,
                        image.height, v.resolution.x, v.resolution.y, v.resolution.z);
            printStats(stats, writeMs, softwareGl);
            printTransportStats(renderer, stats, transportSteps);
        }
        transportSteps = renderer.transportSteps();
        std::fflush(stdout);
    };
    // A live simulation steps through the frames between those listed (SceneDriver).
    if (listed.empty()) {
        for (int frame = scene.time.frameStart; frame <= scene.time.frameEnd; ++frame)
            renderFrame(frame);
    } else {
        for (int frame : listed) renderFrame(frame);
    }
    return 0;
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand("render", "Render a scene file or a VDB cache to images");
    addMemoryLimitOption(cmd);
    auto o = std::make_shared<RenderOptions>();
    cmd->add_option("input", o->input, "scene.json or cache.vdb")->required();
    cmd->add_option("-o,--output", o->outputDir, "output folder (default: the scene's)");
    cmd->add_option("--frames", o->frames,
                    "frames: 7, 1-10, 1-10x2 (every 2nd) or a comma list (1,3,5-7)");
    cmd->add_option("--size", o->size, "image size WIDTHxHEIGHT");
    cmd->add_flag("--stats", o->stats, "print time per stage (CPU and GPU)");
    cmd->add_option("--backend", o->backend,
                    "auto (GPU unless OpenGL is software or missing), gpu, or cpu (the CPU twin)")
        ->check(CLI::IsMember({"auto", "gpu", "cpu"}));
    cmd->add_flag("--exr", o->exr, "also write linear HDR EXR");
    cmd->add_option("--shadows", o->shadows,
                    "light_volumes method's transmittance: volume, swept or marched")
        ->check(CLI::IsMember({"volume", "swept", "marched"}));
    cmd->add_option("--step", o->step, "view step in voxels (overrides the scene)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--shadow-step", o->shadowStep, "shadow step in voxels (overrides the scene)")
        ->check(CLI::PositiveNumber);
    cmd->callback([o, &exitCode] { exitCode = runRender(*o); });
}

}  // namespace eikon::app
