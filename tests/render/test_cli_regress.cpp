// `eikon regress` (issue 19): a suite of cases against their references. Each test builds a small
// suite in a scratch folder (cheap scenes at tiny sizes), writes references with --update, then
// breaks one thing and checks the line, the exit status, the JUnit XML and the HTML report say
// what broke — and that the other cases still ran and no reference was overwritten by a failure.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>

#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::contains;
using eikon::test::lines;
using eikon::test::quoted;
using eikon::test::readFile;
using eikon::test::runEikon;
using eikon::test::RunResult;
using eikon::test::scratchDir;
using eikon::test::writeFile;
namespace fs = std::filesystem;

namespace {

const std::string kCube = eikon::test::sourcePath("data/scenes/homogeneous_cube.json");

// A case rendering `scene` (absolute) on the CPU twin, comparing `compare` (JSON).
void writeCase(const std::string& suite, const std::string& name, const std::string& scene,
               const std::string& compare, const std::string& size = "24x16") {
    writeFile(suite + "/" + name + ".json", "{\"input\": \"" + scene + "\", \"size\": \"" + size +
                                                "\", \"compare\": " + compare + "}\n");
}

RunResult regress(const std::string& dir, const std::string& args) {
    return runEikon("regress " + args, dir);
}

// The case's result line: its status word, or empty when there is no line for it.
std::string lineOf(const RunResult& r, const std::string& name) {
    for (const std::string& l : lines(r.out)) {
        std::smatch m;
        if (std::regex_match(l, m, std::regex("(\\S+) +(\\S+) +[0-9.]+ s(.*)")) && m[2] == name)
            return l;
    }
    return "";
}

bool startsWith(const std::string& s, const std::string& prefix) {
    return s.rfind(prefix, 0) == 0;
}

// The same scene with its cube's absorption changed: a different picture.
std::string writeDarkerCube(const std::string& dir) {
    std::string text = readFile(kCube);
    const std::regex absorption("\"absorption\": *\\[[^\\]]*\\]");
    std::smatch m;
    REQUIRE(std::regex_search(text, m, absorption));
    text.replace(size_t(m.position(0)), size_t(m.length(0)), "\"absorption\": [2.0, 2.0, 2.0]");
    const std::string path = dir + "/darker_cube.json";
    writeFile(path, text);
    return path;
}

}  // namespace

TEST_CASE("eikon regress: update writes references and a manifest, a rerun passes", "[regress]") {
    const std::string dir = scratchDir("regress_update");
    const std::string suite = dir + "/suite";
    fs::create_directories(suite);
    writeCase(suite, "by_hash", kCube, "{\"png\": \"hash\"}");
    writeCase(suite, "by_metrics", kCube,
              "{\"exr\": {\"rmse\": 1e-6, \"ssim\": 0.999, \"psnr\": 60}, \"render_stats\": "
              "{\"width\": {\"absolute\": 0}}}");
    const RunResult u = regress(dir, quoted(suite) + " --update");
    INFO(u.out << u.err);
    REQUIRE(u.exitCode == 0);
    CHECK(startsWith(lineOf(u, "by_hash"), "updated"));
    const std::string manifest = readFile(suite + "/references/SHA256SUMS");
    CHECK(contains(manifest, "  by_hash/cpu/frame_0000.png\n"));
    CHECK(contains(manifest, "  by_metrics/cpu/frame_0000.exr\n"));
    CHECK(contains(manifest, "  by_metrics/cpu/render_stats.json\n"));
    CHECK_FALSE(contains(manifest, "by_hash/cpu/frame_0000.exr"));  // only what is compared
    CHECK(fs::exists(suite + "/references/by_metrics/cpu/frame_0000.exr"));

    const RunResult r = regress(dir, quoted(suite) + " -j 2 --junit " + quoted(dir + "/j.xml"));
    INFO(r.out << r.err);
    CHECK(r.exitCode == 0);
    CHECK(startsWith(lineOf(r, "by_hash"), "pass"));
    CHECK(startsWith(lineOf(r, "by_metrics"), "pass"));
    CHECK(contains(r.out, "2 cases, 2 passed, 0 failed, 0 errors"));
    const std::string junit = readFile(dir + "/j.xml");
    CHECK(contains(junit, "tests=\"2\" failures=\"0\" errors=\"0\""));
    CHECK(contains(junit, "<testcase classname="));

    // One case at a time: the same lines but for the times.
    const RunResult one = regress(dir, quoted(suite) + " -j 1");
    const auto withoutTimes = [](const std::string& out) {
        return std::regex_replace(out, std::regex("[0-9]+\\.[0-9] s"), "T s");
    };
    CHECK(withoutTimes(one.out) == withoutTimes(r.out));
}

TEST_CASE("eikon regress: a broken case fails with a clear report, the others still pass",
          "[regress]") {
    const std::string dir = scratchDir("regress_broken");
    const std::string suite = dir + "/suite";
    fs::create_directories(suite);
    writeCase(suite, "cube_png", kCube, "{\"png\": \"hash\"}");
    writeCase(suite, "cube_exr", kCube, "{\"exr\": {\"rmse\": 1e-4, \"ssim\": 0.99}}");
    writeCase(suite, "unchanged", kCube, "{\"png\": \"hash\"}");
    REQUIRE(regress(dir, quoted(suite) + " --update").exitCode == 0);

    // The same cases now render a different scene: their outputs no longer match.
    const std::string darker = writeDarkerCube(dir);
    writeCase(suite, "cube_png", darker, "{\"png\": \"hash\"}");
    writeCase(suite, "cube_exr", darker, "{\"exr\": {\"rmse\": 1e-4, \"ssim\": 0.99}}");
    const std::string report = dir + "/report";
    const RunResult r = regress(
        dir, quoted(suite) + " --report " + quoted(report) + " --junit " + quoted(dir + "/j.xml"));
    INFO(r.out << r.err);
    CHECK(r.exitCode == 1);
    CHECK(startsWith(lineOf(r, "cube_png"), "FAIL"));
    CHECK(contains(lineOf(r, "cube_png"), "cube_png/cpu/frame_0000.png: SHA-256"));
    CHECK(startsWith(lineOf(r, "cube_exr"), "FAIL"));
    CHECK(std::regex_search(lineOf(r, "cube_exr"), std::regex("rmse [0-9.e-]+ > 0.0001")));
    CHECK(std::regex_search(lineOf(r, "cube_exr"), std::regex("ssim [0-9.e-]+ < 0.99")));
    CHECK(startsWith(lineOf(r, "unchanged"), "pass"));
    CHECK(contains(r.out, "3 cases, 1 passed, 2 failed, 0 errors"));
    CHECK(contains(r.out, "report: " + report + "/index.html"));

    const std::string html = readFile(report + "/index.html");
    CHECK(contains(html, "cube_exr/cpu/frame_0000.exr"));
    for (const char* picture : {"reference", "new", "difference"}) {
        INFO(picture);
        CHECK(contains(html, std::string("_") + picture + ".png"));
    }
    int pictures = 0;
    for (const auto& e : fs::directory_iterator(report + "/images"))
        pictures += e.path().extension() == ".png";
    CHECK(pictures == 6);  // reference, new and difference of both failed images
    const std::string junit = readFile(dir + "/j.xml");
    CHECK(contains(junit, "tests=\"3\" failures=\"2\" errors=\"0\""));
    CHECK(contains(junit, "<failure message=\"cube_exr/cpu/frame_0000.exr: rmse"));
}

TEST_CASE("eikon regress: missing, resized and corrupt references each fail with their reason",
          "[regress]") {
    const std::string dir = scratchDir("regress_references");
    const std::string suite = dir + "/suite";
    fs::create_directories(suite);
    const std::string metrics = "{\"exr\": {\"max_abs\": 1e-3}}";
    writeCase(suite, "resized", kCube, metrics);
    writeCase(suite, "corrupt", kCube, metrics);
    REQUIRE(regress(dir, quoted(suite) + " --update").exitCode == 0);
    writeCase(suite, "missing", kCube, metrics);  // never updated
    writeCase(suite, "resized", kCube, metrics, "20x12");
    {  // a byte of the reference changed behind the manifest's back
        const std::string path = suite + "/references/corrupt/cpu/frame_0000.exr";
        std::string bytes = readFile(path);
        bytes[bytes.size() / 2] ^= 0x5a;
        writeFile(path, bytes);
    }
    const RunResult r = regress(dir, quoted(suite));
    INFO(r.out << r.err);
    CHECK(r.exitCode == 1);
    CHECK(contains(lineOf(r, "missing"),
                   "missing/cpu/frame_0000.exr: no reference; create it with: eikon regress " +
                       suite + " missing --update"));
    CHECK(contains(lineOf(r, "resized"), "the new image is 20x12, the reference 24x16"));
    CHECK(contains(lineOf(r, "corrupt"), "is corrupt or was changed"));
    CHECK(contains(r.out, "3 cases, 0 passed, 3 failed, 0 errors"));
}

TEST_CASE("eikon regress: a case that cannot run is an error and --update keeps its references",
          "[regress]") {
    const std::string dir = scratchDir("regress_errors");
    const std::string suite = dir + "/suite";
    fs::create_directories(suite);
    const std::string scene = dir + "/scene.json";
    fs::copy_file(kCube, scene);
    writeCase(suite, "scene_breaks", scene, "{\"png\": \"hash\"}");
    writeCase(suite, "fine", kCube, "{\"png\": \"hash\"}");
    REQUIRE(regress(dir, quoted(suite) + " --update").exitCode == 0);
    const std::string reference = suite + "/references/scene_breaks/cpu/frame_0000.png";
    const std::string before = readFile(reference);
    const std::string manifest = readFile(suite + "/references/SHA256SUMS");

    writeFile(scene, "{\"camera\": {\"fov\": 40}");  // cut short
    writeFile(suite + "/typo.json",
              "{\"input\": \"" + kCube + "\", \"compare\": {\"pgn\": \"hash\"}}");
    for (const std::string& update : {std::string(""), std::string(" --update")}) {
        INFO("with" << update);
        const RunResult r = regress(dir, quoted(suite) + update);
        INFO(r.out << r.err);
        CHECK(r.exitCode == 1);
        const std::string broken = lineOf(r, "scene_breaks");
        CHECK(startsWith(broken, "ERROR"));
        CHECK(contains(broken, "render exit status 1: eikon: " + scene + ":"));
        const std::string typo = lineOf(r, "typo");
        CHECK(startsWith(typo, "ERROR"));
        CHECK(contains(typo, "/compare/pgn"));
        CHECK(contains(typo, "did you mean 'png'"));
        CHECK((startsWith(lineOf(r, "fine"), "pass") || startsWith(lineOf(r, "fine"), "updated")));
        CHECK(readFile(reference) == before);
    }
    CHECK(readFile(suite + "/references/SHA256SUMS") == manifest);
}

TEST_CASE("eikon regress: bad suites and case names are one-line errors", "[regress]") {
    const std::string dir = scratchDir("regress_usage");
    eikon::test::checkOneLineError(regress(dir, quoted(dir + "/nowhere")), dir + "/nowhere: ");
    const std::string suite = dir + "/suite";
    fs::create_directories(suite);
    eikon::test::checkOneLineError(regress(dir, quoted(suite)), suite + ": ");  // no cases
    writeCase(suite, "glass", kCube, "{\"png\": \"hash\"}");
    const RunResult r = regress(dir, quoted(suite) + " glas");
    eikon::test::checkOneLineError(r, suite + ": ");
    CHECK(contains(r.err, "no case 'glas' (did you mean 'glass'?)"));
    fs::create_directories(suite + "/references");
    writeFile(suite + "/references/SHA256SUMS", "not a manifest line\n");
    eikon::test::checkOneLineError(regress(dir, quoted(suite)),
                                   suite + "/references/SHA256SUMS:1: ");
}

TEST_CASE("eikon regress: a case that hangs is killed at its timeout and the others run",
          "[regress]") {
    const std::string dir = scratchDir("regress_timeout");
    const std::string suite = dir + "/suite";
    fs::create_directories(suite);
    // A scene that is a named pipe nobody writes: eikon render waits on it for ever.
    const std::string pipe = dir + "/never.json";
    REQUIRE(mkfifo(pipe.c_str(), 0644) == 0);
    writeFile(suite + "/hangs.json", "{\"input\": \"" + pipe +
                                         "\", \"timeout_seconds\": 1, \"compare\": "
                                         "{\"png\": \"hash\"}}");
    writeCase(suite, "fine", kCube, "{\"png\": \"hash\"}");
    const RunResult r = regress(dir, quoted(suite) + " -j 2");
    INFO(r.out << r.err);
    CHECK(r.exitCode == 1);
    CHECK(contains(lineOf(r, "hangs"), "ERROR"));
    CHECK(contains(lineOf(r, "hangs"), "render timed out after 1 s"));
    CHECK(contains(lineOf(r, "fine"), "FAIL"));  // it ran: no reference yet
}
