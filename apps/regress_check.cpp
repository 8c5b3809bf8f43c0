#include "apps/regress_check.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "apps/stats_file.h"
#include "core/error.h"
#include "core/sha256.h"
#include "render/image.h"
#include "render/image_metrics.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);
    return text;
}

Image readImage(const std::string& path) {
    return fs::path(path).extension() == ".exr" ? readExr(path) : readPng(path);
}

// The metrics `t` asks for, between two images of the same size; one reason per bound broken.
std::vector<std::string> imageProblems(const Image& test, const Image& reference, bool linear,
                                       const ImageTolerances& t) {
    std::vector<std::string> out;
    const ImageDifference d = compareImages(test, reference);
    if (t.rmse && d.rmse > *t.rmse)
        out.push_back("rmse " + number(d.rmse) + " > " + number(*t.rmse));
    if (t.maxAbs && d.maxAbs > *t.maxAbs)
        out.push_back("max_abs " + number(d.maxAbs) + " > " + number(*t.maxAbs));
    if (t.meanRelative && d.meanRelative > *t.meanRelative)
        out.push_back("mean_relative " + number(d.meanRelative) + " > " + number(*t.meanRelative));
    if (t.psnr) {
        const double peak = linear ? std::max(d.referenceMax, 1e-30) : 1.0;
        const double p = psnr(test, reference, peak);
        if (!(p >= *t.psnr)) out.push_back("psnr " + number(p) + " dB < " + number(*t.psnr));
    }
    if (t.ssim) {
        const double s = ssim(displayValues(test, !linear), displayValues(reference, !linear));
        if (!(s >= *t.ssim)) out.push_back("ssim " + number(s) + " < " + number(*t.ssim));
    }
    return out;
}

std::string joined(const std::vector<std::string>& parts) {
    std::string s;
    for (const std::string& p : parts) s += (s.empty() ? "" : ", ") + p;
    return s;
}

// Images by metrics; a size that differs is a finding of its own.
void compareImageFiles(const std::string& key, const std::string& testPath,
                       const std::string& referencePath, const ImageTolerances& t,
                       std::vector<Finding>& findings) {
    const bool linear = fs::path(testPath).extension() == ".exr";
    const Image test = readImage(testPath);
    const Image reference = readImage(referencePath);
    Finding f{key, "", referencePath, testPath, linear, {}};
    if (test.width != reference.width || test.height != reference.height) {
        f.reason = "the new image is " + std::to_string(test.width) + "x" +
                   std::to_string(test.height) + ", the reference " +
                   std::to_string(reference.width) + "x" + std::to_string(reference.height);
        f.referenceImage.clear();
        findings.push_back(f);
        return;
    }
    const std::vector<std::string> problems = imageProblems(test, reference, linear, t);
    if (problems.empty()) return;
    f.reason = joined(problems);
    findings.push_back(f);
}

void compareCacheFiles(const std::string& key, const std::string& testPath,
                       const std::string& referencePath, const CacheCheck& check,
                       std::vector<Finding>& findings) {
    const VdbFileDifference d = compareVdbFiles(testPath, referencePath, check.maxAbs, check.grids);
    if (d.within()) return;
    Finding f{key, "", "", "", false, {}};
    std::vector<std::string> parts = d.problems;
    for (const GridDifference& g : d.grids)
        if (g.voxelsOver > 0) {
            parts.push_back("grid '" + g.name + "': " + std::to_string(g.voxelsOver) + " of " +
                            std::to_string(g.voxelsCompared) + " voxels differ by more than " +
                            number(check.maxAbs) + " (largest " + number(g.maxDifference) + ")");
            f.grids.push_back(g);
        }
    f.reason = joined(parts);
    findings.push_back(f);
}

void compareStatFiles(const std::string& key, const std::string& testPath,
                      const std::string& referencePath,
                      const std::map<std::string, StatTolerance>& tolerances,
                      std::vector<Finding>& findings) {
    const std::map<int, FrameCounters> test = readStatsFile(testPath);
    const std::map<int, FrameCounters> reference = readStatsFile(referencePath);
    std::vector<std::string> problems;
    for (const auto& [frame, counters] : reference) {
        const auto t = test.find(frame);
        if (t == test.end()) {
            problems.push_back("frame " + std::to_string(frame) + " has no counters");
            continue;
        }
        for (const auto& [name, tol] : tolerances) {
            const auto r = counters.find(name);
            const auto n = t->second.find(name);
            if (r == counters.end() && n == t->second.end()) continue;  // not counted this frame
            if (r == counters.end() || n == t->second.end()) {
                problems.push_back("frame " + std::to_string(frame) + " " + name + ": counted in " +
                                   (r == counters.end() ? "the new run" : "the reference") +
                                   " only");
                continue;
            }
            const double allowed = tol.absolute + tol.relative * std::fabs(r->second);
            if (!(std::fabs(n->second - r->second) <= allowed))
                problems.push_back("frame " + std::to_string(frame) + " " + name + " " +
                                   number(n->second) + ", reference " + number(r->second) +
                                   " (allowed ±" + number(allowed) + ")");
        }
    }
    for (const auto& [frame, counters] : test)
        if (!reference.count(frame))
            problems.push_back("frame " + std::to_string(frame) + " is not in the reference");
    if (problems.size() > 4) {
        const size_t more = problems.size() - 3;
        problems.resize(3);
        problems.push_back("and " + std::to_string(more) + " more");
    }
    if (!problems.empty()) findings.push_back({key, joined(problems), "", "", false, {}});
}

bool comparedByHash(const RegressCase& c, const std::string& kind) {
    if (kind == "png") return c.png && c.png->hash;
    if (kind == "exr") return c.exr && c.exr->hash;
    if (kind == "cache") return c.cache && c.cache->hash;
    return false;
}

}  // namespace

std::set<std::string> hashOnlyOutputs(const RegressCase& c, const CaseRun& run) {
    std::set<std::string> keys;
    for (const auto& [key, path] : run.outputs)
        if (outputKind(key) == "cache" && comparedByHash(c, "cache")) keys.insert(key);
    return keys;
}

std::vector<Finding> checkCase(const RegressCase& c, const CaseRun& run,
                               const ReferenceManifest& references, const std::string& suiteArg) {
    std::vector<Finding> findings;
    const std::string howToCreate =
        "create it with: eikon regress " + suiteArg + " " + c.name + " --update";
    std::set<std::string> keys;
    for (const auto& [key, path] : run.outputs) keys.insert(key);
    for (const std::string& key : references.keysOfCase(c.name)) keys.insert(key);
    for (const std::string& key : keys) {
        const auto output = run.outputs.find(key);
        const std::optional<std::string> hash = references.hashOf(key);
        const std::string referencePath = (fs::path(references.folder()) / key).string();
        if (output == run.outputs.end()) {
            findings.push_back({key,
                                "the reference has this output, the new run did not write it",
                                "",
                                "",
                                false,
                                {}});
            continue;
        }
        if (!hash) {
            findings.push_back(
                {key, "no reference; " + howToCreate, "", output->second, false, {}});
            continue;
        }
        const std::string kind = outputKind(key);
        const std::string newHash = sha256OfFile(output->second);
        if (comparedByHash(c, kind)) {
            if (newHash == *hash) continue;
            // The reference file, when kept, is only for the report's pictures.
            const bool kept = fs::exists(referencePath);
            findings.push_back({key,
                                "SHA-256 " + newHash.substr(0, 12) +
                                    "… differs from the reference's " + hash->substr(0, 12) + "…",
                                kept && kind != "cache" ? referencePath : "",
                                kind != "cache" ? output->second : "",
                                kind == "exr",
                                {}});
            continue;
        }
        if (!fs::exists(referencePath)) {
            findings.push_back({key,
                                "reference file " + referencePath + " is missing; " + howToCreate,
                                "",
                                "",
                                false,
                                {}});
            continue;
        }
        if (sha256OfFile(referencePath) != *hash) {
            findings.push_back({key,
                                "reference file " + referencePath +
                                    " is corrupt or was changed: its SHA-256 is not the "
                                    "manifest's; restore it or " +
                                    howToCreate,
                                "",
                                "",
                                false,
                                {}});
            continue;
        }
        if (newHash == *hash) continue;  // the same bytes pass every tolerance
        try {
            if (kind == "png")
                compareImageFiles(key, output->second, referencePath, c.png->tolerances, findings);
            else if (kind == "exr")
                compareImageFiles(key, output->second, referencePath, c.exr->tolerances, findings);
            else if (kind == "cache")
                compareCacheFiles(key, output->second, referencePath, *c.cache, findings);
            else if (kind == "render_stats")
                compareStatFiles(key, output->second, referencePath, c.renderStats, findings);
            else if (kind == "simulation_stats")
                compareStatFiles(key, output->second, referencePath, c.simulationStats, findings);
        } catch (const Error& e) {
            findings.push_back({key, e.what(), "", "", false, {}});
        }
    }
    // Each backend after the first against the first, frame by frame, without references.
    if (c.acrossBackends) {
        const std::string& first = c.backends.front();
        for (size_t b = 1; b < c.backends.size(); ++b) {
            const auto& base = run.frames.at(first);
            const auto& other = run.frames.at(c.backends[b]);
            for (const auto& [name, path] : base) {
                const std::string key = c.name + "/" + first + " vs " + c.backends[b] + " " + name;
                const auto o = other.find(name);
                if (o == other.end()) {
                    findings.push_back(
                        {key, c.backends[b] + " did not write it", "", "", false, {}});
                    continue;
                }
                try {
                    compareImageFiles(key, o->second, path, *c.acrossBackends, findings);
                } catch (const Error& e) {
                    findings.push_back({key, e.what(), "", "", false, {}});
                }
            }
        }
    }
    return findings;
}

}  // namespace eikon::app
