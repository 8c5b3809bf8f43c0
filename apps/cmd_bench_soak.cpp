// `eikon bench soak`: a live scene simulated and rendered frame after frame, as `eikon render`
// and `eikon view` do (pipeline/scene_driver.h hands the frame renderer each frame's inputs), for
// thousands of frames with no image written, watching the process's memory: a leak shows as
// growth after the warm-up. Every --every frames it samples VmRSS and VmHWM (/proc/self/status),
// RssAnon, the bytes malloc has handed out, the GL objects alive (render/gl_objects.h), the fields
// the renderer holds, the smoke's total density and the picture's mean (so a run that blew up,
// emptied or saturated shows it), into a CSV that scripts/plot_soak.py plots. At the end: frames,
// wall time, ms per frame by stage, RSS at the warm-up and at the end, the largest growth after
// the warm-up, and the verdict against the bound (--bound-mib; a failed verdict is an error).
//
// The bound, 16 MiB after the warm-up: over the default 10,000 frames it catches any leak of
// 1.7 KiB a frame or more (a frame's smoke fields at 24x32x24 are ~400 KiB, a leaked one would
// pass it in 40 frames), while leaving room for what allocators legitimately do after a warm-up
// (glibc's per-thread arenas fragmenting and settling, Mesa's caches) that is no leak. Smaller
// leaks show in the slope the summary prints and in the heap-in-use column.
//
// Built with AddressSanitizer (the CI's second pass), RSS is printed but not judged: ASan holds
// freed blocks in its quarantine (256 MiB by default) before reusing them, so RSS climbs by
// hundreds of MiB over the first thousands of frames with no leak at all. The GL objects are
// still judged there.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/bench_report.h"
#include "apps/commands.h"
#include "apps/process_memory.h"
#include "core/error.h"
#include "core/scene.h"
#include "pipeline/backend_choice.h"
#include "pipeline/scene_driver.h"
#include "pipeline/scene_input.h"
#include "render/frame_renderer.h"
#include "render/gl_context.h"
#include "render/gl_objects.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

const char* const kWhere = "bench soak";

struct SoakOptions {
    std::string input = "data/scenes/soak_smoke.json";
    int frames = 10000;
    int every = 100;
    int warmup = 100;
    double boundMib = 16.0;
    std::string csv = "out/bench/soak.csv";
    std::string size;
    std::string backend = "gpu";
    int threads = 0;
};

struct Sample {
    int frame = 0;  // frames rendered so far (the scene frame when frame_start is 1)
    double elapsedS = 0.0;
    double msPerFrame = 0.0;  // mean over the frames since the previous sample
    ProcessMemory memory;
    std::optional<GlObjectCounts> gl;
    int fields = 0;
    double densityTotal = 0.0;  // ∫ density dV over every density field, scene units³
    double imageMean = 0.0;     // mean linear RGB of the frame's picture
};

double mib(std::int64_t kib) {
    return double(kib) / 1024.0;
}

// ∫ density dV of every scalar density field (labelled ones too: several smoke domains).
double densityTotal(const FieldRegistry& fields) {
    double total = 0.0;
    for (const std::string& name : fields.names()) {
        const Field& f = fields.get(name);
        if (fieldKind(name) != field::kDensity || !f.isScalar()) continue;
        const auto grid = openvdb::gridConstPtrCast<openvdb::FloatGrid>(f.grid);
        double sum = 0.0;
        for (auto it = grid->cbeginValueOn(); it; ++it)
            sum += double(*it) * double(it.getVoxelCount());
        const openvdb::Vec3d h = grid->voxelSize();
        total += sum * h.x() * h.y() * h.z();
    }
    return total;
}

double imageMean(const Image& image) {
    double sum = 0.0;
    for (const glm::vec4& p : image.pixels) sum += double(p.r) + double(p.g) + double(p.b);
    return image.pixels.empty() ? 0.0 : sum / (3.0 * double(image.pixels.size()));
}

void writeCsvHeader(std::ofstream& csv) {
    csv << "frame,elapsed_s,ms_per_frame,rss_kib,hwm_kib,rss_anon_kib,heap_in_use_kib,"
           "gl_objects,gl_textures,gl_buffers,gl_programs,gl_queries,fields,density_total,"
           "image_mean\n";
}

void writeCsvRow(std::ofstream& csv, const Sample& s) {
    char line[512];
    const GlObjectCounts none{-1, -1, -1, -1, -1, -1, -1, -1};
    const GlObjectCounts& gl = s.gl ? *s.gl : none;
    std::snprintf(
        line, sizeof line, "%d,%.3f,%.3f,%lld,%lld,%lld,%lld,%d,%d,%d,%d,%d,%d,%.6g,%.6g\n",
        s.frame, s.elapsedS, s.msPerFrame, static_cast<long long>(s.memory.rssKib),
        static_cast<long long>(s.memory.hwmKib), static_cast<long long>(s.memory.rssAnonKib),
        static_cast<long long>(s.memory.heapInUseKib), s.gl ? gl.total() : -1, gl.textures,
        gl.buffers, gl.programs, gl.queries, s.fields, s.densityTotal, s.imageMean);
    csv << line;
    csv.flush();  // a run stopped by a blow-up or a kill keeps the rows before it
}

// Least-squares slope of RSS against frame over the samples from `from` on, KiB per 1000 frames.
double rssSlope(const std::vector<Sample>& samples, size_t from) {
    const size_t n = samples.size() - from;
    if (n < 2) return 0.0;
    double mx = 0.0, my = 0.0;
    for (size_t i = from; i < samples.size(); ++i) {
        mx += samples[i].frame;
        my += double(samples[i].memory.rssKib);
    }
    mx /= double(n);
    my /= double(n);
    double sxy = 0.0, sxx = 0.0;
    for (size_t i = from; i < samples.size(); ++i) {
        const double dx = samples[i].frame - mx;
        sxy += dx * (double(samples[i].memory.rssKib) - my);
        sxx += dx * dx;
    }
    return sxx > 0.0 ? 1000.0 * sxy / sxx : 0.0;
}

struct StageTotal {
    std::string name;
    double ms = 0.0;
};

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kRssJudged = false;
#else
constexpr bool kRssJudged = true;
#endif

// The summary, from the samples so far; throws eikon::Error when the verdict fails.
void printSummary(const SoakOptions& o, const std::vector<Sample>& samples, int framesDone,
                  double wallS, double loopMs, const std::vector<StageTotal>& stages) {
    std::printf("# soak: %d frames in %.1f s, %.2f ms/frame (%.1f fps), sampling excluded\n",
                framesDone, wallS, framesDone > 0 ? loopMs / framesDone : 0.0,
                loopMs > 0.0 ? 1000.0 * framesDone / loopMs : 0.0);
    std::string split;
    for (const StageTotal& s : stages) {
        char item[64];
        std::snprintf(item, sizeof item, "%s%s %.2f", split.empty() ? "" : ", ", s.name.c_str(),
                      framesDone > 0 ? s.ms / framesDone : 0.0);
        split += item;
    }
    std::printf("# ms/frame by stage: %s\n", split.c_str());
    if (samples.empty()) return;
    const Sample& last = samples.back();
    std::printf("# RSS at the start (frame %d): %.1f MiB; peak (VmHWM) %.1f MiB\n",
                samples.front().frame, mib(samples.front().memory.rssKib), mib(last.memory.hwmKib));
    size_t warm = samples.size();
    for (size_t i = 0; i < samples.size(); ++i)
        if (samples[i].frame == o.warmup) warm = i;
    if (warm == samples.size()) {
        std::printf("# RSS at the end (frame %d): %.1f MiB\n", last.frame, mib(last.memory.rssKib));
        std::printf("# verdict: not judged: the run ended before the warm-up (frame %d)\n",
                    o.warmup);
        return;
    }
    const Sample& w = samples[warm];
    double maxGrowth = 0.0;
    int maxAt = w.frame;
    for (size_t i = warm; i < samples.size(); ++i) {
        const double g = mib(samples[i].memory.rssKib - w.memory.rssKib);
        if (g > maxGrowth) {
            maxGrowth = g;
            maxAt = samples[i].frame;
        }
    }
    const double endGrowth = mib(last.memory.rssKib - w.memory.rssKib);
    std::printf("# RSS after the warm-up (frame %d): %.1f MiB; at the end (frame %d): %.1f MiB\n",
                w.frame, mib(w.memory.rssKib), last.frame, mib(last.memory.rssKib));
    std::printf(
        "# growth after the warm-up: max %+.2f MiB (frame %d), at the end %+.2f MiB; "
        "least-squares slope after it %+.1f KiB per 1000 frames\n",
        maxGrowth, maxAt, endGrowth, rssSlope(samples, warm));
    std::printf("# RssAnon %.1f -> %.1f MiB; heap in use (malloc) %.1f -> %.1f MiB\n",
                mib(w.memory.rssAnonKib), mib(last.memory.rssAnonKib), mib(w.memory.heapInUseKib),
                mib(last.memory.heapInUseKib));
    bool glGrew = false;
    if (w.gl && last.gl) {
        glGrew = last.gl->total() > w.gl->total();
        std::printf("# GL objects alive: %d after the warm-up, %d at the end (%s)\n", w.gl->total(),
                    last.gl->total(), last.gl->describe().c_str());
    }
    const bool rssOver = kRssJudged && maxGrowth > o.boundMib;
    const char* glText = w.gl ? glGrew ? "; GL objects grew" : "; GL objects constant" : "";
    if (kRssJudged)
        std::printf("# verdict: %s (RSS growth after the warm-up %.2f MiB, bound %.1f MiB%s)\n",
                    !rssOver && !glGrew ? "PASS" : "FAIL", maxGrowth, o.boundMib, glText);
    else
        std::printf(
            "# verdict: %s (RSS not judged: built with AddressSanitizer, whose quarantine holds "
            "freed memory%s)\n",
            glGrew ? "FAIL" : "PASS", glText);
    std::fflush(stdout);
    if (rssOver) {
        char reason[160];
        std::snprintf(reason, sizeof reason,
                      "RSS grew %.2f MiB after the warm-up (frame %d), over the %.1f MiB bound",
                      maxGrowth, o.warmup, o.boundMib);
        throw Error(kWhere, reason);
    }
    if (glGrew)
        throw Error(kWhere, "GL objects alive grew from " + std::to_string(w.gl->total()) +
                                " after the warm-up to " + std::to_string(last.gl->total()));
}

int runBenchSoak(const SoakOptions& o) {
    if (o.frames < 1) throw Error("--frames", "expected at least 1");
    if (o.every < 1) throw Error("--every", "expected at least 1");
    if (o.warmup < 1) throw Error("--warmup", "expected at least 1");
    if (!(o.boundMib >= 0.0)) throw Error("--bound-mib", "expected a size in MiB, 0 or more");
    const auto threadCap = limitThreads(o.threads);
    InputChoices choices;
    choices.size = o.size;
    Scene scene = readSceneInput(o.input, choices).scene;
    SceneDriver driver(scene);
    BackendChoice choice = chooseBackend(o.backend);
    FrameRenderer renderer(scene, choice.backend, choice.context.get());

    if (fs::path(o.csv).has_parent_path()) fs::create_directories(fs::path(o.csv).parent_path());
    std::ofstream csv(o.csv);
    if (!csv) throw Error(o.csv, "cannot write the CSV file");
    writeCsvHeader(csv);

    std::printf("# eikon bench soak: a live scene simulated and rendered frame after frame\n");
    printBenchHeader(stdout, o.threads);
    std::printf("# renderer: %s\n", choice.description.c_str());
    std::printf(
        "# scene %s: %dx%d pixels, %d frames from frame %d, sampled every %d; warm-up %d "
        "frames; bound %.1f MiB of RSS growth after it\n",
        scene.path.c_str(), scene.render.width, scene.render.height, o.frames,
        scene.time.frameStart, o.every, o.warmup, o.boundMib);
    std::fflush(stdout);

    std::vector<Sample> samples;
    std::vector<StageTotal> stages = {{"simulate"}};
    const auto start = std::chrono::steady_clock::now();
    double loopMs = 0.0;          // frames only, sampling excluded
    double loopMsAtSample = 0.0;  // at the previous sample
    int frameAtSample = 0;
    int done = 0;
    auto sample = [&](const Image& image) {
        Sample s;
        s.frame = done;
        s.elapsedS =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        s.msPerFrame = (loopMs - loopMsAtSample) / double(done - frameAtSample);
        s.memory = readProcessMemory();
        if (renderer.context()) s.gl = countGlObjects();
        s.fields = int(renderer.fields().names().size());
        s.densityTotal = densityTotal(renderer.fields());
        s.imageMean = imageMean(image);
        writeCsvRow(csv, s);
        std::printf("frame %6d/%d  %6.1f fps  RSS %7.1f MiB  heap %7.1f MiB", s.frame, o.frames,
                    s.msPerFrame > 0.0 ? 1000.0 / s.msPerFrame : 0.0, mib(s.memory.rssKib),
                    mib(s.memory.heapInUseKib));
        if (s.gl) std::printf("  GL objects %d", s.gl->total());
        std::printf("  density %.4g  image %.4g\n", s.densityTotal, s.imageMean);
        std::fflush(stdout);
        samples.push_back(s);
        loopMsAtSample = loopMs;
        frameAtSample = done;
    };
    auto addStage = [&](const std::string& name, double ms) {
        for (StageTotal& s : stages)
            if (s.name == name) {
                s.ms += ms;
                return;
            }
        stages.push_back({name, ms});
    };
    auto wallS = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    try {
        for (int i = 0; i < o.frames; ++i) {
            const int frame = scene.time.frameStart + i;
            const auto t0 = std::chrono::steady_clock::now();
            const FrameInputs inputs = driver.frameInputs(frame, scene);
            const auto t1 = std::chrono::steady_clock::now();
            const Image image = renderer.render(inputs);
            const auto t2 = std::chrono::steady_clock::now();
            addStage("simulate", std::chrono::duration<double, std::milli>(t1 - t0).count());
            for (const StageTime& s : renderer.takeStats()) addStage(s.name, s.cpuMs);
            loopMs += std::chrono::duration<double, std::milli>(t2 - t0).count();
            ++done;
            if (done == 1 || done % o.every == 0 || done == o.warmup || done == o.frames)
                sample(image);
        }
    } catch (const Error& e) {
        std::printf("# stopped after %d frames: %s\n", done, e.what());
        printSummary(o, samples, done, wallS(), loopMs, stages);
        throw;
    }
    printSummary(o, samples, done, wallS(), loopMs, stages);
    std::printf("# wrote %s (plot: /usr/bin/python3 scripts/plot_soak.py %s)\n", o.csv.c_str(),
                o.csv.c_str());
    return 0;
}

}  // namespace

void addBenchSoakCommand(CLI::App& bench, int& exitCode) {
    auto* cmd = bench.add_subcommand(
        "soak", "A live scene simulated and rendered for many frames, its memory watched");
    auto o = std::make_shared<SoakOptions>();
    cmd->add_option("input", o->input,
                    "scene.json with a live simulation (default data/scenes/soak_smoke.json)");
    cmd->add_option("--frames", o->frames, "frames to simulate and render (default 10000)");
    cmd->add_option("--every", o->every, "sample memory every this many frames (default 100)");
    cmd->add_option("--warmup", o->warmup,
                    "frames before memory is judged; growth counts from here (default 100)");
    cmd->add_option("--bound-mib", o->boundMib,
                    "the most RSS may grow after the warm-up, MiB (default 16)");
    cmd->add_option("--csv", o->csv, "CSV output (default out/bench/soak.csv)");
    cmd->add_option("--size", o->size, "image size WIDTHxHEIGHT (default: the scene's)");
    cmd->add_option("--backend", o->backend, "gpu (default: headless OpenGL) or cpu (the twin)")
        ->check(CLI::IsMember({"gpu", "cpu"}));
    cmd->add_option("--threads", o->threads, "cap TBB's threads (default: all cores)");
    cmd->callback([o, &exitCode] { exitCode = runBenchSoak(*o); });
}

}  // namespace eikon::app
