// `eikon info` against grids built here with known answers (issue 20): a rotated grid's world
// bounds from all eight corners, NaN and Inf counted, an unnamed grid labelled, the half-float
// flag shown only where it means something.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <openvdb/openvdb.h>

#include "core/vdb_import.h"
#include "core/vdb_info.h"
#include "support/test_paths.h"

using namespace eikon;

namespace {

std::string writeGrids(const std::string& name, openvdb::GridPtrVec grids) {
    // A folder per file: scratchDir empties its folder, and ctest runs cases in parallel.
    const std::string path = test::scratchDir("vdb_info_" + name) + "/" + name;
    openvdb::io::File(path).write(grids);
    return path;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("a rotated grid's world bounds hold all eight corners", "[vdb][info]") {
    ensureOpenVdbInitialized();
    // Voxels 0..9 on x and z, 0..0 on y: a flat slab, turned 45 degrees about y. The two extreme
    // corners alone give z within ±0.035 (the Houdini file); the slab spans ±0.707·10·h.
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->tree().fill(openvdb::CoordBBox({0, 0, 0}, {9, 0, 9}), 1.0f, true);
    const double h = 0.1;
    openvdb::math::Transform::Ptr xform = openvdb::math::Transform::createLinearTransform(h);
    xform->preTranslate(openvdb::Vec3d(0.5));  // index box -0.5..9.5 -> 0..10 before the turn
    xform->postRotate(M_PI / 4, openvdb::math::Y_AXIS);
    grid->setTransform(xform);
    const VdbFileInfo info = inspectVdb(writeGrids("rotated.vdb", {grid}));
    REQUIRE(info.grids.size() == 1);
    const GridInfo& g = info.grids[0];
    // Index box corners (0..10)·h in x and z, rotated: x' = (x + z)/√2, z' = (z − x)/√2.
    const double r = 10 * h / std::sqrt(2.0);
    CHECK(g.worldMin[0] == Approx(0.0).margin(1e-9));
    CHECK(g.worldMax[0] == Approx(2 * r));
    CHECK(g.worldMin[2] == Approx(-r));
    CHECK(g.worldMax[2] == Approx(r));
    CHECK(g.worldMax[1] - g.worldMin[1] == Approx(h));
}

TEST_CASE("NaN and Inf values are counted, and kept out of the value range", "[vdb][info]") {
    ensureOpenVdbInitialized();
    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    auto acc = density->getAccessor();
    acc.setValue({0, 0, 0}, 0.5f);
    acc.setValue({1, 0, 0}, 2.0f);
    acc.setValue({2, 0, 0}, std::numeric_limits<float>::quiet_NaN());
    acc.setValue({3, 0, 0}, std::numeric_limits<float>::quiet_NaN());
    acc.setValue({4, 0, 0}, -std::numeric_limits<float>::infinity());
    auto velocity = openvdb::Vec3SGrid::create();
    velocity->setName("vel");
    velocity->getAccessor().setValue({0, 0, 0}, {3, 4, 0});
    velocity->getAccessor().setValue({1, 0, 0}, {0, std::numeric_limits<float>::quiet_NaN(), 0});
    auto clean = openvdb::FloatGrid::create(0.0f);
    clean->setName("temperature");
    clean->getAccessor().setValue({0, 0, 0}, 1.0f);
    const VdbFileInfo info = inspectVdb(writeGrids("nan.vdb", {density, velocity, clean}));
    REQUIRE(info.grids.size() == 3);
    CHECK(info.grids[0].nanValues == 2);
    CHECK(info.grids[0].infValues == 1);
    CHECK(info.grids[0].minValue == 0.5);
    CHECK(info.grids[0].maxValue == 2.0);
    CHECK(info.grids[1].nanValues == 1);
    CHECK(info.grids[1].maxValue == Approx(5.0));
    CHECK(info.grids[2].nanValues + info.grids[2].infValues == 0);
    const std::string text = formatVdbInfo(info);
    CHECK(contains(text, "non-finite values: 2 NaN, 1 Inf"));
    CHECK(contains(text, "non-finite values: 1 NaN, 0 Inf"));
    // Only the two grids that hold them say so.
    size_t lines = 0;
    for (size_t at = text.find("non-finite"); at != std::string::npos;
         at = text.find("non-finite", at + 1))
        ++lines;
    CHECK(lines == 2);
}

TEST_CASE("an unnamed grid is labelled, an int grid is not 'stored as half'", "[vdb][info]") {
    ensureOpenVdbInitialized();
    auto unnamed = openvdb::FloatGrid::create(0.0f);
    unnamed->getAccessor().setValue({0, 0, 0}, 1.0f);
    unnamed->setSaveFloatAsHalf(true);
    auto flags = openvdb::Int32Grid::create(0);
    flags->setName("flags");
    flags->getAccessor().setValue({0, 0, 0}, 3);
    flags->setSaveFloatAsHalf(true);  // Blender writes the flag on every grid
    const std::string text = formatVdbInfo(inspectVdb(writeGrids("unnamed.vdb", {unnamed, flags})));
    INFO(text);
    CHECK(contains(text, "  (unnamed grid 0)  float (stored as half), class"));
    CHECK(contains(text, "  flags  int32, class"));
}
