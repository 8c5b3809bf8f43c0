// `eikon bench smoke scene.json`: the smoke solver's cost per step, split into advection, forces
// (sources included) and projection, with the pressure solve's iterations and residual, at
// several resolutions of the scene's simulation. data/scenes/smoke_blender_peer.json is the
// set-up of Blender's Mantaflow peer (../shared/peers/blender_smoke_peer.py);
// scripts/bench-smoke.sh runs both. Timings belong in a benchmark program, never in a unit test.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "apps/bench_report.h"
#include "apps/commands.h"
#include "apps/frame_files.h"
#include "core/error.h"
#include "core/field_registry.h"
#include "core/scene.h"
#include "core/vdb_export.h"
#include "sim/smoke_from_scene.h"
#include "sim/smoke_publish.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

struct BenchSmokeOptions {
    std::string scene;
    std::string sizes = "32,64,128";
    std::string frames = "20,20,10";  // what the Blender peer runs
    std::string steps = "adaptive";
    int threads = 0;
    bool quick = false;
    std::string cacheDir;
    std::string tsv;
};

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

const char* wallName(SimWall w) {
    return w == SimWall::Open ? "open" : "closed";
}

const char* advectionName(SimAdvection a) {
    switch (a) {
        case SimAdvection::SemiLagrangian:
            return "semi_lagrangian";
        case SimAdvection::MacCormack:
            return "maccormack";
        case SimAdvection::Bfecc:
            return "bfecc";
    }
    return "?";
}

const char* limiterName(SimLimiter l) {
    switch (l) {
        case SimLimiter::None:
            return "none";
        case SimLimiter::Clamp:
            return "clamp";
        case SimLimiter::Revert:
            return "revert";
    }
    return "?";
}

std::string shapeText(const SimShapeSpec& s) {
    char buf[160];
    if (s.kind == SimShapeSpec::Kind::Sphere)
        std::snprintf(buf, sizeof buf, "sphere r %g at (%g, %g, %g)", double(s.radius),
                      double(s.center.x), double(s.center.y), double(s.center.z));
    else
        std::snprintf(buf, sizeof buf, "box (%g, %g, %g)-(%g, %g, %g)", double(s.boxMin.x),
                      double(s.boxMin.y), double(s.boxMin.z), double(s.boxMax.x),
                      double(s.boxMax.y), double(s.boxMax.z));
    return buf;
}

// The scene's simulation at `n` cells along the domain's longest axis (cubic cells, the other
// axes rounded), as "resolution": n in the scene would give.
SmokeSimulationSpec atResolution(SmokeSimulationSpec spec, int n) {
    const glm::vec3 extent = spec.domain.max - spec.domain.min;
    const float longest = std::max({extent.x, extent.y, extent.z});
    spec.voxelSize = longest / float(n);
    for (int a = 0; a < 3; ++a)
        spec.resolution[a] = std::max(1, int(std::lround(extent[a] / spec.voxelSize)));
    spec.domain.max = spec.domain.min + glm::vec3(spec.resolution) * spec.voxelSize;
    return spec;
}

void printSettings(const Scene& scene, const SmokeSimulationSpec& s, const BenchSmokeOptions& o) {
    std::printf("# scene: %s\n", scene.path.c_str());
    std::printf(
        "# domain: (%g, %g, %g)-(%g, %g, %g) scene units; walls -x %s +x %s -y %s +y %s "
        "-z %s +z %s\n",
        double(s.domain.min.x), double(s.domain.min.y), double(s.domain.min.z),
        double(s.domain.max.x), double(s.domain.max.y), double(s.domain.max.z),
        wallName(s.walls[0]), wallName(s.walls[1]), wallName(s.walls[2]), wallName(s.walls[3]),
        wallName(s.walls[4]), wallName(s.walls[5]));
    if (o.steps == "fixed1")
        std::printf(
            "# time: %g fps, one step per frame (--steps fixed1; the scene's cfl %g "
            "ignored)\n",
            scene.time.fps, s.cfl);
    else
        std::printf("# time: %g fps, substeps per frame from cfl %g (at most %d)\n", scene.time.fps,
                    s.cfl, s.maxSubsteps);
    std::printf("# advection: %s + %s limiter (density, temperature and velocity)\n",
                advectionName(s.advection), limiterName(s.limiter));
    std::printf(
        "# forces: buoyancy alpha %g, beta %g, ambient %g; vorticity %g; wind (%g, %g, "
        "%g)\n",
        double(s.buoyancyAlpha), double(s.buoyancyBeta), double(s.ambientTemperature),
        double(s.vorticity), double(s.wind.x), double(s.wind.y), double(s.wind.z));
    std::printf("# pressure: %s, relative max-norm tolerance %g, at most %d iterations\n",
                s.pressurePreconditioner == SimPreconditioner::Mic0 ? "MIC(0)-PCG" : "MG-PCG",
                s.pressureTolerance, s.pressureMaxIterations);
    for (const SmokeSourceSpec& src : s.sources)
        std::printf(
            "# source: %s, density %g/s, temperature %g/s, velocity (%g, %g, %g) at "
            "rate %g/s\n",
            shapeText(src.shape).c_str(), double(src.densityRate), double(src.temperatureRate),
            double(src.velocity.x), double(src.velocity.y), double(src.velocity.z),
            double(src.velocityRate));
    for (const SimShapeSpec& obstacle : s.obstacles)
        std::printf("# obstacle: %s\n", shapeText(obstacle).c_str());
    std::printf(
        "# ms per step are means over every step of every frame, frame 1 included; the "
        "other column is the rest of a frame (NaN checks, CFL)%s\n",
        o.cacheDir.empty() ? "" : ", write is publishing and writing one VDB per frame");
}

struct SizeResult {
    glm::ivec3 resolution{0};
    int frames = 0;
    sim::SmokeStepStats stats;
    std::vector<double> frameMs;  // solver only, per frame
    double writeMs = 0.0;         // all frames
    glm::ivec3 densityLo{0}, densityHi{-1};
};

// Cells holding any smoke (density > 1e-6, the clipping Blender's VDB cache applies).
void densityBox(const sim::MacGrid& g, SizeResult& r) {
    const glm::ivec3 n = g.resolution();
    glm::ivec3 lo = n, hi(-1);
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i)
                if (g.density(i, j, k) > 1e-6f) {
                    lo = glm::min(lo, glm::ivec3(i, j, k));
                    hi = glm::max(hi, glm::ivec3(i, j, k));
                }
    r.densityLo = lo;
    r.densityHi = hi;
}

SizeResult runSize(const Scene& scene, const SmokeSimulationSpec& spec, int frames,
                   const BenchSmokeOptions& o) {
    SizeResult r;
    r.resolution = spec.resolution;
    r.frames = frames;
    sim::SmokeSolver solver = sim::smokeSolverFrom(spec, scene.time.fps);
    FieldRegistry registry;
    const std::vector<std::string> fields = {field::kDensity, field::kTemperature,
                                             field::kVelocity};
    std::string dir;
    if (!o.cacheDir.empty()) {
        dir = (fs::path(o.cacheDir) / ("res" + std::to_string(spec.resolution.x))).string();
        fs::create_directories(dir);
    }
    for (int f = 1; f <= frames; ++f) {
        const Clock::time_point t0 = Clock::now();
        r.stats.add(solver.advanceFrame());
        r.frameMs.push_back(msSince(t0));
        if (!dir.empty()) {
            const Clock::time_point t1 = Clock::now();
            sim::publishSmoke(solver.grid(), registry, "bench frame " + std::to_string(f));
            exportVdb(framePath(dir, "smoke", f, "vdb"), registry, fields);
            r.writeMs += msSince(t1);
        }
    }
    densityBox(solver.grid(), r);
    return r;
}

int runBenchSmoke(BenchSmokeOptions o) {
    if (o.quick) {
        o.sizes = "16";
        o.frames = "3";
    }
    if (o.steps != "adaptive" && o.steps != "fixed1")
        throw Error("--steps", "expected adaptive or fixed1, got '" + o.steps + "'");
    const std::vector<int> sizes = parseSizeList(o.sizes, "--sizes");
    std::vector<int> frames = parseSizeList(o.frames, "--frames");
    if (frames.size() == 1) frames.resize(sizes.size(), frames[0]);
    if (frames.size() != sizes.size())
        throw Error("--frames",
                    "give one frame count, or one per size (" + std::to_string(sizes.size()) + ")");

    const Scene scene = loadScene(o.scene);
    if (scene.simulations.empty())
        throw Error(o.scene, "no \"simulation\" section: nothing to benchmark");
    // A scene of several domains: the first is timed (each domain is a solver of its own).
    SmokeSimulationSpec base = scene.simulations.front();
    if (o.steps == "fixed1") base.cfl = 1e9;  // one substep whatever the speed

    const auto threadCap = limitThreads(o.threads);
    std::printf("# eikon bench smoke: ms per solver step by stage\n");
    printBenchHeader(stdout, o.threads);
    printSettings(scene, scene.simulations.front(), o);
    if (scene.simulations.size() > 1)
        std::printf("# the scene has %zu smoke domains; this times the first, '%s'\n",
                    scene.simulations.size(), scene.simulations.front().label.c_str());
    std::fflush(stdout);

    std::unique_ptr<std::ofstream> tsv;
    if (!o.tsv.empty()) {
        if (fs::path(o.tsv).has_parent_path())
            fs::create_directories(fs::path(o.tsv).parent_path());
        tsv = std::make_unique<std::ofstream>(o.tsv);
        if (!*tsv) throw Error(o.tsv, "cannot write the TSV file");
        *tsv << "resolution\tframes\tsteps\tadvection_ms_per_step\tforces_ms_per_step\t"
                "projection_ms_per_step\tother_ms_per_step\ttotal_ms_per_step\tcg_iterations_mean\t"
                "cg_iterations_max\tcg_residual_max\tms_per_frame_mean\t"
                "ms_per_frame_median_excl_f1\twrite_ms_per_frame\n";
    }

    std::printf("%-11s %6s %5s %6s | %9s %9s %9s %9s %9s | %7s %6s %9s | %9s %9s %9s | %s\n",
                "resolution", "frames", "steps", "st/fr", "advect", "forces", "project", "other",
                "total", "CG mean", "CG max", "residual", "frame", "fr med>1", "write",
                "smoke cells (bbox)");
    std::printf("%-11s %6s %5s %6s | %9s %9s %9s %9s %9s | %7s %6s %9s | %9s %9s %9s |\n", "", "",
                "", "", "ms/step", "ms/step", "ms/step", "ms/step", "ms/step", "it/step", "it",
                "max", "ms mean", "ms", "ms/frame");
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        const SmokeSimulationSpec spec = atResolution(base, sizes[i]);
        const SizeResult r = runSize(scene, spec, frames[i], o);
        const sim::SmokeStepStats& s = r.stats;
        const double steps = std::max(1, s.substeps);
        double frameTotal = 0.0;
        for (double ms : r.frameMs) frameTotal += ms;
        const double stages = s.advectionMs + s.forcesMs + s.projectionMs;
        const std::vector<double> later(r.frameMs.begin() + (r.frameMs.size() > 1 ? 1 : 0),
                                        r.frameMs.end());
        char res[32], box[64];
        std::snprintf(res, sizeof res, "%dx%dx%d", r.resolution.x, r.resolution.y, r.resolution.z);
        if (r.densityHi.x >= 0)
            std::snprintf(box, sizeof box, "%dx%dx%d, top y %d", r.densityHi.x - r.densityLo.x + 1,
                          r.densityHi.y - r.densityLo.y + 1, r.densityHi.z - r.densityLo.z + 1,
                          r.densityHi.y);
        else
            std::snprintf(box, sizeof box, "none");
        const double writePerFrame = r.writeMs / r.frames;
        char write[32] = "-";
        if (!o.cacheDir.empty()) std::snprintf(write, sizeof write, "%.1f", writePerFrame);
        std::printf(
            "%-11s %6d %5d %6.2f | %9.2f %9.2f %9.2f %9.2f %9.2f | %7.1f %6d %9.2e | %9.1f %9.1f "
            "%9s | %s\n",
            res, r.frames, s.substeps, s.substeps / double(r.frames), s.advectionMs / steps,
            s.forcesMs / steps, s.projectionMs / steps, (frameTotal - stages) / steps,
            frameTotal / steps, s.cgIterations / steps, s.maxCgIterations, s.cgResidual,
            frameTotal / r.frames, median(later), write, box);
        std::fflush(stdout);
        if (tsv)
            *tsv << res << '\t' << r.frames << '\t' << s.substeps << '\t' << s.advectionMs / steps
                 << '\t' << s.forcesMs / steps << '\t' << s.projectionMs / steps << '\t'
                 << (frameTotal - stages) / steps << '\t' << frameTotal / steps << '\t'
                 << s.cgIterations / steps << '\t' << s.maxCgIterations << '\t' << s.cgResidual
                 << '\t' << frameTotal / r.frames << '\t' << median(later) << '\t'
                 << (o.cacheDir.empty() ? 0.0 : writePerFrame) << '\n';
    }
    if (tsv) std::printf("# wrote %s\n", o.tsv.c_str());
    return 0;
}

}  // namespace

void addBenchSmokeCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "smoke", "Time the smoke solver per step (advection, forces, projection) at several sizes");
    auto o = std::make_shared<BenchSmokeOptions>();
    cmd->add_option("scene", o->scene,
                    "scene.json with a \"simulation\" section (the Blender peer's set-up: "
                    "data/scenes/smoke_blender_peer.json)")
        ->required();
    cmd->add_option("--sizes", o->sizes,
                    "cells along the domain's longest axis, comma-separated (default 32,64,128)");
    cmd->add_option("--frames", o->frames,
                    "frames per size, one number or one per size (default 20,20,10)");
    cmd->add_option("--steps", o->steps,
                    "adaptive: substeps from the scene's cfl (Blender's default); fixed1: one "
                    "step per frame (the peer's STEPS=fixed1)");
    cmd->add_option("--threads", o->threads, "cap TBB's threads (default: all cores)");
    cmd->add_flag("--quick", o->quick, "smallest run, to check that it works: 16³, 3 frames");
    cmd->add_option("--cache", o->cacheDir,
                    "also publish and write one VDB per frame under DIR/res<N>/ (the peer writes "
                    "its cache every frame), timed apart");
    cmd->add_option("--tsv", o->tsv, "also write the table as TSV to FILE");
    cmd->callback([o, &exitCode] { exitCode = runBenchSmoke(*o); });
}

}  // namespace eikon::app
