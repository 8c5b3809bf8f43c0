// `eikon bench methods`: every registered light-transport method, at each of its named settings
// (coarse, default, fine: render/light_transport_registry.cpp), on the analytic suite
// (apps/bench_method_cases.h), its error against the closed form beside its time. A method
// registered later appears here with no new code. Writes a table and a TSV that
// scripts/plot_methods_bench.py turns into error-against-time plots with the Pareto front.
//
// The CPU twin runs each method through its interface, as the frame renderer does: configure,
// the shared stages it needs (∇n, octree), its run. Time: its own timer stages plus the shared
// stages it needed, median of --reps runs, each from scratch. (GPU times on llvmpipe say nothing
// of a GPU; the GPU runs are checked against the CPU twin by the tests.)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "apps/bench_method_cases.h"
#include "apps/bench_report.h"
#include "apps/commands.h"
#include "core/camera.h"
#include "core/error.h"
#include "render/gpu_timer.h"
#include "render/light_transport_registry.h"
#include "render/refraction_volume.h"
#include "render/view_params.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

struct BenchMethodsOptions {
    int resolution = 63;
    int reps = 3;
    std::string methods;   // comma-separated; empty: every registered method
    std::string cases;     // comma-separated; empty: every case
    std::string settings;  // comma-separated setting names; empty: every named setting
    int threads = 0;
    bool quick = false;
    std::string tsv = "out/bench/methods.tsv";
};

struct Measurement {
    bool active = false;  // false: the method computes nothing for this scene
    double ms = 0.0;      // median
    double error = std::numeric_limits<double>::quiet_NaN();
    int64_t steps = 0;
};

// One method at one setting on one case, `reps` times from scratch.
Measurement measure(const MethodCase& c, const std::string& method, const std::string& settings,
                    int reps) {
    Scene scene = c.scene;
    patchLightTransport(scene,
                        "{\"method\": \"" + method + "\", \"" + method + "\": " + settings + "}");
    const CameraFrame camera = makeCameraFrame(scene.camera, c.volume.bounds, 4, 4);
    Measurement m;
    std::vector<double> times;
    for (int rep = 0; rep < reps; ++rep) {
        std::unique_ptr<LightTransport> transport = makeLightTransport(scene, TransportDevice{});
        ViewSetup setup = makeViewSetup(scene, c.volume, camera);
        transport->configure(scene, setup);
        std::vector<const DenseGrid*> grids;
        for (const std::string& field : setup.slotFields) grids.push_back(&c.fields.at(field));
        if (transport->cacheKey(setup, grids).empty()) return m;
        const TransportNeeds needs = transport->needs();
        GpuStageTimer timer(false);
        RefractionVolumeCpu gradient, octree;
        if (needs.gradient || needs.octree) {
            timer.begin("gradient");
            gradient = computeIndexGradientCpu(setup, grids);
            timer.end();
        }
        if (needs.octree) {
            timer.begin("octree");
            octree = computeOctreeCpu(setup, gradient, needs.octreeSettings, grids);
            timer.end();
        }
        transport->runCpu({setup, grids, gradient, octree, &timer});
        double ms = 0.0;
        for (const StageTime& s : timer.results()) ms += s.cpuMs;
        times.push_back(ms);
        if (rep + 1 < reps) continue;
        CaseOutput out{c.volume, fluenceRateCpu(setup, transport->outputCpu()),
                       transport->energy()};
        m.error = c.error(out);
        m.steps = transport->stats().steps;
    }
    m.active = true;
    m.ms = median(times);
    return m;
}

int runBenchMethods(BenchMethodsOptions o) {
    if (o.quick) {
        o.resolution = 49;  // the smallest at which the ball lens still shows its focus
        o.reps = 1;
    }
    if (o.resolution < 9 || o.resolution > 255)
        throw Error("--resolution",
                    "expected 9 to 255 voxels per edge, got " + std::to_string(o.resolution));
    if (o.reps < 1) throw Error("--reps", "expected at least 1");
    const auto threadCap = limitThreads(o.threads);
    const std::vector<MethodCase> cases = methodCases(o.resolution, splitList(o.cases));
    std::vector<const LightTransportMethod*> methods;
    const std::vector<std::string> wanted = splitList(o.methods);
    for (const std::string& name : wanted) {
        bool known = false;
        for (const LightTransportMethod& m : lightTransportMethods()) known |= m.name == name;
        if (!known) throw Error("--methods", "no light-transport method '" + name + "'");
    }
    for (const LightTransportMethod& m : lightTransportMethods())
        if (wanted.empty() || std::find(wanted.begin(), wanted.end(), m.name) != wanted.end())
            methods.push_back(&m);
    const std::vector<std::string> settings = splitList(o.settings);
    auto settingWanted = [&](const std::string& name) {
        return settings.empty() ||
               std::find(settings.begin(), settings.end(), name) != settings.end();
    };
    for (const std::string& name : settings) {
        bool known = false;
        for (const LightTransportMethod* m : methods)
            for (const auto& named : m->benchSettings) known |= named.first == name;
        if (!known) throw Error("--settings", "no method benched has a setting '" + name + "'");
    }

    std::printf("# eikon bench methods: error against ms of every light-transport method\n");
    printBenchHeader(stdout, o.threads);
    const int n = o.resolution | 1;
    std::printf(
        "# volume %d^3 over [-1, 1]^3; CPU twin; ms: the method's stages and the shared "
        "stages it needs (gradient, octree), median of %d\n",
        n, o.reps);
    for (const MethodCase& c : cases)
        std::printf("# case %s: %s; error %s\n", c.name.c_str(), c.closedForm.c_str(),
                    c.errorUnit.c_str());
    for (const LightTransportMethod* m : methods)
        for (const auto& [name, json] : m->benchSettings)
            if (settingWanted(name))
                std::printf("# setting %s %s: %s\n", m->name.c_str(), name.c_str(), json.c_str());

    if (fs::path(o.tsv).has_parent_path()) fs::create_directories(fs::path(o.tsv).parent_path());
    std::ofstream tsv(o.tsv);
    if (!tsv) throw Error(o.tsv, "cannot write the TSV file");
    tsv << "case\tmethod\tsetting\tresolution\tms\terror\terror_unit\tsteps\n";
    std::printf("%-10s %-14s %-8s | %10s | %10s %-8s | %12s\n", "case", "method", "setting", "ms",
                "error", "unit", "steps");
    for (const MethodCase& c : cases)
        for (const LightTransportMethod* m : methods)
            for (const auto& [setting, json] : m->benchSettings) {
                if (!settingWanted(setting)) continue;
                const Measurement r = measure(c, m->name, json, o.reps);
                if (!r.active) {
                    std::printf("%-10s %-14s %-8s | %10s | (computes nothing for this scene)\n",
                                c.name.c_str(), m->name.c_str(), setting.c_str(), "-");
                    continue;
                }
                char error[32];
                if (std::isnan(r.error))
                    std::snprintf(error, sizeof error, "%s",
                                  c.errorUnit == "voxels" ? "no focus" : "n/a");
                else
                    std::snprintf(error, sizeof error, "%.4g", r.error);
                std::printf("%-10s %-14s %-8s | %10.2f | %10s %-8s | %12lld\n", c.name.c_str(),
                            m->name.c_str(), setting.c_str(), r.ms, error, c.errorUnit.c_str(),
                            static_cast<long long>(r.steps));
                std::fflush(stdout);
                tsv << c.name << '\t' << m->name << '\t' << setting << '\t' << n << '\t' << r.ms
                    << '\t';
                if (std::isnan(r.error))
                    tsv << "nan";
                else
                    tsv << r.error;  // 6 significant digits, small errors included
                tsv << '\t' << c.errorUnit << '\t' << r.steps << '\n';
            }
    std::printf("# wrote %s (plot: /usr/bin/python3 scripts/plot_methods_bench.py %s)\n",
                o.tsv.c_str(), o.tsv.c_str());
    return 0;
}

}  // namespace

void addBenchMethodsCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "methods", "Error against time of every light-transport method on the analytic suite");
    auto o = std::make_shared<BenchMethodsOptions>();
    cmd->add_option("--resolution", o->resolution,
                    "voxels per edge of the cases' volume, made odd (default 63)");
    cmd->add_option("--reps", o->reps, "runs per measurement, the median is reported (default 3)");
    cmd->add_option("--methods", o->methods,
                    "comma-separated registered methods (default: all of them)");
    cmd->add_option("--cases", o->cases,
                    "comma-separated: slab, ball_lens, luneburg, linear_n2, grin, caustic, "
                    "caustic_box, energy (default all)");
    cmd->add_option("--settings", o->settings,
                    "comma-separated setting names, e.g. default,fine (default: every method's "
                    "named settings)");
    cmd->add_option("--threads", o->threads, "cap TBB's threads (default: all cores)");
    cmd->add_flag("--quick", o->quick, "a small run, to check that it works: 49^3, one run");
    cmd->add_option("--tsv", o->tsv, "TSV output (default out/bench/methods.tsv)");
    cmd->callback([o, &exitCode] { exitCode = runBenchMethods(*o); });
}

}  // namespace eikon::app
