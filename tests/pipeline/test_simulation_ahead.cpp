// SimulationAhead (pipeline/simulation_ahead.h), the viewer's simulation thread: in lockstep it
// hands every frame once, in order, as many as asked; running free it hands increasing frames,
// merging those not taken; either way a frame's fields are those a driver stepping in the
// caller's thread gives for that frame, voxel for voxel (a frame is the same however it is
// reached), and the merge keeps every mesh and field handed out.
#include <catch2/catch.hpp>

#include <openvdb/openvdb.h>

#include "pipeline/scene_driver.h"
#include "pipeline/simulation_ahead.h"
#include "support/test_paths.h"

using eikon::FrameInputs;
using eikon::SceneDriver;
using eikon::SimulationAhead;

namespace {

// The live smoke around a glass ball, its solver at a test's size.
eikon::Scene smokeScene() {
    eikon::Scene scene =
        eikon::loadScene(eikon::test::sourcePath("data/scenes/smoke_glass_mesh.json"));
    eikon::SmokeSimulationSpec& sim = scene.simulations.at(0);
    sim.resolution /= 2;  // the same box in cells twice as wide
    sim.voxelSize *= 2.0f;
    return scene;
}

// The density the driver of a fresh scene hands out at `frame`, stepping there in this thread.
openvdb::FloatGrid::ConstPtr densityAt(const eikon::Scene& scene, int frame) {
    SceneDriver driver(scene);
    FrameInputs last;
    for (int f = scene.time.frameStart; f <= frame; ++f) {
        FrameInputs in = driver.frameInputs(f, scene);
        if (in.fields.has("density")) last = std::move(in);
    }
    return last.fields.floatGrid("density");
}

void checkSameVoxels(const openvdb::FloatGrid& a, const openvdb::FloatGrid& b) {
    REQUIRE(a.activeVoxelCount() == b.activeVoxelCount());
    REQUIRE(a.activeVoxelCount() > 0);
    const auto other = b.getConstAccessor();
    int differ = 0;
    for (auto it = a.cbeginValueOn(); it; ++it) differ += other.getValue(it.getCoord()) != *it;
    CHECK(differ == 0);
}

}  // namespace

TEST_CASE("SimulationAhead in lockstep hands each frame once, in order, as the caller would step",
          "[pipeline][simulation_ahead]") {
    openvdb::initialize();
    const eikon::Scene scene = smokeScene();
    const int first = scene.time.frameStart;
    SceneDriver driver(scene);
    FrameInputs shown = driver.frameInputs(first, scene);  // the viewer's first frame, itself
    SimulationAhead ahead(driver, scene);
    ahead.start(first + 1, 3);
    for (int k = 1; k <= 3; ++k) {
        std::optional<FrameInputs> in = ahead.take(true);
        REQUIRE(in);
        CHECK(in->frame == first + k);
        REQUIRE(in->fields.has("density"));
        if (k == 3) checkSameVoxels(*in->fields.floatGrid("density"), *densityAt(scene, first + 3));
    }
    CHECK_FALSE(ahead.take(true));  // the three asked for, and no more
    ahead.stop();
    CHECK_FALSE(ahead.running());
}

TEST_CASE(
    "SimulationAhead running free hands later and later frames, the same voxels as stepped "
    "here",
    "[pipeline][simulation_ahead]") {
    openvdb::initialize();
    const eikon::Scene scene = smokeScene();
    const int first = scene.time.frameStart;
    SceneDriver driver(scene);
    (void)driver.frameInputs(first, scene);
    SimulationAhead ahead(driver, scene);
    ahead.start(first + 1);
    int last = first;
    FrameInputs latest;
    for (int taken = 0; taken < 4; ++taken) {
        std::optional<FrameInputs> in = ahead.take(true);
        REQUIRE(in);
        CHECK(in->frame > last);  // no frame twice, none backwards (the scene has 72)
        last = in->frame;
        latest = std::move(*in);
    }
    ahead.stop();
    CHECK_FALSE(ahead.running());
    // What was stepped after the last take stays for the caller, merged.
    if (std::optional<FrameInputs> rest = ahead.take(false)) {
        CHECK(rest->frame > last);
        eikon::mergeFrameInputs(latest, std::move(*rest));
    }
    checkSameVoxels(*latest.fields.floatGrid("density"), *densityAt(scene, latest.frame));
}

TEST_CASE("mergeFrameInputs keeps the newer frame, scene, meshes and fields, and the older rest",
          "[pipeline][simulation_ahead]") {
    openvdb::initialize();
    auto grid = [](float v) {
        openvdb::FloatGrid::Ptr g = openvdb::FloatGrid::create();
        g->tree().setValue(openvdb::Coord(0, 0, 0), v);
        return g;
    };
    auto mesh = [](float x) {
        eikon::TriangleMesh m;
        m.positions = {glm::vec3(x, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)};
        m.triangles = {glm::uvec3(0, 1, 2)};
        return m;
    };
    FrameInputs older(3, eikon::Scene{}), newer(5, eikon::Scene{});
    newer.scene.path = "newer";
    older.meshes = {{0, mesh(1.0f)}, {2, mesh(2.0f)}};
    newer.meshes = {{2, mesh(3.0f)}, {4, mesh(4.0f)}};
    older.fields.set("density", grid(1.0f), "older");
    older.fields.set("n", grid(2.0f), "older");
    newer.fields.set("density", grid(3.0f), "newer");
    eikon::mergeFrameInputs(older, std::move(newer));
    CHECK(older.frame == 5);
    CHECK(older.scene.path == "newer");
    REQUIRE(older.meshes.size() == 3);
    CHECK(older.meshes[0].second.positions[0].x == 1.0f);
    CHECK(older.meshes[1].second.positions[0].x == 3.0f);
    CHECK(older.meshes[2].first == 4);
    CHECK(older.fields.get("density").origin == "newer");
    CHECK(older.fields.get("n").origin == "older");
}
