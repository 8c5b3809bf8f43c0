#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "apps/frame_files.h"
#include "apps/memory_limit_option.h"
#include "apps/output_files.h"
#include "apps/render_manifest.h"
#include "apps/render_progress.h"
#include "apps/stats_file.h"
#include "core/error.h"
#include "core/frame_chunks.h"
#include "core/frame_list.h"
#include "core/log.h"
#include "core/scene.h"
#include "core/scene_sources.h"
#include "core/sha256.h"
#include "core/vdb_sequence.h"  // describeFrameRanges
#include "pipeline/backend_choice.h"
#include "pipeline/scene_driver.h"
#include "pipeline/scene_input.h"
#include "render/frame_renderer.h"
#include "render/gl_context.h"
#include "render/gpu_timer.h"
#include "render/light_transport_registry.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

struct RenderOptions {
    std::string input;
    std::string output;  // -o: a file, a pattern or a folder (apps/output_files.h)
    std::string frames;
    bool hold = false;
    bool quiet = false;
    std::string up;
    std::string grid;
    std::string size;
    bool stats = false;
    bool glDebug = false;
    std::string statsJson;  // --stats-json FILE (apps/stats_file.h)
    std::string backend = "auto";
    bool exr = false;
    std::string shadows;
    float step = 0.0f;
    float shadowStep = 0.0f;
    std::string chunk;     // --chunk K/N | auto (core/frame_chunks.h)
    std::string manifest;  // --manifest FILE (apps/render_manifest.h)
    bool resume = false;
    bool fromCache = false;
};

// What makes this render's pictures what they are, for its manifest: the binary, the input, the
// options that change pixels (in a fixed order, the backend as chosen) and the frames asked for.
// Not --from-cache, which gives the same pixels as stepping live (so a farm's manifest, rendered
// from the cache, equals a workstation's live one), nor --chunk or -o.
RenderIdentity identityOf(const RenderOptions& o, const Scene& scene, const BackendChoice& choice,
                          const std::vector<int>& frames) {
    RenderIdentity id;
    id.build = sha256OfFile("/proc/self/exe");
    std::error_code ec;
    id.input = fs::is_regular_file(o.input, ec) ? sha256OfFile(o.input) : "pattern " + o.input;
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, "size=%dx%d step=%.9g shadow_step=%.9g",
                  scene.render.width, scene.render.height, double(o.step), double(o.shadowStep));
    id.settings = std::string(numbers) + " shadows=" + o.shadows +
                  " exr=" + (scene.output.exr ? "1" : "0") + " hold=" + (o.hold ? "1" : "0") +
                  " up=" + o.up + " grid=" + o.grid + " backend=" +
                  (choice.backend == Backend::Cpu ? std::string("cpu")
                                                  : "gpu " + choice.context->rendererName());
    id.frames = describeFrameRanges(frames);
    return id;
}

// The frames a render without --frames writes: the scene's frame_start to frame_end.
std::vector<int> sceneFrames(const TimeSettings& time) {
    if (int64_t(time.frameEnd) - time.frameStart >= kMaxListedFrames)
        throw Error("time", "the scene spans " +
                                std::to_string(int64_t(time.frameEnd) - time.frameStart + 1) +
                                " frames; eikon render writes at most " +
                                std::to_string(kMaxListedFrames) +
                                " at once: pick them with --frames");
    std::vector<int> frames;
    for (int64_t f = time.frameStart; f <= time.frameEnd; ++f) frames.push_back(int(f));
    return frames;
}

// The command line's choices on top of the scene as written; the frames to render (--frames, or
// the scene's).
std::vector<int> applyOptions(const RenderOptions& o, Scene& scene) {
    const std::vector<int> listed =
        o.frames.empty() ? sceneFrames(scene.time) : parseFrames(o.frames, scene.time);
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

// Energy figures are reported summed over the colour channels.
double channelSum(glm::dvec3 v) {
    return v.x + v.y + v.z;
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
    // Rounds are the photon march's and the wavefront's (between them the lists are compacted);
    // a method without them prints none.
    const std::string rounds =
        last.rounds > 0 ? ", " + std::to_string(last.rounds) + " rounds" : "";
    std::printf("  %s: %lld traced, %lld steps (%.1f per particle), %.2f M steps/s; %lld cut%s\n",
                method.c_str(), static_cast<long long>(last.particlesTraced),
                static_cast<long long>(steps),
                last.particlesTraced > 0 ? double(steps) / double(last.particlesTraced) : 0.0,
                ms > 0.0 ? double(steps) / (ms * 1e3) : 0.0,
                static_cast<long long>(last.particlesCut), rounds.c_str());
    if (last.particlesSplit > 0 || last.splitsRefused > 0 || last.particlesTorn > 0 ||
        last.particlesRemoved > 0)
        std::printf(
            "  %s: %lld split, %lld refused a split (patch budget), %lld torn, %lld removed "
            "at caustics\n",
            method.c_str(), static_cast<long long>(last.particlesSplit),
            static_cast<long long>(last.splitsRefused), static_cast<long long>(last.particlesTorn),
            static_cast<long long>(last.particlesRemoved));
    if (last.viewSteps > 0)
        std::printf("  %s: interleaved view, %lld view ray steps; %lld samples behind the sweep\n",
                    method.c_str(), static_cast<long long>(last.viewSteps),
                    static_cast<long long>(last.viewSamplesBehind));
    if (const std::optional<EnergyBalance> e = renderer.lightTransport().energy()) {
        // Shares of the power that entered the volume.
        const double in = std::max(channelSum(e->emitted), 1e-300);
        auto share = [&](const glm::dvec3& part) { return channelSum(part) / in; };
        std::printf(
            "  %s energy: emitted %.6g; extinguished %.4f, escaped %.4f, received %.4f, "
            "reflected at surfaces %.4f, dropped %.4f (removed at caustics %.4f); unaccounted "
            "%.2e\n",
            method.c_str(), channelSum(e->emitted), share(e->extinguished), share(e->escaped),
            share(e->received), share(e->reflected), share(e->dropped), share(e->removed),
            share(e->emitted - e->accounted()));
    }
}

// The frame's counters for --stats-json: what the light-transport method traced (nothing when it
// reused its light), the picture's and the volume's size.
FrameCounters frameCounters(const FrameRenderer& renderer, int64_t stepsBefore) {
    const TransportStats last = renderer.lastTransportStats();
    const int64_t steps = renderer.transportSteps() - stepsBefore;
    const RenderVolume& v = renderer.volume();
    FrameCounters c{{"width", renderer.scene().render.width},
                    {"height", renderer.scene().render.height},
                    {"volume_voxels", double(v.resolution.x) * v.resolution.y * v.resolution.z}};
    if (steps > 0) {
        c["particles_traced"] = double(last.particlesTraced);
        c["particle_steps"] = double(steps);
        c["particles_cut"] = double(last.particlesCut);
        c["transport_rounds"] = last.rounds;
        if (last.particlesSplit > 0 || last.splitsRefused > 0 || last.particlesTorn > 0 ||
            last.particlesRemoved > 0) {
            c["particles_split"] = double(last.particlesSplit);
            c["splits_refused"] = double(last.splitsRefused);
            c["particles_torn"] = double(last.particlesTorn);
            c["particles_removed"] = double(last.particlesRemoved);
        }
        if (last.viewSteps > 0) {
            c["view_steps"] = double(last.viewSteps);
            c["view_samples_behind"] = double(last.viewSamplesBehind);
        }
        if (const std::optional<EnergyBalance> e = renderer.lightTransport().energy()) {
            c["energy_emitted"] = channelSum(e->emitted);
            c["energy_extinguished"] = channelSum(e->extinguished);
            c["energy_escaped"] = channelSum(e->escaped);
            c["energy_received"] = channelSum(e->received);
            c["energy_reflected"] = channelSum(e->reflected);
            c["energy_dropped"] = channelSum(e->dropped);
            c["energy_removed"] = channelSum(e->removed);
        }
    }
    return c;
}

// --resume: of `frames`, those not yet written by this render. A frame whose files the manifest
// vouches for is kept; a file at a frame's name that is not one of them is named, and the frame
// rendered again.
std::vector<int> framesLeftToRender(const RenderManifest& manifest, const OutputFiles& files,
                                    const std::vector<int>& frames, bool quiet) {
    std::vector<int> left;
    for (int frame : frames) {
        const std::vector<std::string> paths = files.paths({frame});
        const std::string why = manifest.whyNotKept(frame, paths);
        if (why.empty()) {
            if (!quiet) logInfo("kept frame " + std::to_string(frame) + " (--resume)");
            continue;
        }
        std::error_code ec;
        for (const std::string& path : paths)
            if (fs::exists(path, ec)) {
                logWarning(why + "; rendering it again");
                break;
            }
        left.push_back(frame);
    }
    return left;
}

int runRender(const RenderOptions& o) {
    InputChoices choices;
    choices.size = o.size;
    choices.framesGiven = !o.frames.empty();
    choices.hold = o.hold;
    choices.up = o.up;
    choices.grid = o.grid;
    SceneInput input = readSceneInput(o.input, choices);
    Scene& scene = input.scene;
    // Before --frames: a live simulation starts at the frame_start the scene gives, whichever
    // frames are rendered. It reads the mesh files too: a bad one fails before anything else.
    if (o.fromCache && scene.simulations.empty())
        throw Error("--from-cache", o.input + " has no \"simulation\": there is no cache to read");
    if (o.resume && o.manifest.empty())
        throw Error("--resume",
                    "needs --manifest FILE: the record of the frames written, which "
                    "tells a finished frame from a file that only has its name");
    SceneDriver driver(scene, o.fromCache);
    const std::vector<int> allFrames = applyOptions(o, scene);
    // Every check before the first file: a bad range, chunk or -o writes nothing.
    checkSequenceFrames(scene, allFrames);
    const OutputFiles files = resolveOutputFiles(o.output, scene.output, allFrames, input.oneFrame);
    std::vector<int> frames = allFrames;
    if (!o.chunk.empty()) {
        const FrameChunk chunk =
            parseFrameChunk(o.chunk, [](const char* n) { return std::getenv(n); });
        frames = framesOfChunk(allFrames, chunk);
        if (!o.quiet) logInfo(describeChunk(allFrames, chunk));
    }
    if (!o.quiet)
        for (const std::string& note : input.notes) logInfo(note);
    std::error_code ec;
    fs::create_directories(files.directory, ec);
    if (ec) throw Error(files.directory, "cannot create the output folder: " + ec.message());
    removeStalePartials(files.paths(frames));

    if (o.glDebug) setGlDebugRequested(true);
    BackendChoice choice = chooseBackend(o.backend);
    std::optional<RenderManifest> manifest;
    if (!o.manifest.empty()) {
        manifest.emplace(o.manifest, identityOf(o, scene, choice, allFrames));
        if (o.resume && !manifest->previousIgnored().empty())
            logWarning(manifest->previousIgnored());
        manifest->save();
    }
    if (o.resume) frames = framesLeftToRender(*manifest, files, frames, o.quiet);
    FrameRenderer renderer(scene, choice.backend, choice.context.get());
    if (!o.quiet) std::printf("%s\n", choice.description.c_str());
    std::fflush(stdout);  // before the progress on stderr
    RenderProgress progress(frames.size(), o.quiet, isatty(STDERR_FILENO) != 0);
    renderer.setStageListener([&progress](const std::string& stage) { progress.stage(stage); });
    const bool softwareGl =
        renderer.context() && isSoftwareRenderer(renderer.context()->rendererName());
    int64_t transportSteps = 0;  // before this frame
    std::optional<StatsFile> statsFile;
    if (!o.statsJson.empty()) statsFile.emplace(o.statsJson);
    const auto renderFrame = [&](size_t index, int frame) {
        progress.startFrame(index, frame);
        const Image image = renderer.render(driver.frameInputs(frame, scene));
        progress.pictureDone();
        const auto t0 = std::chrono::steady_clock::now();
        if (files.png) {
            const std::string path = files.path(frame, "png");
            writePng(path, image, scene.render.exposure, scene.render.toneCurve);
            if (!o.quiet) std::printf("wrote %s\n", path.c_str());
        }
        if (files.exr) {
            const std::string path = files.path(frame, "exr");
            writeExr(path, image);
            if (!o.quiet) std::printf("wrote %s\n", path.c_str());
        }
        if (manifest) manifest->record(frame, files.paths({frame}));
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
        if (statsFile) statsFile->record(frame, frameCounters(renderer, transportSteps));
        transportSteps = renderer.transportSteps();
        std::fflush(stdout);
        progress.endFrame();
    };
    // A live simulation steps through the frames between those listed (SceneDriver).
    for (size_t i = 0; i < frames.size(); ++i) renderFrame(i, frames[i]);
    return 0;
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand("render", "Render a scene file or a VDB cache to images");
    addMemoryLimitOption(cmd);
    auto o = std::make_shared<RenderOptions>();
    cmd->add_option("input", o->input,
                    "scene.json, cache.vdb, or a VDB sequence (fluid_data_####.vdb, %04d, $F4)")
        ->required();
    cmd->add_option("-o,--output", o->output,
                    "still.png or still.exr (one frame), shot_####.png (one file per frame), or a "
                    "folder (ending in / or existing; default: the scene's)");
    cmd->add_option("--frames", o->frames,
                    "frames: 7, 1-10, 1-10x2 (every 2nd) or a comma list (1,3,5-7); on a "
                    "numbered VDB file (fluid_data_0001.vdb), frames of its sequence");
    cmd->add_flag("--hold", o->hold,
                  "where a VDB sequence lacks a frame (a gap, or before its first or after its "
                  "last), show its nearest frame instead of stopping with an error");
    cmd->add_option("--size", o->size, "image size WIDTHxHEIGHT");
    cmd->add_option("--up", o->up,
                    "a VDB input's up axis for the automatic camera: x, y or z (default: the "
                    "file's metadata or writer, else the sequence's motion, else y)")
        ->check(CLI::IsMember({"x", "y", "z"}));
    cmd->add_option("--grid", o->grid,
                    "a VDB input's level set to render as a solid (glass over a floor), by name "
                    "or index (default: the density; without one, the file's level set)");
    cmd->add_flag("--stats", o->stats, "print time per stage (CPU and GPU)");
    cmd->add_option("--stats-json", o->statsJson,
                    "write FILE: each frame's counters as JSON (particles traced and their "
                    "steps, sizes; no times), for scripts and eikon regress");
    cmd->add_flag("--quiet", o->quiet,
                  "print nothing but errors, warnings and --stats: no 'wrote' lines, no progress "
                  "(which is a line per frame on stderr, and a status line on a terminal)");
    cmd->add_option("--backend", o->backend,
                    "auto (GPU unless OpenGL is software or missing), gpu, or cpu (the CPU twin)")
        ->check(CLI::IsMember({"auto", "gpu", "cpu"}));
    cmd->add_flag("--exr", o->exr, "also write linear HDR EXR");
    cmd->add_flag("--gl-debug", o->glDebug,
                  "OpenGL debug output (GL_KHR_debug): every driver error, warning and "
                  "performance hint as a warning on stderr (also EIKON_GL_DEBUG=1)");
    cmd->add_option("--shadows", o->shadows,
                    "light_volumes method's transmittance: volume, swept or marched")
        ->check(CLI::IsMember({"volume", "swept", "marched"}));
    cmd->add_option("--step", o->step, "view step in voxels (overrides the scene)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--shadow-step", o->shadowStep, "shadow step in voxels (overrides the scene)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--chunk", o->chunk,
                    "render only chunk K/N of the frames (contiguous, sizes within one), or "
                    "auto: K and N from a Slurm job array (SLURM_ARRAY_TASK_ID, _COUNT, _MIN, "
                    "_STEP)");
    cmd->add_option("--manifest", o->manifest,
                    "write FILE: the render's identity (binary, input, settings, frames) and "
                    "each frame's files with their SHA-256; rewritten after every frame");
    cmd->add_flag("--resume", o->resume,
                  "keep the frames --manifest records as written with the bytes they have; "
                  "render the rest, and files from another render or changed since (warned)");
    cmd->add_flag("--from-cache", o->fromCache,
                  "a scene's live simulation (source \"simulation\") reads the frames eikon "
                  "simulate wrote to its simulation.cache instead of stepping: the same pictures, "
                  "any frame without the ones before");
    cmd->footer(
        "Examples (from the repository root):\n  eikon render data/scenes/glass_sphere_fog.json -o "
        "out/ --size 320x240\n  eikon render ../shared/data/vdb/houdini_smoke1.vdb -o "
        "out/smoke.png\n  "
        "eikon render '../shared/data/vdb/blender_smoke_c42/fluid_data_####.vdb' -o "
        "'out/shots/shot_####.png' --hold\n  eikon render "
        "../shared/data/vdb/blender_smoke_c42/fluid_data_0001.vdb --frames 1-2 -o out/\n");
    cmd->callback([o, &exitCode] { exitCode = runRender(*o); });
}

}  // namespace eikon::app
