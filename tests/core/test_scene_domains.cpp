// Several smoke domains in one scene: "simulation" as an array of labelled domains, each
// publishing its own labelled fields (density.<label>, ...), with its own cache name and its own
// tracks; and the alias keys that load a domain's cache back under its labelled names.
#include <catch2/catch.hpp>

#include <string>

#include "core/animation_targets.h"
#include "core/error.h"
#include "core/scene.h"

using Catch::Matchers::Contains;

namespace {

// Two domains side by side, `extra` appended to the top level.
std::string twoDomains(const std::string& firstLabel, const std::string& secondLabel,
                       const std::string& extra = "") {
    auto domain = [](const std::string& label, float x0) {
        const std::string x = std::to_string(x0), x1 = std::to_string(x0 + 1.0f);
        return R"({)" + label + R"("domain": {"min": [)" + x + R"(, 0, 0], "max": [)" + x1 +
               R"(, 1, 1]}, "resolution": 8,
                   "sources": [{"type": "sphere", "center": [)" +
               std::to_string(x0 + 0.5f) + R"(, 0.2, 0.5], "radius": 0.2}]})";
    };
    return R"({"sources": [{"type": "simulation"}],
               "materials": [{"name": "a", "field": "density.left"},
                             {"name": "b", "field": "density.right", "absorption": [1, 0, 0]}],
               "simulation": [)" +
           domain(firstLabel, 0.0f) + ", " + domain(secondLabel, 1.5f) + "]" + extra + "}";
}

const std::string kLeft = R"("label": "left", )";
const std::string kRight = R"("label": "right", )";

eikon::Error errorOf(const std::string& text) {
    try {
        eikon::parseScene(text, "two.json");
    } catch (const eikon::Error& e) {
        return e;
    }
    FAIL("expected an eikon::Error for: " << text);
    return eikon::Error("", "");
}

}  // namespace

TEST_CASE("an array of labelled simulation domains parses", "[scene][simulation]") {
    const eikon::Scene scene = eikon::parseScene(twoDomains(kLeft, kRight), "two.json");
    REQUIRE(scene.simulations.size() == 2);
    CHECK(scene.simulations[0].label == "left");
    CHECK(scene.simulations[1].label == "right");
    CHECK(scene.simulations[0].jsonPath == "/simulation/0");
    CHECK(scene.simulations[1].jsonPath == "/simulation/1");
    CHECK(scene.simulations[1].domain.min.x == 1.5f);
    // Fields and cache files stay apart.
    CHECK(eikon::simulationFieldName(scene.simulations[1], "density") == "density.right");
    CHECK(scene.simulations[0].cacheName == "smoke_left");
    CHECK(scene.simulations[1].cacheName == "smoke_right");

    SECTION("the output name is the caches' prefix") {
        const eikon::Scene named = eikon::parseScene(
            twoDomains(kLeft, kRight, R"(, "output": {"name": "puff"})"), "two.json");
        CHECK(named.simulations[0].cacheName == "puff_left");
        CHECK(named.simulations[1].cacheName == "puff_right");
    }
    SECTION("a lone object keeps its unlabelled names and may take a label") {
        const eikon::Scene lone = eikon::parseScene(
            R"({"sources": [{"type": "simulation"}], "materials": [{"name": "m", "field": "density.x"}],
                "simulation": {"label": "x", "domain": {"min": [0, 0, 0], "max": [1, 1, 1]},
                               "resolution": 8}})",
            "one.json");
        REQUIRE(lone.simulations.size() == 1);
        CHECK(lone.simulations[0].jsonPath == "/simulation");
        CHECK(lone.simulations[0].cacheName == "smoke_x");
    }
}

TEST_CASE("simulation domains' mistakes name their JSON pointer", "[scene][simulation]") {
    SECTION("a domain of several without a label") {
        const eikon::Error e = errorOf(twoDomains(kLeft, ""));
        CHECK(e.where() == "two.json:/simulation/1/label");
        CHECK_THAT(e.reason(), Contains("missing required key 'label'"));
    }
    SECTION("two domains of one label") {
        const eikon::Error e = errorOf(twoDomains(kLeft, kLeft));
        CHECK(e.where() == "two.json:/simulation/1/label");
        CHECK_THAT(e.reason(), Contains("taken by /simulation/0"));
    }
    SECTION("a label that cannot be part of a field name") {
        const eikon::Error e = errorOf(twoDomains(kLeft, R"("label": "ri.ght", )"));
        CHECK(e.where() == "two.json:/simulation/1/label");
        CHECK_THAT(e.reason(), Contains("letters, digits and '_'"));
    }
    SECTION("an empty array") {
        const eikon::Error e = errorOf(
            R"({"sources": [{"type": "simulation"}], "materials": [{"name": "m"}], "simulation": []})");
        CHECK(e.where() == "two.json:/simulation");
        CHECK_THAT(e.reason(), Contains("at least one"));
    }
    SECTION("a material reading a domain that is not there") {
        std::string text = twoDomains(kLeft, kRight);
        text.replace(text.find("density.right"), 13, "density.rigth");
        const eikon::Error e = errorOf(text);
        CHECK(e.where() == "two.json:/materials/1/field");
        CHECK_THAT(e.reason(), Contains("did you mean \"density.right\"?"));
    }
}

TEST_CASE("a track names its domain's source", "[scene][simulation][animation]") {
    const std::string track =
        R"(, "animation": [{"target": "/simulation/1/sources/0/center", "times": [0, 1],
                            "values": [[2, 0.2, 0.5], [2.2, 0.2, 0.5]]}])";
    eikon::Scene scene = eikon::parseScene(twoDomains(kLeft, kRight, track), "two.json");
    std::string why;
    const auto target = eikon::resolveAnimationTarget(scene, "/simulation/1/sources/0/center", why);
    REQUIRE(target);
    CHECK(target->domain == 1);
    const float to[3] = {2.25f, 0.3f, 0.5f};
    eikon::writeAnimationTarget(scene, *target, to);
    CHECK(scene.simulations[1].sources[0].shape.center.x == 2.25f);
    CHECK(scene.simulations[0].sources[0].shape.center.x == 0.5f);  // the other domain holds

    // The lone-object form has no domain index, the array form needs one.
    CHECK_FALSE(eikon::resolveAnimationTarget(scene, "/simulation/sources/0/center", why));
    CHECK_THAT(why, Contains("/simulation/<domain>/sources/<index>/<key>"));
    CHECK_FALSE(eikon::resolveAnimationTarget(scene, "/simulation/2/sources/0/center", why));
    CHECK_FALSE(eikon::resolveAnimationTarget(scene, "/simulation/0/sources/1/center", why));
    CHECK_THAT(why, Contains("/simulation/0 has 1"));
}

TEST_CASE("an alias key may be a labelled field", "[scene][sources]") {
    const eikon::Scene scene = eikon::parseScene(
        R"({"sources": [{"type": "vdb_sequence", "file": "cache/puff_left_####.vdb",
                         "aliases": {"density.left": ["density"], "temperature": ["heat"]}}],
            "materials": [{"name": "m", "field": "density.left"}]})",
        "/s/two.json");
    REQUIRE(scene.sources[0].aliases.count("density.left") == 1);
    CHECK(scene.sources[0].aliases.at("density.left") == std::vector<std::string>{"density"});
    CHECK(scene.sources[0].aliases.count("temperature") == 1);

    const eikon::Error e = errorOf(
        R"({"sources": [{"type": "vdb", "file": "a.vdb", "aliases": {"densty.left": ["density"]}}],
            "materials": [{"name": "m"}]})");
    CHECK(e.where() == "two.json:/sources/0/aliases/densty.left");
    CHECK_THAT(e.reason(), Contains("did you mean \"density\"?"));
}
