// `eikon regress SUITE [CASE...]`: a user's deterministic sim-plus-render regression tests
// (docs/regress.md). Each case runs as child processes of this binary (apps/regress_run.h), so a
// crash or a hang is that case's error and the others go on; with -j N cases run N at a time and
// every result is the same as with -j 1.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "apps/commands.h"
#include "apps/regress_case.h"
#include "apps/regress_check.h"
#include "apps/regress_references.h"
#include "apps/regress_report.h"
#include "apps/regress_run.h"
#include "apps/subprocess.h"
#include "core/error.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

struct RegressOptions {
    std::string suite;
    std::vector<std::string> cases;
    bool update = false;
    int jobs = 1;
    std::string report;  // --report DIR
    std::string junit;   // --junit FILE
    std::string work;    // --work DIR: keep every case's outputs there
};

// One case from its file to its result. `manifest` is shared: --update changes it under `lock`.
CaseResult runOne(const SuiteEntry& entry, const RegressOptions& o, const std::string& eikon,
                  const std::string& workDir, ReferenceManifest& manifest, std::mutex& lock) {
    CaseResult result;
    result.name = entry.name;
    result.logPath = (fs::path(workDir) / entry.name / "log.txt").string();
    const auto start = std::chrono::steady_clock::now();
    try {
        const RegressCase c = loadRegressCase(entry.path);
        result.description = c.description;
        const CaseRun run = runCase(c, eikon, (fs::path(workDir) / c.name).string());
        if (!run.ok) {
            // A failed render never becomes a reference, with --update or without.
            result.status = CaseStatus::Error;
            result.reason = run.reason;
        } else if (o.update) {
            const auto hashes =
                installReferences(manifest.folder(), c.name, run.outputs, hashOnlyOutputs(c, run));
            std::lock_guard<std::mutex> guard(lock);
            manifest.replaceCase(c.name, hashes);
            manifest.save();
            result.status = CaseStatus::Updated;
            result.reason = std::to_string(hashes.size()) + " reference file(s)";
        } else {
            // No lock: without --update no case changes the manifest, and the comparisons (SSIM,
            // grids voxel by voxel) run in parallel with -j.
            result.findings = checkCase(c, run, manifest, o.suite);
            result.status = result.findings.empty() ? CaseStatus::Pass : CaseStatus::Fail;
            if (!result.findings.empty()) {
                result.reason = result.findings.front().key + ": " + result.findings.front().reason;
                if (result.findings.size() > 1)
                    result.reason +=
                        " (and " + std::to_string(result.findings.size() - 1) + " more)";
            }
        }
    } catch (const Error& e) {
        result.status = CaseStatus::Error;
        result.reason = e.what();
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

void printResult(const CaseResult& r) {
    std::printf("%-8s %-28s %7.1f s%s%s\n", statusWord(r.status), r.name.c_str(), r.seconds,
                r.reason.empty() ? "" : "  ", r.reason.c_str());
    std::fflush(stdout);
}

void createFolder(const std::string& folder) {
    if (folder.empty()) return;
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) throw Error(folder, "cannot create the folder: " + ec.message());
}

// A folder for the cases' outputs that nothing else uses: --work, or a new one under the
// system's temporary folder (removed afterwards).
std::string makeWorkDir(const RegressOptions& o, bool& temporary) {
    temporary = o.work.empty();
    if (!temporary) return o.work;
    const fs::path base = fs::temp_directory_path() / "eikon-regress-XXXXXX";
    std::string pattern = base.string();
    if (!mkdtemp(pattern.data()))
        throw Error(base.parent_path().string(), "cannot create a work folder for the cases");
    return pattern;
}

int runRegress(const RegressOptions& o) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<SuiteEntry> entries = listSuite(o.suite, o.cases);
    // The folders of what is written at the end, before any case runs: a report that cannot be
    // written fails now, not after the suite.
    createFolder(o.report);
    if (!o.junit.empty()) createFolder(fs::path(o.junit).parent_path().string());
    ReferenceManifest manifest(o.suite);
    const std::string eikon = selfExecutable();
    bool temporary = false;
    const std::string workDir = makeWorkDir(o, temporary);

    std::vector<CaseResult> results(entries.size());
    std::vector<bool> done(entries.size(), false);
    size_t printed = 0;
    std::mutex lock, printLock;
    std::atomic<size_t> next{0};
    const auto worker = [&] {
        for (size_t i = next++; i < entries.size(); i = next++) {
            CaseResult r = runOne(entries[i], o, eikon, workDir, manifest, lock);
            std::lock_guard<std::mutex> guard(printLock);
            results[i] = std::move(r);
            done[i] = true;
            // Lines in the suite's order, each as soon as the cases before it are done.
            while (printed < entries.size() && done[printed]) printResult(results[printed++]);
        }
    };
    std::vector<std::thread> threads;
    for (int j = 1; j < std::min<int>(o.jobs, int(entries.size())); ++j)
        threads.emplace_back(worker);
    worker();
    for (std::thread& t : threads) t.join();

    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int passed = 0, failed = 0, errors = 0, updated = 0;
    for (const CaseResult& r : results) {
        passed += r.status == CaseStatus::Pass;
        failed += r.status == CaseStatus::Fail;
        errors += r.status == CaseStatus::Error;
        updated += r.status == CaseStatus::Updated;
    }
    if (!o.junit.empty()) writeJUnit(o.junit, o.suite, results, seconds);
    if (!o.report.empty()) writeHtmlReport(o.report, o.suite, results, seconds);
    if (o.update)
        std::printf("%s: %zu cases, %d updated, %d errors (references unchanged) in %.1f s\n",
                    o.suite.c_str(), results.size(), updated, errors, seconds);
    else
        std::printf("%s: %zu cases, %d passed, %d failed, %d errors in %.1f s%s\n", o.suite.c_str(),
                    results.size(), passed, failed, errors, seconds,
                    o.report.empty() || passed == int(results.size())
                        ? ""
                        : ("; report: " + o.report + "/index.html").c_str());
    if (temporary) {
        std::error_code ec;
        fs::remove_all(workDir, ec);
    }
    return failed + errors == 0 ? 0 : 1;
}

}  // namespace

void addRegressCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand(
        "regress", "Run a folder of regression cases against their references (docs/regress.md)");
    auto o = std::make_shared<RegressOptions>();
    cmd->add_option("suite", o->suite, "folder of case files (*.json) and their references/")
        ->required();
    cmd->add_option("cases", o->cases, "only these cases (file names without .json)");
    cmd->add_flag("--update", o->update,
                  "write the references of the cases run (all, or those named) from this run's "
                  "outputs; a case that fails to run keeps its old references");
    cmd->add_option("-j,--jobs", o->jobs, "cases run at a time (results do not depend on it)")
        ->check(CLI::Range(1, 256));
    cmd->add_option("--report", o->report,
                    "write DIR/index.html: each failed image beside its reference with a heat map "
                    "of the difference, each failed grid's worst voxels, each error's log");
    cmd->add_option("--junit", o->junit, "write JUnit XML to FILE (for CI systems)");
    cmd->add_option("--work", o->work,
                    "keep every case's outputs and log in DIR/CASE/ (default: a temporary folder, "
                    "removed)");
    cmd->footer(
        "Exit status: 0 when every case passes, 1 otherwise.\nExamples (from the repository "
        "root):\n  eikon regress tests/regress -j 2\n  eikon regress tests/regress glass_sphere "
        "--update\n  eikon regress tests/regress --report out/regress --junit out/regress.xml\n");
    cmd->callback([o, &exitCode] { exitCode = runRegress(*o); });
}

}  // namespace eikon::app
