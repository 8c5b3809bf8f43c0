// The scene's "clip_planes" (core/scene_clip_planes.h): what is read, and each error at its JSON
// pointer. Rendering with them: tests/render/test_clip_planes.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "core/animation_targets.h"
#include "core/error.h"
#include "core/scene.h"

using Catch::Matchers::Contains;

namespace {

eikon::Scene sceneWith(const std::string& clipPlanes) {
    return eikon::parseScene(
        R"({"sources": [{"type": "box", "value": 1}],
            "materials": [{"name": "skin", "absorption": [1, 1, 1]},
                          {"name": "bone", "absorption": [2, 2, 2], "ior": 1.3}],
            "clip_planes": )" +
            clipPlanes + "}",
        "clip.json");
}

std::string errorOf(const std::string& clipPlanes) {
    try {
        sceneWith(clipPlanes);
    } catch (const eikon::Error& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("Clip planes in a scene: the point, the unit normal, the materials they cut",
          "[clip][scene]") {
    const eikon::Scene scene = sceneWith(
        R"([{"point": [0, 0.25, 0], "normal": [0, 0, -2]},
            {"point": [1, 2, 3], "normal": [1, 1, 0], "materials": ["bone"]}])");
    REQUIRE(scene.clipPlanes.size() == 2);
    CHECK(scene.clipPlanes[0].point == glm::vec3(0.0f, 0.25f, 0.0f));
    CHECK(scene.clipPlanes[0].normal == glm::vec3(0.0f, 0.0f, -1.0f));  // normalised
    CHECK(scene.clipPlanes[0].materials.empty());                       // every material
    CHECK(scene.clipPlanes[0].jsonPath == "/clip_planes/0");
    CHECK(scene.clipPlanes[1].normal.x == Approx(std::sqrt(0.5)).epsilon(1e-6));
    CHECK(scene.clipPlanes[1].materials == std::vector<std::string>{"bone"});
    CHECK(sceneWith("[]").clipPlanes.empty());
}

TEST_CASE("Clip planes: each error names the file and the JSON pointer", "[clip][scene]") {
    CHECK_THAT(errorOf(R"([{"point": [0, 0, 0], "normal": [0, 0, 0]}])"),
               Contains("clip.json:/clip_planes/0/normal: the normal is zero"));
    CHECK_THAT(errorOf(R"([{"normal": [0, 0, 1]}])"),
               Contains("clip.json:/clip_planes/0") && Contains("point"));
    CHECK_THAT(errorOf(R"([{"point": [0, 0, 0], "normal": [0, 1, 0], "materials": ["glass"]}])"),
               Contains("/clip_planes/0/materials/0: no material is named \"glass\""));
    CHECK_THAT(
        errorOf(R"([{"point": [0, 0, 0], "normal": [0, 1, 0], "materials": ["bone", "bone"]}])"),
        Contains("/clip_planes/0/materials/1: material \"bone\" is listed twice"));
    CHECK_THAT(errorOf(R"([{"point": [0, 0, 0], "normal": [0, 1, 0], "materials": []}])"),
               Contains("/clip_planes/0/materials: the list is empty"));
    CHECK_THAT(errorOf(R"([{"point": [0, 0, 0], "normal": [0, 1, 0], "keep": "both"}])"),
               Contains("/clip_planes/0") && Contains("keep"));
    std::string five = "[";
    for (int i = 0; i < 5; ++i)
        five += std::string(i ? ", " : "") + R"({"point": [0, 0, 0], "normal": [0, 1, 0]})";
    CHECK_THAT(errorOf(five + "]"), Contains("/clip_planes: expected at most 4 elements"));
    CHECK_THAT(errorOf(R"({"point": [0, 0, 0]})"), Contains("/clip_planes: expected an array"));
}

TEST_CASE("A clip plane's point and normal are animation targets", "[clip][animation]") {
    eikon::Scene scene = sceneWith(R"([{"point": [0, 0, 0], "normal": [0, 0, -1]}])");
    std::string why;
    const auto point = eikon::resolveAnimationTarget(scene, "/clip_planes/0/point", why);
    REQUIRE(point);
    const float p[3] = {0.1f, 0.2f, 0.3f};
    eikon::writeAnimationTarget(scene, *point, p);
    CHECK(scene.clipPlanes[0].point == glm::vec3(0.1f, 0.2f, 0.3f));
    const auto normal = eikon::resolveAnimationTarget(scene, "/clip_planes/0/normal", why);
    REQUIRE(normal);
    const float n[3] = {3.0f, 0.0f, 4.0f};
    eikon::writeAnimationTarget(scene, *normal, n);
    const glm::vec3 turned = scene.clipPlanes[0].normal;
    CHECK(turned.x == Approx(0.6));
    CHECK(turned.z == Approx(0.8));
    const float zero[3] = {0.0f, 0.0f, 0.0f};
    eikon::writeAnimationTarget(scene, *normal, zero);
    CHECK(scene.clipPlanes[0].normal == turned);  // kept

    CHECK_FALSE(eikon::resolveAnimationTarget(scene, "/clip_planes/1/point", why));
    CHECK_THAT(why, Contains("no clip_planes 1 (the scene has 1)"));
    CHECK_FALSE(eikon::resolveAnimationTarget(scene, "/clip_planes/0/materials", why));
    CHECK_THAT(why, Contains("a clip plane animates point or normal"));
}
