// The default scene of a VDB input (issue 20): the automatic camera frames the density that
// shows, not every active voxel; frames a sequence once; and takes its up axis from the user, the
// file's writer, or the sequence's motion, in that order.
#include <catch2/catch.hpp>

#include <string>

#include <openvdb/openvdb.h>

#include "core/camera.h"
#include "core/density_view.h"
#include "core/scene.h"
#include "core/vdb_import.h"
#include "support/test_paths.h"

using namespace eikon;

namespace {

// A fog grid of `voxel` size: a cube of density 1 at index [lo, lo + 7]^3 (8^3 voxels), and
// with `allActive` every voxel of [0, 63]^3 active at 0 around it.
openvdb::FloatGrid::Ptr puff(openvdb::Coord lo, bool allActive, double voxel = 0.1) {
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxel));
    if (allActive) grid->tree().fill(openvdb::CoordBBox({0, 0, 0}, {63, 63, 63}), 0.0f, true);
    grid->tree().fill(openvdb::CoordBBox(lo, lo.offsetBy(7)), 1.0f, true);
    return grid;
}

std::string write(const std::string& name, openvdb::FloatGrid::Ptr grid,
                  const openvdb::MetaMap& meta = {}) {
    // A folder per file: scratchDir empties its folder, and ctest runs cases in parallel.
    const std::string path = test::scratchDir("default_scene_" + name) + "/" + name;
    openvdb::io::File(path).write({grid}, meta);
    return path;
}

}  // namespace

TEST_CASE("the camera frames the density that shows, not every active voxel", "[camera]") {
    ensureOpenVdbInitialized();
    const std::string path = write("puff_in_active_grid.vdb", puff({40, 40, 40}, true));
    std::string note;
    const Scene scene = defaultSceneForVdb(path, {}, note);
    REQUIRE(scene.camera.automatic);
    REQUIRE(scene.camera.framed);
    // Index 40..47 -> outer faces at 3.95 .. 4.75 with 0.1 voxels.
    CHECK(scene.camera.framed->min.x == Approx(3.95f));
    CHECK(scene.camera.framed->max.x == Approx(4.75f));
    CHECK(scene.camera.framed->min.y == Approx(3.95f));
    CHECK(scene.camera.framed->max.z == Approx(4.75f));
    // The camera looks at the puff's centre whatever the render volume is.
    Bounds3 whole{{-0.05f, -0.05f, -0.05f}, {6.35f, 6.35f, 6.35f}};
    const CameraFrame a = makeCameraFrame(scene.camera, whole, 64, 48);
    const CameraFrame b = makeCameraFrame(scene.camera, Bounds3{{0, 0, 0}, {1, 1, 1}}, 64, 48);
    CHECK(a.origin == b.origin);
    CHECK(glm::dot(a.forward, glm::normalize(glm::vec3(4.35f) - a.origin)) == Approx(1.0f));
    CHECK(note.empty());  // y up by default: nothing to say
}

TEST_CASE("the up axis: --up, the writer's, the sequence's motion, else y", "[camera]") {
    ensureOpenVdbInitialized();
    std::string note;
    SECTION("Blender Mantaflow caches are z-up, Houdini's y-up") {
        const Scene blender = defaultSceneForVdb(
            test::sharedData("vdb/blender_smoke_c42/fluid_data_0010.vdb"), {}, note);
        CHECK(blender.camera.up == glm::vec3(0, 0, 1));
        CHECK(note.find("Blender Mantaflow cache") != std::string::npos);
        // The camera looks from Blender's front (−y), up is +z, the sun from above.
        const CameraFrame f = makeCameraFrame(blender.camera, {}, 64, 48);
        CHECK(f.up.z > 0.9f);
        CHECK(f.forward.y > 0.9f);
        CHECK(blender.lights[0].direction.z < -0.5f);
        note.clear();
        const Scene houdini =
            defaultSceneForVdb(test::sharedData("vdb/houdini_smoke1.vdb"), {}, note);
        CHECK(houdini.camera.up == glm::vec3(0, 1, 0));
        CHECK(note.find("Houdini") != std::string::npos);
    }
    SECTION("the user's axis wins") {
        DefaultSceneChoices camera;
        camera.up = glm::vec3(1, 0, 0);
        const Scene s = defaultSceneForVdb(
            test::sharedData("vdb/blender_smoke_c42/fluid_data_0010.vdb"), camera, note);
        CHECK(s.camera.up == glm::vec3(1, 0, 0));
        CHECK(note.empty());
    }
    SECTION("file metadata up_axis") {
        openvdb::MetaMap meta;
        meta.insertMeta("up_axis", openvdb::StringMetadata("Z"));
        const std::string path = write("meta_up.vdb", puff({0, 0, 0}, false), meta);
        const Scene s = defaultSceneForVdb(path, {}, note);
        CHECK(s.camera.up == glm::vec3(0, 0, 1));
        CHECK(note.find("up_axis = Z") != std::string::npos);
    }
    SECTION("a sequence that moves along x, framed once on its frames' union") {
        const std::string dir = test::scratchDir("default_scene_moving");
        for (int f = 1; f <= 3; ++f)
            openvdb::io::File(dir + "/drift_000" + std::to_string(f) + ".vdb")
                .write({puff({10 * f, 0, 0}, false)});
        const Scene s = defaultSceneForVdbSequence(dir + "/drift_####.vdb", false, {}, note);
        CHECK(s.camera.up == glm::vec3(1, 0, 0));
        CHECK(note.find("moves along x") != std::string::npos);
        REQUIRE(s.camera.framed);
        CHECK(s.camera.framed->min.x == Approx(0.95f));  // first frame's puff
        CHECK(s.camera.framed->max.x == Approx(3.75f));  // last frame's
        CHECK(s.time.frameStart == 1);
        CHECK(s.time.frameEnd == 3);
    }
    SECTION("a sequence that barely moves keeps y") {
        const std::string dir = test::scratchDir("default_scene_still");
        for (int f = 1; f <= 2; ++f)
            openvdb::io::File(dir + "/still_000" + std::to_string(f) + ".vdb")
                .write({puff({f, 0, 0}, false)});
        const Scene s = defaultSceneForVdbSequence(dir + "/still_####.vdb", false, {}, note);
        CHECK(s.camera.up == glm::vec3(0, 1, 0));
        CHECK(note.empty());
    }
}

TEST_CASE("up axis text", "[camera]") {
    CHECK(parseUpAxis("z") == glm::vec3(0, 0, 1));
    CHECK(parseUpAxis("+Y") == glm::vec3(0, 1, 0));
    CHECK_FALSE(parseUpAxis("-z"));
    CHECK_FALSE(parseUpAxis("up"));
}
