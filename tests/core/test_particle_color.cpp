// Particle colour (core/particle_color.h): the named maps against matplotlib's published end
// colours, the sRGB decoding, points interpolated and flat beyond, the table the shaders read, and
// the scene's forms and errors.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/particle_color.h"
#include "core/scene.h"

using Catch::Matchers::Contains;
using eikon::ParticleColorSpec;

namespace {

// A colour given as a web hex code (display values), decoded to linear as the maps are.
glm::vec3 linearHex(int r, int g, int b) {
    return {eikon::srgbToLinear(float(r) / 255.0f), eikon::srgbToLinear(float(g) / 255.0f),
            eikon::srgbToLinear(float(b) / 255.0f)};
}

// Within half a step of the 8-bit code, measured in display values.
void checkNearHex(glm::vec3 linear, int r, int g, int b) {
    const glm::vec3 expected = linearHex(r, g, b);
    for (int c = 0; c < 3; ++c) {
        INFO("channel " << c << ": " << linear[c] << " against " << expected[c]);
        const auto display = [](float x) {
            return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
        };
        CHECK(std::abs(display(linear[c]) - display(expected[c])) <= 0.5f / 255.0f + 1e-6f);
    }
}

ParticleColorSpec named(const std::string& map, float lo = 0.0f, float hi = 1.0f) {
    ParticleColorSpec s;
    s.map = map;
    s.range = glm::vec2(lo, hi);
    return s;
}

}  // namespace

TEST_CASE("The named colour maps end on matplotlib's published colours", "[particle_color]") {
    // viridis #440154 → #FDE725, inferno #000004 → #FCFFA4, magma #000004 → #FCFDBF,
    // plasma #0D0887 → #F0F921, cividis #00224E → #FEE838 (matplotlib's _cm_listed.py ends).
    checkNearHex(eikon::particleColorAt(named("viridis"), 0.0f), 0x44, 0x01, 0x54);
    checkNearHex(eikon::particleColorAt(named("viridis"), 1.0f), 0xFD, 0xE7, 0x25);
    checkNearHex(eikon::particleColorAt(named("inferno"), 0.0f), 0x00, 0x00, 0x04);
    checkNearHex(eikon::particleColorAt(named("inferno"), 1.0f), 0xFC, 0xFF, 0xA4);
    checkNearHex(eikon::particleColorAt(named("magma"), 1.0f), 0xFC, 0xFD, 0xBF);
    checkNearHex(eikon::particleColorAt(named("plasma"), 0.0f), 0x0D, 0x08, 0x87);
    checkNearHex(eikon::particleColorAt(named("plasma"), 1.0f), 0xF0, 0xF9, 0x21);
    checkNearHex(eikon::particleColorAt(named("cividis"), 0.0f), 0x00, 0x22, 0x4E);
    checkNearHex(eikon::particleColorAt(named("gray"), 0.5f), 0x80, 0x80, 0x80);
    // The range stretches the map: its middle at the middle of [2, 6], flat beyond.
    CHECK(eikon::particleColorAt(named("viridis", 2.0f, 6.0f), 4.0f) ==
          eikon::particleColorAt(named("viridis"), 0.5f));
    CHECK(eikon::particleColorAt(named("viridis", 2.0f, 6.0f), -9.0f) ==
          eikon::particleColorAt(named("viridis"), 0.0f));
    CHECK(eikon::particleColorAt(named("viridis", 2.0f, 6.0f), 60.0f) ==
          eikon::particleColorAt(named("viridis"), 1.0f));
    CHECK(eikon::colorMapNames().size() == 8);
}

TEST_CASE("sRGB decoding: the standard's curve and its linear toe", "[particle_color]") {
    CHECK(eikon::srgbToLinear(0.0f) == 0.0f);
    CHECK(eikon::srgbToLinear(1.0f) == Approx(1.0f).epsilon(1e-6));
    CHECK(eikon::srgbToLinear(0.04f) == Approx(0.04f / 12.92f).epsilon(1e-6));
    CHECK(eikon::srgbToLinear(0.5f) == Approx(0.2140411f).epsilon(1e-5));  // IEC 61966-2-1
}

TEST_CASE("Particle colour points: linear between them, flat beyond, and the table",
          "[particle_color]") {
    ParticleColorSpec s;
    s.points = {{0.2f, 1.0f, 0.0f, 0.0f}, {0.6f, 0.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 2.0f, 0.0f}};
    CHECK(eikon::particleColorAt(s, -1.0f) == glm::vec3(1.0f, 0.0f, 0.0f));
    CHECK(eikon::particleColorAt(s, std::numeric_limits<float>::quiet_NaN()) ==
          glm::vec3(1.0f, 0.0f, 0.0f));
    const glm::vec3 mid = eikon::particleColorAt(s, 0.4f);
    CHECK(mid.r == Approx(0.5f));
    CHECK(mid.b == Approx(0.5f));
    CHECK(eikon::particleColorAt(s, 0.6f) == glm::vec3(0.0f, 0.0f, 1.0f));
    CHECK(eikon::particleColorAt(s, 0.9f).g == Approx(1.5f));
    CHECK(eikon::particleColorAt(s, 3.0f) == glm::vec3(0.0f, 2.0f, 0.0f));
    CHECK(eikon::particleColorRange(s) == glm::vec2(0.2f, 1.0f));
    // The table: evenly over [0.2, 1]; 5 entries put one on every point.
    const std::vector<glm::vec3> table = eikon::particleColorTable(s, 5);
    REQUIRE(table.size() == 5);
    CHECK(table[0] == glm::vec3(1.0f, 0.0f, 0.0f));
    CHECK(table[2] == glm::vec3(0.0f, 0.0f, 1.0f));
    CHECK(table[4] == glm::vec3(0.0f, 2.0f, 0.0f));
    // A map's table at its own size is its entries, so the first and last are its ends.
    const std::vector<glm::vec3> viridis = eikon::particleColorTable(named("viridis"), 256);
    CHECK(viridis.front() == eikon::particleColorAt(named("viridis"), 0.0f));
    CHECK(viridis.back() == eikon::particleColorAt(named("viridis"), 1.0f));
}

TEST_CASE("Particle colours in a scene: the three forms, and their errors", "[particle_color]") {
    auto sceneWith = [](const std::string& color) {
        return eikon::parseScene(
            R"({"sources": [{"type": "box", "value": 1}], "materials": [{"name": "m", )"
            R"("scattering": [1, 1, 1], "particle_color": )" +
                color + "}]}",
            "pc.json");
    };
    CHECK(sceneWith(R"("inferno")").materials[0].particleColor.map == "inferno");
    const eikon::Scene ranged = sceneWith(R"({"map": "magma", "range": [0.1, 0.9]})");
    CHECK(ranged.materials[0].particleColor.map == "magma");
    CHECK(ranged.materials[0].particleColor.range == glm::vec2(0.1f, 0.9f));
    const eikon::Scene points = sceneWith("[[0, 1, 0, 0], [1, 0, 0, 1]]");
    REQUIRE(points.materials[0].particleColor.points.size() == 2);
    CHECK(points.materials[0].particleColor.points[1] == glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    CHECK(eikon::parseScene(R"({"sources": [{"type": "box"}], "materials": [{"name": "m"}]})",
                            "plain.json")
              .materials[0]
              .particleColor.empty());

    auto errorOf = [&](const std::string& color) {
        try {
            sceneWith(color);
        } catch (const eikon::Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    CHECK_THAT(errorOf(R"("viridiss")"),
               Contains("/materials/0/particle_color:") && Contains("viridis"));
    CHECK_THAT(errorOf(R"({"map": "inferno", "range": [1, 0]})"),
               Contains("/materials/0/particle_color: the particle colour range [1, 0]: its high "
                        "end must be finite and above its low end"));
    CHECK_THAT(errorOf(R"({"map": "inferno", "range": [0]})"),
               Contains("/materials/0/particle_color/range: expected [low, high]"));
    CHECK_THAT(errorOf(R"({"map": "inferno", "gamma": 2})"),
               Contains("/materials/0/particle_color/gamma"));
    CHECK_THAT(errorOf("[[0, 1, 0, 0], [0, 0, 0, 1]]"),
               Contains("the particle colour point 1: value 0 is not above the one before, 0"));
    CHECK_THAT(errorOf("[[0, 1, 0, 0], [1, 0, -1, 1]]"),
               Contains("/materials/0/particle_color/1/2: expected"));
    CHECK_THAT(errorOf("[[0, 1, 0]]"), Contains("/materials/0/particle_color: expected"));
    CHECK_THAT(errorOf("[[0, 1, 0, 0], [1, 0, 1]]"),
               Contains("/materials/0/particle_color/1: expected a point [value, r, g, b]"));
    CHECK_THAT(errorOf("7"), Contains("/materials/0/particle_color: expected a colour map's name"));
    std::string many = "[";
    for (int i = 0; i < 17; ++i) many += (i ? ", [" : "[") + std::to_string(i) + ", 0, 0, 0]";
    CHECK_THAT(errorOf(many + "]"), Contains("expected at most 16 elements"));
}
