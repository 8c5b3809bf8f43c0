// `eikon bench integrators`: the ray equation's integrators (shaders/shared/ray_equation.h) on
// the refracting cases of the analytic suite (apps/bench_method_cases.h), measured ray by ray.
// The photons of each case are traced by the CPU twin of the photon march with each integrator
// at three steps and at the photons' default steps; every sampled photon's exit point is
// compared with two exact traces of the same starting ray (double precision, RK4 at 1/16 voxel,
// core/exact_ray.h):
//   path error         against the trace through the continuous index field the case samples:
//                      what a user sees, the integrator's error and the sampled ∇n's together;
//   integration error  against the trace through the ∇n volume the photons read (trilinear,
//                      as sampleVolume): the integrator's own error.
// A focus measured on the fluence (`eikon bench methods`) mixes these with the deposit and the
// smoothing; here nothing else is in the way. ms: the photon march alone (the octree and ∇n are
// shared by all rows of a case), median of --reps.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "apps/bench_method_cases.h"
#include "apps/bench_report.h"
#include "apps/commands.h"
#include "core/camera.h"
#include "core/error.h"
#include "core/exact_ray.h"
#include "render/refraction_volume.h"
#include "render/transport/photons/photon_transport.h"
#include "render/view_params.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

struct BenchIntegratorsOptions {
    int resolution = 63;
    int reps = 3;
    int perSide = 128;
    int rays = 2048;
    std::string cases;
    std::string integrators;
    int threads = 0;
    bool quick = false;
    std::string tsv = "out/bench/integrators.tsv";
};

// A named step setting: min_step_voxels and max_step_voxels of the photons.
struct StepSetting {
    const char* name;
    float minVoxels;
    float maxVoxels;
};
// Three steps taken wherever n varies (the octree's minimum and limit both set to it), and the
// photons' defaults (1 voxel near strong variation, up to 8 where n varies a little).
const StepSetting kSteps[] = {
    {"2", 2.0f, 2.0f}, {"1", 1.0f, 1.0f}, {"0.5", 0.5f, 0.5f}, {"default", 1.0f, 8.0f}};

// The ∇n volume sampled as sampleVolume does (shaders/shared/sampling.h), in double: the field
// the photons integrate, for the exact trace of integration error.
IndexField sampledField(const RefractionVolumeCpu& gradient, const RenderVolume& volume) {
    return [&gradient, volume](const glm::dvec3& x) {
        const glm::ivec3 res = volume.resolution;
        const glm::dvec3 h = glm::dvec3(volume.voxelSize());
        const glm::dvec3 q = (x - glm::dvec3(volume.bounds.min)) / h - 0.5;
        const glm::dvec3 base = glm::floor(q);
        const glm::dvec3 f = q - base;
        glm::dvec4 sum(0.0);
        for (int c = 0; c < 8; ++c) {
            glm::ivec3 i = glm::ivec3(base) + glm::ivec3(c & 1, (c >> 1) & 1, (c >> 2) & 1);
            i = glm::clamp(i, glm::ivec3(0), res - 1);
            const double w = ((c & 1) ? f.x : 1.0 - f.x) * ((c & 2) ? f.y : 1.0 - f.y) *
                             ((c & 4) ? f.z : 1.0 - f.z);
            const size_t at =
                (size_t(i.z) * size_t(res.y) + size_t(i.y)) * size_t(res.x) + size_t(i.x);
            sum += w * glm::dvec4(gradient[at]);
        }
        return sum;
    };
}

struct ExactExits {
    std::vector<size_t> photons;  // indices of the sampled photons
    std::vector<ExactRayEnd> continuous, sampled;
};

// The exact exits of every `stride`-th photon that entered the box.
ExactExits exactExits(const MethodCase& c, const std::vector<shared::GpuPhoton>& starts,
                      const RefractionVolumeCpu& gradient, int rays) {
    ExactExits e;
    std::vector<size_t> active;
    for (size_t i = 0; i < starts.size(); ++i)
        if (int(starts[i].position.w) == EK_PHOTON_ACTIVE) active.push_back(i);
    const size_t stride = std::max<size_t>(1, active.size() / size_t(std::max(rays, 1)));
    const double ds = double(c.volume.voxelSize().y) / 16.0;
    const int maxSteps = int(16.0 * 16.0 * 3.0 * double(c.volume.resolution.y));
    const IndexField sampled = sampledField(gradient, c.volume);
    for (size_t k = 0; k < active.size(); k += stride) {
        const shared::GpuPhoton& p = starts[active[k]];
        const glm::dvec3 x(glm::vec3(p.position));
        const glm::dvec3 v(glm::vec3(p.direction));
        const glm::dvec3 d = glm::normalize(v);
        e.photons.push_back(active[k]);
        e.continuous.push_back(
            traceExactRay(c.index, c.volume.bounds, x, c.index(x).w * d, ds, maxSteps));
        e.sampled.push_back(traceExactRay(sampled, c.volume.bounds, x, v, ds, maxSteps));
    }
    return e;
}

struct RayErrors {
    double path = 0.0;         // RMS, voxels
    double integration = 0.0;  // RMS, voxels
    int unmatched = 0;         // a photon that did not escape, or an exact ray that did not
};

RayErrors compare(const ExactExits& e, const std::vector<shared::GpuPhoton>& ends, double h) {
    RayErrors r;
    double path2 = 0.0, integration2 = 0.0;
    int matched = 0;
    for (size_t k = 0; k < e.photons.size(); ++k) {
        const shared::GpuPhoton& p = ends[e.photons[k]];
        if (int(p.position.w) != EK_PHOTON_ESCAPED || !e.continuous[k].left || !e.sampled[k].left) {
            ++r.unmatched;
            continue;
        }
        const glm::dvec3 x(glm::vec3(p.position));
        path2 += glm::dot(x - e.continuous[k].position, x - e.continuous[k].position);
        integration2 += glm::dot(x - e.sampled[k].position, x - e.sampled[k].position);
        ++matched;
    }
    if (matched > 0) {
        r.path = std::sqrt(path2 / matched) / h;
        r.integration = std::sqrt(integration2 / matched) / h;
    } else {
        r.path = r.integration = std::nan("");
    }
    return r;
}

int runBenchIntegrators(BenchIntegratorsOptions o) {
    if (o.quick) {
        o.resolution = 33;
        o.reps = 1;
        o.perSide = 32;
        o.rays = 256;
    }
    if (o.resolution < 9 || o.resolution > 255)
        throw Error("--resolution",
                    "expected 9 to 255 voxels per edge, got " + std::to_string(o.resolution));
    if (o.reps < 1) throw Error("--reps", "expected at least 1");
    if (o.perSide < 1 || o.perSide > 1024) throw Error("--per-side", "expected 1 to 1024");
    if (o.rays < 1) throw Error("--rays", "expected at least 1");
    std::vector<std::string> integrators = splitList(o.integrators);
    if (integrators.empty()) integrators = rayIntegratorNames();
    for (const std::string& name : integrators) {
        const auto& all = rayIntegratorNames();
        if (std::find(all.begin(), all.end(), name) == all.end())
            throw Error("--integrators",
                        "no integrator '" + name + "' (euler, midpoint, rk4, verlet)");
    }
    std::vector<std::string> only = splitList(o.cases);
    if (only.empty()) only = refractingCaseNames();
    const std::vector<MethodCase> cases = methodCases(o.resolution, only);
    for (const MethodCase& c : cases)
        if (!c.index) throw Error("--cases", "case '" + c.name + "' bends no light");
    const auto threadCap = limitThreads(o.threads);

    std::printf(
        "# eikon bench integrators: exit-point error against ms of the ray equation's "
        "integrators, photon by photon\n");
    printBenchHeader(stdout, o.threads);
    const int n = o.resolution | 1;
    std::printf(
        "# volume %d^3 over [-1, 1]^3; CPU twin; %d^2 photons per case, up to %d of "
        "them against exact traces (RK4, double, 1/16 voxel); ms: the photon march, "
        "median of %d\n",
        n, o.perSide, o.rays, o.reps);
    std::printf(
        "# path: RMS exit-point error against the trace through the continuous field; "
        "integration: against the trace through the sampled grad-n volume; voxels\n");
    for (const StepSetting& s : kSteps)
        std::printf("# step %s: min_step_voxels %g, max_step_voxels %g\n", s.name,
                    double(s.minVoxels), double(s.maxVoxels));

    if (fs::path(o.tsv).has_parent_path()) fs::create_directories(fs::path(o.tsv).parent_path());
    std::ofstream tsv(o.tsv);
    if (!tsv) throw Error(o.tsv, "cannot write the TSV file");
    // The columns of `eikon bench methods`' TSV first, so that its plot script reads this too.
    // error: the integration error, the integrator's own; path_error beside it.
    tsv << "case\tmethod\tsetting\tresolution\tms\terror\terror_unit\tsteps\tpath_error"
           "\tunmatched\n";
    std::printf("%-9s %-9s %-7s | %9s | %10s %11s | %9s %9s\n", "case", "integr.", "step", "ms",
                "path err", "integr. err", "steps", "unmatched");
    for (const MethodCase& c : cases) {
        const CameraFrame camera = makeCameraFrame(c.scene.camera, c.volume.bounds, 4, 4);
        const ViewSetup setup = makeViewSetup(c.scene, c.volume, camera);
        std::vector<const DenseGrid*> grids;
        for (const std::string& field : setup.slotFields) grids.push_back(&c.fields.at(field));
        const RefractionVolumeCpu gradient = computeIndexGradientCpu(setup, grids);
        PhotonSettings base;
        base.photonsPerSide = o.perSide;
        const ExactExits exact =
            exactExits(c, generatePhotonsCpu(setup, gradient, base), gradient, o.rays);
        const double h = double(c.volume.voxelSize().y);
        for (const std::string& integrator : integrators)
            for (const StepSetting& step : kSteps) {
                PhotonTransportSettings settings;
                settings.trace.photonsPerSide = o.perSide;
                settings.trace.integrator = rayIntegratorNamed(integrator);
                settings.trace.minStepVoxels = step.minVoxels;
                settings.maxStepVoxels = step.maxVoxels;
                const PhotonTransport transport(settings, TransportDevice{});
                const RefractionVolumeCpu octree =
                    computeOctreeCpu(setup, gradient, transport.needs().octreeSettings, grids);
                std::vector<double> times;
                PhotonResultCpu result;
                for (int rep = 0; rep < o.reps; ++rep) {
                    const auto t0 = std::chrono::steady_clock::now();
                    result = traceLightPhotonsCpu(setup, grids, gradient, octree,
                                                  transport.traceSettings());
                    times.push_back(std::chrono::duration<double, std::milli>(
                                        std::chrono::steady_clock::now() - t0)
                                        .count());
                }
                const double ms = median(times);
                const RayErrors e = compare(exact, result.photons, h);
                std::printf("%-9s %-9s %-7s | %9.2f | %10.4g %11.4g | %9lld %9d\n", c.name.c_str(),
                            integrator.c_str(), step.name, ms, e.path, e.integration,
                            static_cast<long long>(result.steps), e.unmatched);
                std::fflush(stdout);
                tsv << c.name << '\t' << integrator << '\t' << step.name << '\t' << n << '\t' << ms
                    << '\t' << e.integration << "\tvoxels\t" << result.steps << '\t' << e.path
                    << '\t' << e.unmatched << '\n';
            }
    }
    std::printf(
        "# wrote %s (plot: /usr/bin/python3 scripts/plot_methods_bench.py %s [PNG "
        "[path_error]])\n",
        o.tsv.c_str(), o.tsv.c_str());
    return 0;
}

}  // namespace

void addBenchIntegratorsCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "integrators",
        "Exit-point error against time of the ray equation's integrators, photon by photon");
    auto o = std::make_shared<BenchIntegratorsOptions>();
    cmd->add_option("--resolution", o->resolution,
                    "voxels per edge of the cases' volume, made odd (default 63)");
    cmd->add_option("--reps", o->reps, "runs per measurement, the median is reported (default 3)");
    cmd->add_option("--per-side", o->perSide,
                    "photons per side of each light's grid (default 128)");
    cmd->add_option("--rays", o->rays,
                    "photons per case compared with exact traces (default 2048)");
    cmd->add_option("--cases", o->cases,
                    "comma-separated: ball_lens, luneburg, linear_n2, grin (default all)");
    cmd->add_option("--integrators", o->integrators,
                    "comma-separated: euler, midpoint, rk4, verlet (default all)");
    cmd->add_option("--threads", o->threads, "cap TBB's threads (default: all cores)");
    cmd->add_flag("--quick", o->quick,
                  "a small run, to check that it works: 33^3, 32^2 photons, 256 rays, one run");
    cmd->add_option("--tsv", o->tsv, "TSV output (default out/bench/integrators.tsv)");
    cmd->callback([o, &exitCode] { exitCode = runBenchIntegrators(*o); });
}

}  // namespace eikon::app
