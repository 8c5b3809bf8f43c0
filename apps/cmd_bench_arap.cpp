// `eikon bench arap`: milliseconds per frame of as-rigid-as-possible handle editing (the
// interactive use of Sorkine & Alexa 2007: a handle is dragged, each frame runs a few
// local/global iterations warm-started from the last frame, the factorization is reused).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "apps/bench_report.h"
#include "apps/commands.h"
#include "core/error.h"
#include "core/mesh_primitives.h"
#include "sim/arap_deformer.h"

namespace eikon::app {
namespace {

struct BenchArapOptions {
    std::string vertices = "5000,20000";
    int frames = 20;
    int iterations = 5;
    int threads = 0;
    bool quick = false;
};

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

// The bar of the tests (radius 0.5, length 5) with about `vertices` vertices, spaced about
// evenly along and around.
struct Bar {
    std::uint32_t around, segments;
    TriangleMesh mesh;
};

Bar barWithVertices(int vertices) {
    const double circumferenceOverLength = 2.0 * 3.14159265358979 * 0.5 / 5.0;
    Bar b;
    b.around =
        std::max(3u, std::uint32_t(std::lround(std::sqrt(vertices * circumferenceOverLength))));
    b.segments = std::max(1u, std::uint32_t(std::lround(double(vertices) / b.around)) - 1);
    b.mesh = makeCylinder(0.5f, 5.0f, b.around, b.segments);
    return b;
}

int runBenchArap(BenchArapOptions o) {
    if (o.quick) {
        o.vertices = "500";
        o.frames = 3;
    }
    if (o.frames < 1) throw Error("--frames", "must be at least 1");
    if (o.iterations < 1) throw Error("--iterations", "must be at least 1");
    const std::vector<int> sizes = parseSizeList(o.vertices, "--vertices");
    const auto threadCap = limitThreads(o.threads);

    std::printf("# eikon bench arap: ms per frame of as-rigid-as-possible handle editing\n");
    printBenchHeader(stdout, o.threads);
    std::printf(
        "# mesh: closed cylinder radius 0.5, length 5 (makeCylinder); handles: the two end "
        "rings at each end, one end held, the other lifted 1.5 along y over the frames\n");
    std::printf(
        "# a frame: move the handles, then %d local/global iterations warm-started from "
        "the last frame; setup = cotangent weights, factor = sparse LDLT (once per handle "
        "set)\n",
        o.iterations);
    std::printf("%8s %9s %7s | %9s %9s | %6s %9s %9s %9s | %10s\n", "vertices", "triangles",
                "handles", "setup ms", "factor ms", "frames", "ms/frame", "min ms", "ms/iter",
                "energy");
    for (int target : sizes) {
        const Bar bar = barWithVertices(target);
        std::vector<std::uint32_t> handles = cylinderRings(bar.around, bar.segments, 0, 1);
        const std::vector<std::uint32_t> lifted =
            cylinderRings(bar.around, bar.segments, bar.segments - 1, bar.segments);
        handles.insert(handles.end(), lifted.begin(), lifted.end());

        auto start = std::chrono::steady_clock::now();
        ArapDeformer arap(bar.mesh);
        const double setupMs = msSince(start);
        start = std::chrono::steady_clock::now();
        arap.setHandles(handles);
        const double factorMs = msSince(start);

        double totalMs = 0.0, minMs = 1e300, energy = 0.0;
        for (int frame = 1; frame <= o.frames; ++frame) {
            std::vector<glm::vec3> targets;
            for (std::uint32_t h : handles) {
                glm::vec3 p = bar.mesh.positions[h];
                if (p.x > 2.5f) p.y += 1.5f * float(frame) / float(o.frames);
                targets.push_back(p);
            }
            start = std::chrono::steady_clock::now();
            energy = arap.solve(targets, o.iterations).back();
            const double ms = msSince(start);
            totalMs += ms;
            minMs = std::min(minMs, ms);
        }
        const double perFrame = totalMs / o.frames;
        std::printf("%8zu %9zu %7zu | %9.2f %9.2f | %6d %9.2f %9.2f %9.3f | %10.4g\n",
                    bar.mesh.positions.size(), bar.mesh.triangles.size(), handles.size(), setupMs,
                    factorMs, o.frames, perFrame, minMs, perFrame / o.iterations, energy);
        std::fflush(stdout);
    }
    return 0;
}

}  // namespace

void addBenchArapCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "arap", "ms per frame of as-rigid-as-possible handle editing on generated bars");
    auto o = std::make_shared<BenchArapOptions>();
    cmd->add_option("--vertices", o->vertices,
                    "approximate vertex counts, comma-separated (default 5000,20000)");
    cmd->add_option("--frames", o->frames, "frames per size (default 20)");
    cmd->add_option("--iterations", o->iterations, "local/global iterations per frame (default 5)");
    cmd->add_option("--threads", o->threads, "cap TBB's threads (default: all cores)");
    cmd->add_flag("--quick", o->quick, "smallest run, to check that it works: 500 vertices");
    cmd->callback([o, &exitCode] { exitCode = runBenchArap(*o); });
}

}  // namespace eikon::app
