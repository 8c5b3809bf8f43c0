// `eikon render --stats` and `--stats-json` with the wavefront method: the splits, the patches
// removed at a caustic, and the energy account with the removed power on its own line, as a
// user reading the figures of a render sees them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <regex>
#include <string>

#include "support/run_eikon.h"
#include "support/test_paths.h"

using eikon::test::quoted;
using eikon::test::readFile;
using eikon::test::runEikon;
using eikon::test::scratchDir;
using eikon::test::writeFile;

namespace {

// A glass ball in thin fog under a light from straight above; the paper's rule removes the
// patches that turn inside out at the ball's focus.
const char* kBallInFog = R"({
  "volume": { "bounds": { "min": [-1, -1, -1], "max": [1, 1, 1] }, "resolution": 32 },
  "sources": [
    { "type": "sphere", "field": "n", "center": [0, 0.3, 0], "radius": 0.5, "value": 1.0,
      "falloff": 0.1, "voxel_size": 0.0625 },
    { "type": "box", "field": "density", "min": [-1, -1, -1], "max": [1, 1, 1], "value": 1.0,
      "voxel_size": 0.0625 }
  ],
  "materials": [
    { "name": "glass", "field": "n", "ior": 1.5 },
    { "name": "fog", "field": "density", "absorption": [0.1, 0.1, 0.1],
      "scattering": [0.5, 0.5, 0.5] }
  ],
  "lights": [ { "type": "directional", "direction": [0, -1, 0], "color": [1, 1, 1] } ],
  "camera": { "position": [0, 0, 4], "look_at": [0, 0, 0] },
  "render": { "width": 32, "height": 24,
              "light_transport": { "method": "wavefront",
                                   "wavefront": { "per_side": 24, "max_level": 4,
                                                  "at_caustic": "remove" } } }
})";

// The number after `label` in `text` (a decimal or exponent form), or NaN.
double numberAfter(const std::string& text, const std::string& label) {
    std::smatch m;
    const std::regex pattern(label + " ([-+0-9.eE]+)");
    return std::regex_search(text, m, pattern) ? std::stod(m[1]) : std::nan("");
}

}  // namespace

TEST_CASE("eikon render --stats: the wavefront's splits, removals and energy account",
          "[cli][wavefront]") {
    const std::string dir = scratchDir("cli_wavefront_stats");
    writeFile(dir + "/ball.json", kBallInFog);
    const auto r = runEikon("render " + quoted(dir + "/ball.json") + " --backend cpu -o " +
                                quoted(dir + "/ball.png") + " --stats --stats-json " +
                                quoted(dir + "/stats.json"),
                            dir);
    INFO("stdout:\n" << r.out << "stderr:\n" << r.err);
    REQUIRE(r.exitCode == 0);

    // "wavefront: S split, R refused a split (patch budget), T torn, N removed at caustics"
    std::smatch m;
    REQUIRE(std::regex_search(
        r.out, m,
        std::regex("wavefront: ([0-9]+) split, ([0-9]+) refused a split \\(patch budget\\), "
                   "([0-9]+) torn, ([0-9]+) removed at caustics")));
    CHECK(std::stoll(m[4]) > 0);

    // "wavefront energy: emitted E; extinguished a, escaped b, received c, reflected at surfaces
    // f, dropped d (removed at caustics e); unaccounted u"
    REQUIRE(r.out.find("wavefront energy: emitted") != std::string::npos);
    const double extinguished = numberAfter(r.out, "extinguished");
    const double escaped = numberAfter(r.out, "escaped");
    const double reflected = numberAfter(r.out, "reflected at surfaces");
    const double dropped = numberAfter(r.out, "dropped");
    const double removed = numberAfter(r.out, "\\(removed at caustics");
    const double unaccounted = numberAfter(r.out, "unaccounted");
    // Shares of the emitted power: the fog takes some, most leaves through the faces, and what
    // the rule removes is part of what is dropped.
    CHECK(extinguished > 0.0);
    CHECK(escaped > 0.1);
    CHECK(removed > 0.0);
    CHECK(removed <= dropped);
    // The ball's surface reflects a few percent of what crosses it (0.04 at normal incidence).
    CHECK(reflected > 0.005);
    CHECK(reflected < 0.1);
    CHECK(extinguished + escaped + dropped + reflected == Approx(1.0).margin(1e-3));
    CHECK(std::abs(unaccounted) < 1e-6);

    const std::string json = readFile(dir + "/stats.json");
    for (const char* key : {"particles_split", "particles_removed", "energy_emitted",
                            "energy_extinguished", "energy_escaped", "energy_received",
                            "energy_reflected", "energy_dropped", "energy_removed"}) {
        INFO(key);
        CHECK(json.find(std::string("\"") + key + "\"") != std::string::npos);
    }
}

TEST_CASE(
    "Fresnel off in the wavefront settings or on the material: nothing reflected, bad keys "
    "are named",
    "[cli][wavefront][fresnel]") {
    const std::string dir = scratchDir("cli_wavefront_fresnel");
    auto reflectedShare = [&](const std::string& name, const std::string& scene) {
        writeFile(dir + "/" + name + ".json", scene);
        const auto r =
            runEikon("render " + quoted(dir + "/" + name + ".json") + " --backend cpu --stats -o " +
                         quoted(dir + "/" + name + ".png"),
                     dir);
        INFO(r.out << r.err);
        REQUIRE(r.exitCode == 0);
        return numberAfter(r.out, "reflected at surfaces");
    };
    auto replaced = [](std::string text, const std::string& what, const std::string& with) {
        const size_t at = text.find(what);
        REQUIRE(at != std::string::npos);
        return text.replace(at, what.size(), with);
    };
    const std::string settingOff = replaced(kBallInFog, R"("at_caustic": "remove")",
                                            R"("at_caustic": "remove", "fresnel": false)");
    const std::string materialOff =
        replaced(kBallInFog, R"("ior": 1.5 })", R"("ior": 1.5, "fresnel": false })");
    CHECK(reflectedShare("setting_off", settingOff) == 0.0);
    CHECK(reflectedShare("material_off", materialOff) == 0.0);

    const std::string badSlope =
        replaced(settingOff, R"("fresnel": false)", R"("fresnel": false, "surface_slope": 0.02)");
    writeFile(dir + "/bad.json", badSlope);
    const auto bad = runEikon(
        "render " + quoted(dir + "/bad.json") + " --backend cpu -o " + quoted(dir + "/bad.png"),
        dir);
    CHECK(bad.exitCode == 1);
    CHECK(bad.err.rfind("eikon: ", 0) == 0);
    CHECK(bad.err.find("surface_slope") != std::string::npos);
    CHECK(bad.err.find("needs \"fresnel\": true") != std::string::npos);
    CHECK(std::count(bad.err.begin(), bad.err.end(), '\n') == 1);
}

TEST_CASE("a light that misses the volume: one warning naming it, a dark picture, exit 0",
          "[cli][wavefront][photons]") {
    const std::string dir = scratchDir("cli_light_misses");
    // lights[0], a spot above the box pointing up, reaches nothing; lights[1] does.
    auto scene = [](const std::string& method, const char* spotColor, bool withSun) {
        std::string s = kBallInFog;
        const std::string sun =
            R"({ "type": "directional", "direction": [0, -1, 0], "color": [1, 1, 1] })";
        const std::string spot =
            std::string(
                R"({ "type": "spot", "position": [0, 2, 0], "direction": [0, 1, 0], "color": )") +
            spotColor + R"(, "cone_angle_deg": 20 })";
        s.replace(s.find(sun), sun.size(), withSun ? spot + ", " + sun : spot);
        const std::string wavefront = R"("method": "wavefront")";
        s.replace(s.find(wavefront), wavefront.size(), "\"method\": \"" + method + "\"");
        return s;
    };
    for (const std::string method : {"wavefront", "photons"}) {
        INFO(method);
        writeFile(dir + "/both.json", scene(method, "[1, 1, 1]", true));
        const auto both = runEikon("render " + quoted(dir + "/both.json") +
                                       " --backend cpu --quiet -o " + quoted(dir + "/both.png"),
                                   dir);
        INFO("stderr:\n" << both.err);
        CHECK(both.exitCode == 0);
        CHECK(both.err ==
              "warning: lights[0]: none of its light reaches the volume (it faces away or its "
              "cone misses the box): it lights nothing there\n");

        // Alone, it leaves the picture as a black light does (which is not warned about).
        writeFile(dir + "/away.json", scene(method, "[1, 1, 1]", false));
        writeFile(dir + "/black.json", scene(method, "[0, 0, 0]", false));
        const auto away = runEikon("render " + quoted(dir + "/away.json") +
                                       " --backend cpu --quiet -o " + quoted(dir + "/away.png"),
                                   dir);
        const auto black = runEikon("render " + quoted(dir + "/black.json") +
                                        " --backend cpu --quiet -o " + quoted(dir + "/black.png"),
                                    dir);
        CHECK(away.exitCode == 0);
        CHECK(black.exitCode == 0);
        CHECK(black.err.empty());
        CHECK(readFile(dir + "/away.png") == readFile(dir + "/black.png"));
    }
}
