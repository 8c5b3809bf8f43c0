// `eikon simulate scene.json`: steps the scene's smoke simulation (each of its domains) frame by
// frame and writes each frame as <dir>/<name>_####.vdb (density, temperature, staggered velocity;
// one file per domain, <name> carrying the domain's label), a cache that
// `eikon info` reads and a "vdb_sequence" source renders. Each file is written atomically after
// its frame, so a blow-up keeps every frame before it and leaves no partial file.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "apps/frame_files.h"
#include "apps/memory_limit_option.h"
#include "apps/stats_file.h"
#include "core/cache_run_marker.h"
#include "core/error.h"
#include "core/field_registry.h"
#include "core/log.h"
#include "core/scene.h"
#include "core/vdb_export.h"
#include "render/light_transport_registry.h"
#include "sim/smoke_from_scene.h"
#include "sim/smoke_publish.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

struct SimulateOptions {
    std::string scene;
    std::string outputDir;
    std::string frames;
    bool quiet = false;
    std::string statsJson;  // --stats-json FILE (apps/stats_file.h)
};

// Where a run is: "3/24, about 25 s left" from the frames stepped so far and their time (the
// frames before --frames count, as they take as long to step).
std::string progressText(int done, int total, double elapsedMs) {
    char text[64];
    const double leftSeconds = elapsedMs / done * (total - done) / 1000.0;
    std::snprintf(text, sizeof text, "%d/%d, about %.0f s left", done, total, leftSeconds);
    return text;
}

// One smoke domain being simulated: its solver, where its cache goes, and the mark that says a
// run is writing it (core/cache_run_marker.h).
struct Domain {
    const SmokeSimulationSpec& spec;
    std::string directory;
    sim::SmokeSolver solver;
    std::string markPath;
    std::optional<CacheRunMarker> stopped;  // the mark a run killed midway left, if any
};

// Before this run marks its caches (core/cache_run_marker.h): another run still writing one is
// an error (two runs would interleave their frames); a mark left by a run that stopped midway is
// reported, as this run rewrites the frames it names.
void checkCacheRuns(std::vector<Domain>& domains, const TimeSettings& written) {
    for (Domain& domain : domains) {
        const auto previous = readCacheRunMarker(domain.markPath);
        if (!previous) continue;
        const std::string cache =
            framePath(domain.directory, domain.spec.cacheName, written.frameStart, "vdb");
        if (cacheRunIsAlive(*previous))
            throw Error(cache, "another eikon simulate (pid " + std::to_string(previous->pid) +
                                   ") is writing this cache; wait for it or stop it");
        logInfo(cache + ": " + stoppedRunText(*previous) + "; this run writes frames " +
                std::to_string(written.frameStart) + "-" + std::to_string(written.frameEnd));
        domain.stopped = previous;
    }
}

// After this run wrote every frame: its marks go, unless a stopped run's frames reach past this
// run's last one, which may still mix two runs; the mark then says so from that frame on.
void unmarkCacheRuns(const std::vector<Domain>& domains, const TimeSettings& written) {
    for (const Domain& domain : domains) {
        const std::optional<CacheRunMarker>& stopped = domain.stopped;
        if (stopped && stopped->lastFrame > written.frameEnd)
            writeCacheRunMarker(domain.markPath,
                                thisRunMarker(std::min(stopped->firstFrame, written.frameStart),
                                              stopped->lastFrame, written.frameEnd));
        else
            removeCacheRunMarker(domain.markPath);
    }
}

// Marks every domain's cache: this run has finished the frames through `finishedThrough`.
void markCacheRuns(const std::vector<Domain>& domains, const TimeSettings& written,
                   int finishedThrough) {
    for (const Domain& domain : domains)
        writeCacheRunMarker(domain.markPath,
                            thisRunMarker(written.frameStart, written.frameEnd, finishedThrough));
}

// After a failure at frame lastComplete + 1: that frame (which some domains may have written
// already) and the frames after it, left in the folders by an earlier run, would make a cache
// that mixes two runs; they are removed. Returns what the message adds: which frames are valid.
std::string keepCacheConsistent(const std::vector<Domain>& domains, int lastComplete,
                                const TimeSettings& written) {
    int removed = 0;
    for (const Domain& domain : domains)
        for (int frame = std::max(lastComplete + 1, written.frameStart); frame <= written.frameEnd;
             ++frame) {
            std::error_code ec;
            if (fs::remove(framePath(domain.directory, domain.spec.cacheName, frame, "vdb"), ec))
                ++removed;
        }
    const std::string cache = framePath(domains.front().directory, domains.front().spec.cacheName,
                                        written.frameStart, "vdb");
    std::string note = lastComplete >= written.frameStart
                           ? "frames " + std::to_string(written.frameStart) + "-" +
                                 std::to_string(lastComplete) + " of this run are complete (" +
                                 cache + " on)"
                           : "no frame of this run was written";
    if (removed > 0)
        note += "; removed " + std::to_string(removed) +
                " later frame file(s) of an earlier run, which would have mixed with this run's";
    return note;
}

// Steps `domain` through `frame` and, when `write`, writes the frame's file; returns the frame's
// line (without its progress) and its milliseconds.
std::string stepFrame(Domain& domain, int frame, bool write, double& ms, FrameCounters& counters) {
    const auto t0 = std::chrono::steady_clock::now();
    const sim::SmokeStepStats stats = domain.solver.advanceFrame();
    // A labelled domain's counters carry its label ("cg_iterations/left").
    const std::string suffix = domain.spec.label.empty() ? "" : "/" + domain.spec.label;
    counters["substeps" + suffix] = stats.substeps;
    counters["cg_iterations" + suffix] = stats.cgIterations;
    counters["max_cg_iterations" + suffix] = stats.maxCgIterations;
    counters["cfl" + suffix] = stats.cfl;
    std::string path;
    if (write) {
        path = framePath(domain.directory, domain.spec.cacheName, frame, "vdb");
        // Unlabelled grids: the names other tools (and a "vdb_sequence" source) read.
        FieldRegistry registry;
        sim::publishSmoke(domain.solver.grid(), registry,
                          "simulation frame " + std::to_string(frame));
        exportVdb(path, registry, {field::kDensity, field::kTemperature, field::kVelocity});
    }
    ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    // With conserve_mass, the advection's density deficit the correction put back (relative, the
    // largest of the frame's substeps) and what the bounds left uncorrected.
    char mass[96] = "";
    if (domain.spec.conserveMass)
        std::snprintf(mass, sizeof mass, ", mass deficit %+.2e corrected (left %+.1e)",
                      stats.massDeficit, stats.massRemainder);
    const std::string& label = domain.spec.label;
    char line[512];
    std::snprintf(line, sizeof line,
                  "frame %d%s%s: %d substeps, %d CG iterations, CFL %.2f%s, %.1f ms", frame,
                  label.empty() ? "" : " ", label.c_str(), stats.substeps, stats.cgIterations,
                  stats.cfl, mass, ms);
    return std::string(line) + (write ? " -> " + path : " (before --frames, not written)");
}

int runSimulate(const SimulateOptions& o) {
    const Scene scene = loadScene(o.scene);
    // The whole scene is checked before any work, the render settings the methods read too: a
    // typo there fails now, not after the simulation when the cache is rendered.
    checkLightTransport(scene);
    if (scene.simulations.empty()) {
        throw Error(o.scene,
                    "no \"simulation\" section: nothing to simulate "
                    "(see docs/scene-format.md#simulation)");
    }
    // The simulation starts, empty, at the scene's first frame whatever --frames says, so that a
    // frame holds the same smoke however the run was cut.
    const int first = scene.time.frameStart;
    TimeSettings written = scene.time;
    if (!o.frames.empty()) parseFrameRange(o.frames, written);
    if (written.frameStart < first) {
        throw Error("--frames", "the simulation starts at the scene's frame_start (" +
                                    std::to_string(first) + "); got first frame " +
                                    std::to_string(written.frameStart));
    }

    // Every domain is a solver of its own with a cache of its own (its cacheName carries its
    // label). Keyframed sources move at every substep's time on the scene's clock, the clock
    // `eikon render` evaluates its tracks on, so frame f of the cache is frame f of the render.
    std::vector<Domain> domains;
    for (std::size_t d = 0; d < scene.simulations.size(); ++d) {
        const SmokeSimulationSpec& spec = scene.simulations[d];
        const std::string directory = o.outputDir.empty() ? spec.cacheDirectory : o.outputDir;
        std::error_code ec;
        fs::create_directories(directory, ec);
        if (ec) throw Error(directory, "cannot create the cache folder: " + ec.message());
        removeStalePartials(directory, spec.cacheName, written.frameStart, written.frameEnd, "vdb");
        domains.push_back({spec, directory, sim::smokeSolverFrom(scene, d),
                           cacheRunMarkerPath(directory, spec.cacheName), std::nullopt});
        const glm::ivec3 n = spec.resolution;
        if (!o.quiet)
            std::printf("smoke%s%s %dx%dx%d, voxel %g, %g fps, frames %d-%d -> %s\n",
                        spec.label.empty() ? "" : " ", spec.label.c_str(), n.x, n.y, n.z,
                        double(spec.voxelSize), scene.time.fps, written.frameStart,
                        written.frameEnd,
                        framePath(directory, spec.cacheName, written.frameStart, "vdb").c_str());
    }
    double totalMs = 0.0;
    // Frame f holds the state after f − first + 1 frames of stepping. Every frame up to
    // lastComplete is complete in every domain (written from written.frameStart on).
    int lastComplete = first - 1;
    checkCacheRuns(domains, written);
    try {
        markCacheRuns(domains, written, written.frameStart - 1);
    } catch (const Error&) {  // nothing written yet: the caches stay as they were
        for (const Domain& domain : domains) removeCacheRunMarker(domain.markPath);
        throw;
    }
    try {
        const int total = written.frameEnd - first + 1;
        std::optional<StatsFile> statsFile;
        if (!o.statsJson.empty()) statsFile.emplace(o.statsJson);
        for (int frame = first; frame <= written.frameEnd; ++frame) {
            FrameCounters counters;
            for (Domain& domain : domains) {
                double ms = 0.0;
                const std::string line =
                    stepFrame(domain, frame, frame >= written.frameStart, ms, counters);
                totalMs += ms;
                if (o.quiet) continue;
                std::printf("%s (%s)\n", line.c_str(),
                            progressText(frame - first + 1, total, totalMs).c_str());
                std::fflush(stdout);
            }
            if (statsFile && frame >= written.frameStart) statsFile->record(frame, counters);
            lastComplete = frame;
            if (frame >= written.frameStart) markCacheRuns(domains, written, frame);
        }
    } catch (const Error& e) {
        const std::string valid = keepCacheConsistent(domains, lastComplete, written);
        for (const Domain& domain : domains) removeCacheRunMarker(domain.markPath);
        throw Error(e.where(), e.reason() + "; " + valid);
    }
    unmarkCacheRuns(domains, written);
    const int stepped = written.frameEnd - first + 1;
    if (!o.quiet)
        std::printf("simulated %d frames in %.1f ms (%.1f ms per frame)\n", stepped, totalMs,
                    totalMs / stepped);
    return 0;
}

}  // namespace

void addSimulateCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand(
        "simulate", "Run a scene's smoke simulation and write one VDB file per frame");
    addMemoryLimitOption(cmd);
    auto o = std::make_shared<SimulateOptions>();  // CLI11 binds by reference
    cmd->add_option("scene", o->scene, "scene.json with a \"simulation\" section")->required();
    cmd->add_option("-o,--output", o->outputDir,
                    "cache folder (default: the scene's simulation.cache)");
    cmd->add_option("--frames", o->frames, "frames to write FIRST-LAST, or one frame");
    cmd->add_option("--stats-json", o->statsJson,
                    "write FILE: each written frame's counters as JSON (substeps, CG iterations, "
                    "CFL; no times), for scripts and eikon regress");
    cmd->add_flag("--quiet", o->quiet,
                  "print nothing but errors and warnings: no line per frame (which gives the "
                  "frame's substeps, CG iterations, CFL, time, file, and the frames left)");
    cmd->footer(
        "Examples (from the repository root):\n  eikon simulate data/scenes/smoke_plume.json "
        "--frames 1-24\n  eikon render data/scenes/smoke_plume.json -o out/plume/\n");
    cmd->callback([o, &exitCode] { exitCode = runSimulate(*o); });
}

}  // namespace eikon::app
