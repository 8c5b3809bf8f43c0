#include "apps/regress_case.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.h"
#include "core/json_reader.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

ImageTolerances readTolerances(const json::Value& value, const std::string& kind) {
    json::Object o(value, kind);
    ImageTolerances t;
    const json::Range nonNegative = json::Range::atLeast(0.0);
    if (auto v = o.optional("rmse")) t.rmse = v->number(nonNegative);
    if (auto v = o.optional("max_abs")) t.maxAbs = v->number(nonNegative);
    if (auto v = o.optional("mean_relative")) t.meanRelative = v->number(nonNegative);
    if (auto v = o.optional("psnr")) t.psnr = v->number(json::Range::any());
    if (auto v = o.optional("ssim")) t.ssim = v->number(json::Range::closed(-1.0, 1.0));
    o.finish();
    if (!t.rmse && !t.maxAbs && !t.meanRelative && !t.psnr && !t.ssim)
        value.fail(
            "give at least one of rmse, max_abs, mean_relative, psnr (least dB), ssim "
            "(least), or \"hash\" instead of the object");
    return t;
}

ImageCheck readImageCheck(const json::Value& value, const std::string& kind) {
    ImageCheck c;
    if (value.json().is_string()) {
        value.choice({"hash"});
        c.hash = true;
        return c;
    }
    if (!value.isObject()) value.failExpected("\"hash\" or an object of tolerances");
    c.tolerances = readTolerances(value, kind);
    return c;
}

CacheCheck readCacheCheck(const json::Value& value) {
    CacheCheck c;
    if (value.json().is_string()) {
        value.choice({"hash"});
        c.hash = true;
        return c;
    }
    if (!value.isObject()) value.failExpected("\"hash\" or {\"max_abs\": ..., \"grids\": [...]}");
    json::Object o(value, "a cache comparison");
    c.maxAbs = o.required("max_abs", "a number >= 0").number(json::Range::atLeast(0.0));
    if (auto grids = o.optional("grids"))
        for (const json::Value& g : grids->elements("an array of grid names", 64))
            c.grids.push_back(g.nonEmptyString());
    o.finish();
    return c;
}

std::map<std::string, StatTolerance> readStats(const json::Value& value) {
    std::map<std::string, StatTolerance> out;
    if (!value.isObject()) value.failExpected("an object of counters and their tolerances");
    for (const auto& item : value.json().items()) {
        const json::Value v = value.child(item.key());
        json::Object o(v, "a counter's tolerance");
        StatTolerance t;
        if (auto a = o.optional("absolute")) t.absolute = a->number(json::Range::atLeast(0.0));
        if (auto r = o.optional("relative")) t.relative = r->number(json::Range::atLeast(0.0));
        o.finish();
        out[item.key()] = t;
    }
    return out;
}

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path, "cannot open the case file");
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

RegressCase loadRegressCase(const std::string& path) {
    const std::string text = readText(path);
    const json::Json doc = json::parseDocument(text, path);
    const json::Value root(doc, path, "");
    if (!root.isObject()) root.failExpected("an object (a regression case)");
    json::Object o(root, "a regression case");
    RegressCase c;
    c.file = path;
    c.name = fs::path(path).stem().string();
    if (auto d = o.optional("description")) c.description = d->string();
    const std::string input = o.required("input", "a scene or VDB file").nonEmptyString();
    c.input = (fs::path(path).parent_path() / input).lexically_normal().string();
    if (auto f = o.optional("frames")) c.frames = f->nonEmptyString();
    if (auto s = o.optional("size")) c.size = s->nonEmptyString();
    if (auto b = o.optional("backends")) {
        c.backends.clear();
        for (const json::Value& e : b->elements("an array of backends", 2)) {
            const std::string backend = e.choice({"cpu", "gpu"});
            if (std::find(c.backends.begin(), c.backends.end(), backend) != c.backends.end())
                e.fail("backend '" + backend + "' is listed twice");
            c.backends.push_back(backend);
        }
        if (c.backends.empty()) b->fail("name at least one backend: \"cpu\" or \"gpu\"");
    }
    if (auto t = o.optional("timeout_seconds")) c.timeoutSeconds = int(t->integer(1, 86400));
    const json::Value compare = o.required("compare", "an object: what to compare");
    json::Object cmp(compare, "a comparison");
    if (auto v = cmp.optional("png")) c.png = readImageCheck(*v, "PNG tolerances");
    if (auto v = cmp.optional("exr")) c.exr = readImageCheck(*v, "EXR tolerances");
    if (auto v = cmp.optional("cache")) c.cache = readCacheCheck(*v);
    if (auto v = cmp.optional("render_stats")) c.renderStats = readStats(*v);
    if (auto v = cmp.optional("simulation_stats")) c.simulationStats = readStats(*v);
    if (auto v = cmp.optional("backends")) {
        c.acrossBackends = readTolerances(*v, "tolerances between backends");
        if (c.backends.size() < 2)
            v->fail("comparing backends needs two: \"backends\": [\"cpu\", \"gpu\"]");
    }
    cmp.finish();
    if (!c.renders() && !c.simulates())
        compare.fail(
            "compare at least one of png, exr, cache, render_stats, simulation_stats, "
            "backends");
    o.finish();
    return c;
}

std::vector<SuiteEntry> listSuite(const std::string& suiteDir,
                                  const std::vector<std::string>& only) {
    std::error_code ec;
    if (!fs::is_directory(suiteDir, ec))
        throw Error(suiteDir, "not a folder (a suite is a folder of case files)");
    std::vector<SuiteEntry> all;
    for (const auto& e : fs::directory_iterator(suiteDir, ec))
        if (e.path().extension() == ".json" && e.is_regular_file(ec))
            all.push_back({e.path().stem().string(), e.path().string()});
    if (ec) throw Error(suiteDir, "cannot list the folder: " + ec.message());
    std::sort(all.begin(), all.end(),
              [](const SuiteEntry& a, const SuiteEntry& b) { return a.name < b.name; });
    if (all.empty()) throw Error(suiteDir, "no case files (*.json) in the suite folder");
    if (only.empty()) return all;
    std::vector<SuiteEntry> chosen;
    std::vector<std::string> names;
    for (const SuiteEntry& e : all) names.push_back(e.name);
    for (const std::string& name : only) {
        const auto it = std::find_if(all.begin(), all.end(),
                                     [&](const SuiteEntry& e) { return e.name == name; });
        if (it == all.end()) {
            const std::string hint = json::closestMatch(name, names);
            throw Error(suiteDir, "no case '" + name + "'" +
                                      (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
        }
        if (std::find_if(chosen.begin(), chosen.end(),
                         [&](const SuiteEntry& e) { return e.name == name; }) == chosen.end())
            chosen.push_back(*it);
    }
    return chosen;
}

}  // namespace eikon::app
