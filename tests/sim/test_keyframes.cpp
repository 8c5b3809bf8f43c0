// Keyframe animation (sim/keyframes.h, sim/animation.h, core/scene_animation.cpp): values at
// keys exact, interpolation against hand-computed values, unit rotations, the same state at the
// same time, and every parse error at its JSON pointer.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/error.h"
#include "core/scene.h"
#include "sim/animation.h"
#include "sim/clock.h"
#include "sim/keyframes.h"

using namespace eikon;

namespace {

AnimationTrack scalarTrack(Interpolation interpolation, std::vector<double> times,
                           std::vector<float> values) {
    AnimationTrack t;
    t.interpolation = interpolation;
    t.times = std::move(times);
    t.values = std::move(values);
    t.width = 1;
    return t;
}

float at(const AnimationTrack& track, double seconds) {
    float v = 0.0f;
    sim::evaluateTrack(track, false, seconds, &v);
    return v;
}

const char* const kScene = R"({
    "meshes": [{"name": "glass", "shape": {"type": "icosphere", "radius": 0.5}, "ior": 1.5}],
    "lights": [{"type": "spot", "position": [2, 2, 0], "direction": [-1, -1, 0]}],
    "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0]},
    "animation": [
        {"target": "/lights/0/position", "interpolation": "catmull_rom", "times": [0, 1, 2, 3, 4],
         "values": [[2, 2, 0], [0, 2, 2], [-2, 2, 0], [0, 2, -2], [2, 2, 0]]},
        {"target": "/lights/0/intensity", "interpolation": "step", "times": [0, 2], "values": [1, 5]},
        {"target": "/meshes/0/rotation", "times": [0, 4],
         "values": [[0, 0, 0, 1], [0, 0.7071068, 0, 0.7071068]]},
        {"target": "/meshes/0/ior", "interpolation": "cubicspline", "times": [0, 4],
         "values": [1.3, 1.7], "in_tangents": [0, 0], "out_tangents": [0, 0]},
        {"target": "/camera/horizontal_fov_deg", "times": [0, 4], "values": [40, 60]}
    ]
})";

}  // namespace

TEST_CASE("keys are exact, and the value holds before the first and after the last",
          "[animation]") {
    for (Interpolation i :
         {Interpolation::Step, Interpolation::Linear, Interpolation::CatmullRom}) {
        const AnimationTrack t = scalarTrack(i, {0.5, 1.0, 2.5}, {3.0f, -1.0f, 7.0f});
        CHECK(at(t, 0.5) == 3.0f);
        CHECK(at(t, 1.0) == -1.0f);
        CHECK(at(t, 2.5) == 7.0f);
        CHECK(at(t, 0.0) == 3.0f);
        CHECK(at(t, 9.0) == 7.0f);
    }
}

TEST_CASE("step, linear and Catmull-Rom match hand-computed values", "[animation]") {
    const AnimationTrack step = scalarTrack(Interpolation::Step, {0, 1}, {2.0f, 4.0f});
    CHECK(at(step, 0.999) == 2.0f);
    const AnimationTrack linear = scalarTrack(Interpolation::Linear, {0, 2}, {2.0f, 4.0f});
    CHECK(at(linear, 0.5) == Approx(2.5f));
    // Catmull-Rom through squares on even times reproduces the parabola between inner keys:
    // tangents (4 − 0)/2 = 2 and (9 − 1)/2 = 4, Hermite at u = ½ gives 0.5 + 0.25 + 2 − 0.5.
    const AnimationTrack cr = scalarTrack(Interpolation::CatmullRom, {0, 1, 2, 3}, {0, 1, 4, 9});
    CHECK(at(cr, 1.5) == Approx(2.25f));
    CHECK(at(cr, 1.25) == Approx(1.5625f));
}

TEST_CASE("cubicspline uses glTF's tangents scaled by the key span", "[animation]") {
    // v0 = 0, out-tangent 1; v1 = 1, in-tangent −1; span 2. At u = ½:
    // ½·0 + ⅛·2·1 + ½·1 − ⅛·2·(−1) = 0.25 + 0.5 + 0.25 = 1.
    AnimationTrack t = scalarTrack(Interpolation::CubicSpline, {1, 3}, {});
    t.values = {/*in*/ 0.0f,  /*v*/ 0.0f, /*out*/ 1.0f,
                /*in*/ -1.0f, /*v*/ 1.0f, /*out*/ 0.0f};
    CHECK(at(t, 2.0) == Approx(1.0f));
    CHECK(at(t, 1.0) == 0.0f);
    CHECK(at(t, 3.0) == 1.0f);
}

TEST_CASE("rotations slerp along the shorter arc and stay unit quaternions", "[animation]") {
    AnimationTrack t;
    t.width = 4;
    t.times = {0.0, 1.0};
    const float s = std::sqrt(0.5f);
    // Identity to 90° about z, the second key given as −q: the same rotation.
    t.values = {0, 0, 0, 1, 0, 0, -s, -s};
    float q[4];
    sim::evaluateTrack(t, true, 0.5, q);
    const glm::quat half = glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 0, 1));
    CHECK(std::abs(q[2]) == Approx(half.z).epsilon(1e-5));
    CHECK(std::abs(q[3]) == Approx(half.w).epsilon(1e-5));
    CHECK(q[2] * q[3] > 0.0f);  // 45° one way, not 135° the other
    for (Interpolation i : {Interpolation::Linear, Interpolation::CatmullRom}) {
        t.interpolation = i;
        for (double time = 0.0; time <= 1.0; time += 0.0625) {
            sim::evaluateTrack(t, true, time, q);
            CHECK(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] == Approx(1.0f));
        }
    }
}

TEST_CASE("a scene animates lights, meshes, materials and camera from one clock", "[animation]") {
    const Scene base = parseScene(kScene, "anim.json");
    REQUIRE(base.animation.size() == 5);
    const sim::SceneAnimation animation(base);
    const SimulationClock clock(24.0, 1.0);
    Scene a = base, b = base;
    animation.apply(clock.timeOfFrame(24), a);  // t = 1 s: a key of the light's path
    CHECK(a.lights[0].position == glm::vec3(0, 2, 2));
    CHECK(a.lights[0].intensity == 1.0f);
    animation.apply(clock.timeOfFrame(48), a);
    CHECK(a.lights[0].intensity == 5.0f);       // step at 2 s
    animation.apply(clock.timeOfFrame(96), a);  // the last key
    CHECK(a.meshes[0].rotation.y == Approx(0.7071068f));
    CHECK(a.materials[0].ior == Approx(1.7f));
    CHECK(a.camera.horizontalFovDeg == Approx(60.0f));
    // The same time twice from different states gives the same state.
    animation.apply(1.37, a);
    animation.apply(3.0, b);
    animation.apply(1.37, b);
    CHECK(a.lights[0].position == b.lights[0].position);
    CHECK(std::memcmp(&a.meshes[0].rotation, &b.meshes[0].rotation, sizeof(glm::quat)) == 0);
    CHECK(a.materials[0].ior == b.materials[0].ior);
    CHECK(a.camera.horizontalFovDeg == b.camera.horizontalFovDeg);
    CHECK(glm::length(glm::vec4(a.meshes[0].rotation.x, a.meshes[0].rotation.y,
                                a.meshes[0].rotation.z, a.meshes[0].rotation.w)) == Approx(1.0f));
}

TEST_CASE("a directional light's disc animates, and only a directional light has one",
          "[animation]") {
    const Scene base = parseScene(R"({
        "meshes": [{"name": "glass", "shape": {"type": "icosphere", "radius": 0.5}, "ior": 1.5}],
        "lights": [{"type": "directional", "direction": [0, -1, 0]}],
        "animation": [{"target": "/lights/0/angular_diameter_deg", "times": [0, 1],
                       "values": [0, 8]}]})",
                                  "sun.json");
    const sim::SceneAnimation animation(base);
    Scene a = base;
    animation.apply(0.25, a);
    CHECK(a.lights[0].angularDiameterDeg == Approx(2.0f));
    CHECK_THROWS_WITH(parseScene(R"({"meshes": [{"name": "glass", "file": "g.obj", "ior": 1.5}],
        "lights": [{"type": "point", "position": [0, 2, 0]}],
        "animation": [{"target": "/lights/0/angular_diameter_deg", "times": [0], "values": [1]}]})",
                                 "p.json"),
                      Catch::Contains("p.json:/animation/0/target") &&
                          Catch::Contains("this light animates position, color, intensity"));
}

TEST_CASE("animation errors name the track and say what was expected", "[animation]") {
    const std::string head = R"({"meshes": [{"name": "glass", "file": "g.obj", "ior": 1.5}],
        "lights": [{"type": "point", "position": [0, 2, 0]}], "animation": [)";
    auto fails = [&](const std::string& track, const std::string& where, const std::string& what) {
        INFO(track);
        CHECK_THROWS_WITH(parseScene(head + track + "]}", "a.json"),
                          Catch::Contains("a.json:" + where) && Catch::Contains(what));
    };
    fails(R"({"target": "/lights/3/position", "times": [0], "values": [[0, 0, 0]]})",
          "/animation/0/target", "no lights 3 (the scene has 1)");
    fails(R"({"target": "/lights/0/direction", "times": [0], "values": [[0, 0, 0]]})",
          "/animation/0/target", "this light animates position, color, intensity");
    fails(R"({"target": "/camera/position", "times": [0], "values": [[0, 0, 0]]})",
          "/animation/0/target", "the camera is \"auto\"");
    fails(R"({"target": "/sky", "times": [0], "values": [1]})", "/animation/0/target",
          "not an animatable value");
    fails(R"({"target": "/meshes/0/absorption", "times": [0], "values": [[1, 1, 1]]})",
          "/animation/0/target", "no absorption, scattering or emission");
    fails(R"({"target": "/lights/0/intensity", "times": [0, 0], "values": [1, 2]})",
          "/animation/0/times/1", "increase strictly");
    fails(R"({"target": "/lights/0/intensity", "times": [0, 1], "values": [1]})",
          "/animation/0/values", "expected 2 keys");
    fails(R"({"target": "/lights/0/intensity", "times": [0], "values": [-1]})",
          "/animation/0/values/0", ">= 0");  // range text from json_reader
    fails(R"({"target": "/lights/0/position", "times": [0], "values": [[1, 2]]})",
          "/animation/0/values/0", "an array of 3 numbers");
    fails(R"({"target": "/meshes/0/rotation", "times": [0], "values": [[0, 0, 0, 2]]})",
          "/animation/0/values/0", "unit quaternion");
    fails(R"({"target": "/lights/0/intensity", "times": [0], "values": [1], "in_tangents": [0]})",
          "/animation/0/in_tangents", "cubicspline");
    fails(R"({"target": "/lights/0/intensity", "interpolation": "cubicspline", "times": [0],
              "values": [1]})",
          "/animation/0", "in_tangents");
    fails(
        R"({"target": "/lights/0/intensity", "interpolation": "bezier", "times": [0], "values": [1]})",
        "/animation/0/interpolation", "catmull_rom");
    fails(R"({"target": "/lights/0/intensity", "times": [0], "values": [1]},
             {"target": "/lights/0/intensity", "times": [1], "values": [2]})",
          "/animation/1/target", "animated already by /animation/0");
}

TEST_CASE("smoke source tracks move and change the simulation's sources", "[animation]") {
    const std::string head = R"({"sources": [{"type": "vdb_sequence", "file": "c/s_####.vdb"}],
        "materials": [{"name": "smoke", "scattering": [1, 1, 1]}],
        "simulation": {"domain": {"min": [0, 0, 0], "max": [1, 1, 1]}, "resolution": 8,
          "sources": [{"type": "sphere", "center": [0.5, 0.2, 0.5], "radius": 0.1},
                      {"type": "box", "min": [0, 0, 0], "max": [0.2, 0.1, 0.4]}]},
        "animation": [)";
    SECTION("values land in the sources, a box keeping its size around its new centre") {
        const Scene base = parseScene(head + R"(
            {"target": "/simulation/sources/0/center", "times": [0, 2],
             "values": [[0.5, 0.2, 0.5], [0.7, 0.2, 0.5]]},
            {"target": "/simulation/sources/0/velocity", "times": [0], "values": [[0, 1, 0]]},
            {"target": "/simulation/sources/0/density_rate", "times": [0, 2], "values": [2, 0]},
            {"target": "/simulation/sources/0/temperature_rate", "times": [0], "values": [-3]},
            {"target": "/simulation/sources/0/velocity_rate", "times": [0], "values": [5]},
            {"target": "/simulation/sources/1/center", "times": [0], "values": [[1, 1, 1]]}]})",
                                      "s.json");
        Scene a = base;
        sim::SceneAnimation(base).apply(1.0, a);
        const SmokeSourceSpec& s0 = a.simulations.at(0).sources[0];
        CHECK(s0.shape.center.x == Approx(0.6f));
        CHECK(s0.velocity == glm::vec3(0, 1, 0));
        CHECK(s0.densityRate == Approx(1.0f));
        CHECK(s0.temperatureRate == -3.0f);  // a cold source, as the parser allows
        CHECK(s0.velocityRate == 5.0f);
        const SimShapeSpec& box = a.simulations.at(0).sources[1].shape;
        const glm::vec3 lo(0.9f, 0.95f, 0.8f), hi(1.1f, 1.05f, 1.2f);
        for (int a = 0; a < 3; ++a) {
            CHECK(box.boxMin[a] == Approx(lo[a]));
            CHECK(box.boxMax[a] == Approx(hi[a]));
        }
    }
    SECTION("a rate that interpolation overshoots below 0 is clamped to 0") {
        const Scene base = parseScene(head + R"(
            {"target": "/simulation/sources/0/density_rate", "interpolation": "cubicspline",
             "times": [0, 1], "values": [0, 0], "in_tangents": [0, 0], "out_tangents": [-5, 0]}]})",
                                      "s.json");
        Scene a = base;
        sim::SceneAnimation(base).apply(0.5, a);
        CHECK(a.simulations.at(0).sources[0].densityRate == 0.0f);
    }
    auto fails = [&](const std::string& track, const std::string& where, const std::string& what) {
        INFO(track);
        CHECK_THROWS_WITH(parseScene(head + track + "]}", "s.json"),
                          Catch::Contains("s.json:" + where) && Catch::Contains(what));
    };
    fails(R"({"target": "/simulation/sources/2/center", "times": [0], "values": [[0, 0, 0]]})",
          "/animation/0/target", "no simulation source 2 (/simulation has 2)");
    fails(R"({"target": "/simulation/sources/0/radius", "times": [0], "values": [1]})",
          "/animation/0/target", "a smoke source animates center, velocity, density_rate");
    fails(R"({"target": "/simulation/obstacles/0/center", "times": [0], "values": [[0, 0, 0]]})",
          "/animation/0/target", "expected /simulation/sources/<index>/<key>");
    fails(R"({"target": "/simulation/sources/0/density_rate", "times": [0], "values": [-1]})",
          "/animation/0/values/0", ">= 0");
    fails(R"({"target": "/simulation/sources/0/velocity_rate", "times": [0], "values": [-1]})",
          "/animation/0/values/0", ">= 0");
    fails(R"({"target": "/simulation/sources/0/velocity", "times": [0], "values": [1]})",
          "/animation/0/values/0", "an array of 3 numbers");
    CHECK_THROWS_WITH(parseScene(R"({"lights": [{"type": "point", "position": [0, 2, 0]}],
            "meshes": [{"name": "glass", "shape": {"type": "icosphere", "radius": 0.5},
                        "ior": 1.5}],
            "animation": [{"target": "/simulation/sources/0/center", "times": [0],
                           "values": [[0, 0, 0]]}]})",
                                 "n.json"),
                      Catch::Contains("n.json:/animation/0/target") &&
                          Catch::Contains("the scene has no \"simulation\" section"));
}
