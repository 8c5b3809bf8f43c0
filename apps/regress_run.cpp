#include "apps/regress_run.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>

#include "apps/subprocess.h"
#include "core/error.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

// The last line of the log that starts "eikon: " (the one-line error), else the last line.
std::string lastErrorLine(const std::string& logPath) {
    std::ifstream in(logPath);
    std::string line, last, error;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        last = line;
        if (line.rfind("eikon: ", 0) == 0) error = line;
    }
    return error.empty() ? last : error;
}

// Runs one command, its line and output appended to the log; false (with `reason`) on failure.
bool runStep(const std::vector<std::string>& argv, const RegressCase& c, CaseRun& run) {
    {
        std::ofstream log(run.logPath, std::ios::app);
        log << "$";
        for (const std::string& a : argv) log << " " << a;
        log << "\n";
    }
    const ProcessResult r = runProcess(argv, run.logPath, c.timeoutSeconds);
    if (r.succeeded()) return true;
    const std::string line = lastErrorLine(run.logPath);
    run.reason = std::string(argv[1]) + " " + r.describe(c.timeoutSeconds) +
                 (line.empty() || line[0] == '$' ? "" : ": " + line);
    return false;
}

void addFiles(const fs::path& folder, const std::string& keyPrefix, const std::string& extension,
              std::map<std::string, std::string>& outputs) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) return;
    for (const auto& e : fs::directory_iterator(folder, ec))
        if (e.path().extension() == extension)
            outputs[keyPrefix + e.path().filename().string()] = e.path().string();
}

}  // namespace

std::string outputKind(const std::string& key) {
    const fs::path p(key);
    const std::string ext = p.extension().string();
    if (p.filename() == "render_stats.json") return "render_stats";
    if (p.filename() == "simulation_stats.json") return "simulation_stats";
    if (ext == ".png") return "png";
    if (ext == ".exr") return "exr";
    if (ext == ".vdb") return "cache";
    return "";
}

CaseRun runCase(const RegressCase& c, const std::string& eikon, const std::string& workDir) {
    CaseRun run;
    std::error_code ec;
    fs::remove_all(workDir, ec);
    fs::create_directories(workDir, ec);
    if (ec) throw Error(workDir, "cannot create the case's work folder: " + ec.message());
    run.logPath = (fs::path(workDir) / "log.txt").string();
    const auto framesAndSize = [&](std::vector<std::string>& argv) {
        if (!c.frames.empty()) argv.insert(argv.end(), {"--frames", c.frames});
    };
    if (c.simulates()) {
        const fs::path cache = fs::path(workDir) / "cache";
        std::vector<std::string> argv{
            eikon,          "simulate",
            c.input,        "-o",
            cache.string(), "--quiet",
            "--stats-json", (fs::path(workDir) / "simulation_stats.json").string()};
        framesAndSize(argv);
        if (!runStep(argv, c, run)) return run;
        if (c.cache) addFiles(cache, c.name + "/cache/", ".vdb", run.outputs);
        if (!c.simulationStats.empty())
            run.outputs[c.name + "/simulation_stats.json"] =
                (fs::path(workDir) / "simulation_stats.json").string();
    }
    if (c.renders()) {
        const bool exr = c.exr || c.acrossBackends;
        for (const std::string& backend : c.backends) {
            const fs::path folder = fs::path(workDir) / backend;
            fs::create_directories(folder, ec);
            std::vector<std::string> argv{eikon,
                                          "render",
                                          c.input,
                                          "-o",
                                          (folder / "frame_####.png").string(),
                                          "--backend",
                                          backend,
                                          "--quiet",
                                          "--stats-json",
                                          (folder / "render_stats.json").string()};
            if (exr) argv.push_back("--exr");
            framesAndSize(argv);
            if (!c.size.empty()) argv.insert(argv.end(), {"--size", c.size});
            if (!runStep(argv, c, run)) return run;
            const std::string prefix = c.name + "/" + backend + "/";
            if (c.png) addFiles(folder, prefix, ".png", run.outputs);
            if (c.exr) addFiles(folder, prefix, ".exr", run.outputs);
            if (!c.renderStats.empty())
                run.outputs[prefix + "render_stats.json"] = (folder / "render_stats.json").string();
            std::map<std::string, std::string> frames;
            addFiles(folder, "", exr ? ".exr" : ".png", frames);
            run.frames[backend] = frames;
        }
    }
    run.ok = true;
    return run;
}

}  // namespace eikon::app
