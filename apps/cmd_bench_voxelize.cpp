// `eikon bench voxelize`: ms per voxelization of closed meshes at a render resolution (Sun et al.
// 2008 Table 1: 10k-80k triangles at 128³ in 15-90 ms on a 2007 GPU) and the volume error of the
// coverage, on the GPU and the CPU twin. The default meshes and framing are those of the
// mesh-to-volume peer (../shared/peers/meshtovolume_peer.sh: a unit sphere 103 voxels across),
// so that both are timed on the same triangles.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "apps/bench_report.h"
#include "apps/commands.h"
#include "core/error.h"
#include "core/mesh_primitives.h"
#include "render/gl_context.h"
#include "render/voxelize.h"
#include "sim/refractive_mesh.h"

namespace eikon::app {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct BenchVoxelizeOptions {
    std::string meshes = "uv:100x51,ico:5,uv:200x101,uv:200x201,ico:6";
    int resolution = 128;
    double span = 103.0;  // the sphere's diameter in voxels, as the peer's
    int reps = 5;
    int threads = 0;
    std::string backends = "cpu,gpu";
    bool quick = false;
};

struct NamedMesh {
    std::string name;
    TriangleMesh mesh;
    bool sphere = true;  // a unit sphere: its error against 4/3 π is printed too
};

// A mesh file scaled and centred so that its bounding box's longest side is 2, like the spheres'
// diameter, so that it spans the same voxels.
NamedMesh fileMesh(const std::string& path) {
    TriangleMesh mesh = loadRefractiveMesh(path, {}).mesh;
    const Bounds3 b = boundsOf(mesh);
    const glm::vec3 size = b.size();
    const float scale = 2.0f / std::max({size.x, size.y, size.z});
    for (glm::vec3& p : mesh.positions) p = (p - b.center()) * scale;
    return {std::filesystem::path(path).filename().string(), std::move(mesh), false};
}

// "ico:L" (icosphere, L subdivisions) or "uv:SxT" (slices × stacks), unit radius at the origin,
// or "file:PATH" (a closed mesh file, scaled to the same span).
NamedMesh parseMesh(const std::string& spec) {
    if (spec.rfind("file:", 0) == 0) return fileMesh(spec.substr(5));
    int a = 0, b = 0;
    char x = 0;
    std::istringstream in(spec.substr(std::min<size_t>(spec.size(), spec.find(':') + 1)));
    if (spec.rfind("ico:", 0) == 0 && (in >> a) && in.eof() && a >= 0 && a <= 8)
        return {"icosphere(L" + std::to_string(a) + ")", icosphere(glm::vec3(0.0f), 1.0f, a)};
    if (spec.rfind("uv:", 0) == 0 && (in >> a >> x >> b) && x == 'x' && in.eof() && a >= 3 &&
        b >= 2)
        return {"uvsphere(" + std::to_string(a) + "x" + std::to_string(b) + ")",
                uvSphere(glm::vec3(0.0f), 1.0f, a, b)};
    throw Error("--meshes",
                "unknown mesh '" + spec + "' (expected ico:L, uv:SLICESxSTACKS or file:PATH)");
}

template <typename F>
std::vector<double> timeRuns(int reps, F&& run) {
    std::vector<double> ms;
    for (int r = 0; r < reps; ++r) {
        const auto start = std::chrono::steady_clock::now();
        run();
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count());
    }
    return ms;
}

double volumeOf(const std::vector<float>& coverage, const RenderVolume& volume) {
    double sum = 0.0;
    for (float c : coverage) sum += double(c);
    const glm::vec3 v = volume.voxelSize();
    return sum * double(v.x) * double(v.y) * double(v.z);
}

int runBenchVoxelize(BenchVoxelizeOptions o) {
    if (o.quick) {
        o.meshes = "ico:2,uv:12x7";
        o.resolution = 24;
        o.span = 19.0;
        o.reps = 1;
    }
    if (o.resolution < 4 || o.resolution > 512) throw Error("--resolution", "must be in 4..512");
    if (!(o.span > 1.0) || o.span > o.resolution)
        throw Error("--span", "must be above 1 and at most the resolution");
    if (o.reps < 1) throw Error("--reps", "must be at least 1");
    std::vector<NamedMesh> meshes;
    for (const std::string& spec : splitList(o.meshes)) meshes.push_back(parseMesh(spec));
    bool cpu = false, gpu = false;
    for (const std::string& b : splitList(o.backends)) {
        if (b == "cpu")
            cpu = true;
        else if (b == "gpu")
            gpu = true;
        else
            throw Error("--backends", "unknown backend '" + b + "' (expected cpu, gpu)");
    }
    const auto threadCap = limitThreads(o.threads);

    const float voxel = float(2.0 / o.span);
    const RenderVolume volume{Bounds3{glm::vec3(-0.5f * voxel * float(o.resolution)),
                                      glm::vec3(0.5f * voxel * float(o.resolution))},
                              glm::ivec3(o.resolution)};
    std::printf("# eikon bench voxelize: closed meshes to coverage (render/voxelize.h)\n");
    printBenchHeader(stdout, o.threads);
    std::printf("# volume %d^3, unit sphere %.1f voxels across (voxel %.6f); median of %d runs\n",
                o.resolution, o.span, double(voxel), o.reps);
    std::printf(
        "# voxelize: mesh upload, parity flips, scan, 64-sample coverage (GPU: to "
        "glFinish); blur: the 9^3 Gaussian of n (sigma 1.5 voxels)\n");
    std::printf(
        "# volume error: sum of coverage x voxel volume against 4/3 pi and against the "
        "polyhedron's own volume\n");

    std::unique_ptr<GlContext> context;
    std::unique_ptr<MeshVoxelizerGpu> voxelizer;
    std::unique_ptr<CoverageTextureGpu> target;  // released before the context
    if (gpu) {
        context = createHeadlessContext();
        std::printf("# GPU: %s\n", context->rendererName().c_str());
        voxelizer = std::make_unique<MeshVoxelizerGpu>();
        target = std::make_unique<CoverageTextureGpu>(volume.resolution);
    }
    std::printf("%-20s %9s %-8s | %12s %12s %9s | %12s %12s\n", "mesh", "triangles", "backend",
                "voxelize ms", "(min)", "blur ms", "err vs 4/3pi", "err vs poly");
    for (const NamedMesh& m : meshes) {
        const double poly = signedVolume(m.mesh);
        auto report = [&](const char* backend, const std::vector<double>& vox,
                          const std::vector<double>& blur, const std::vector<float>& coverage) {
            const double v = volumeOf(coverage, volume);
            char sphereError[32] = "           -";
            if (m.sphere)
                std::snprintf(sphereError, sizeof sphereError, "%11.4f%%",
                              100.0 * (v - 4.0 / 3.0 * kPi) / (4.0 / 3.0 * kPi));
            std::printf("%-20s %9zu %-8s | %12.2f %12.2f %9.2f | %s %11.4f%%\n", m.name.c_str(),
                        m.mesh.triangles.size(), backend, median(vox),
                        *std::min_element(vox.begin(), vox.end()), median(blur), sphereError,
                        100.0 * (v - poly) / poly);
            std::fflush(stdout);
        };
        if (cpu) {
            std::vector<float> coverage;
            const auto vox =
                timeRuns(o.reps, [&] { coverage = voxelizeCoverageCpu(m.mesh, volume); });
            const auto blur = timeRuns(o.reps, [&] {
                (void)blurCoverageCpu(coverage, volume.resolution, IndexBlurSettings{});
            });
            report("cpu twin", vox, blur, coverage);
        }
        if (gpu) {
            const auto vox = timeRuns(o.reps, [&] {
                voxelizer->voxelize(m.mesh, volume, target->texture());
                context->finish();
            });
            const std::vector<float> coverage = target->download();
            const auto blur = timeRuns(o.reps, [&] {
                voxelizer->blur(target->texture(), volume.resolution, IndexBlurSettings{});
                context->finish();
            });
            report("gpu", vox, blur, coverage);
        }
    }
    return 0;
}

}  // namespace

void addBenchVoxelizeCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand("voxelize", "ms and volume error of mesh voxelization");
    auto o = std::make_shared<BenchVoxelizeOptions>();
    cmd->add_option("--meshes", o->meshes,
                    "comma-separated ico:L, uv:SLICESxSTACKS and file:PATH (default: the peer's, "
                    "plus uv:200x101 for 40k triangles)");
    cmd->add_option("--resolution", o->resolution, "voxels per axis (default 128)");
    cmd->add_option("--span", o->span, "the sphere's diameter in voxels (default 103)");
    cmd->add_option("--reps", o->reps, "runs per measurement; the median is printed (default 5)");
    cmd->add_option("--backends", o->backends, "cpu, gpu or both (default cpu,gpu)");
    cmd->add_option("--threads", o->threads, "cap TBB's threads (default: all cores)");
    cmd->add_flag("--quick", o->quick, "smallest run, to check that it works");
    cmd->callback([o, &exitCode] { exitCode = runBenchVoxelize(*o); });
}

}  // namespace eikon::app
