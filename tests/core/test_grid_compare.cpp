// Voxel-by-voxel comparison of VDB files (core/grid_compare.h), for eikon regress's cache checks.
#include <catch2/catch.hpp>

#include <openvdb/openvdb.h>

#include "core/grid_compare.h"
#include "support/test_paths.h"

namespace {

struct Grids {
    openvdb::FloatGrid::Ptr density = openvdb::FloatGrid::create(0.0f);
    openvdb::Vec3SGrid::Ptr velocity = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
};

Grids smoke() {
    openvdb::initialize();
    Grids g;
    g.density->setName("density");
    g.velocity->setName("velocity");
    auto d = g.density->getAccessor();
    auto v = g.velocity->getAccessor();
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 5; ++j)
            for (int k = 0; k < 4; ++k) {
                d.setValue({i, j, k}, 0.1f * float(i + j + k));
                v.setValue({i, j, k}, openvdb::Vec3s(float(i), 0.5f, -float(k)));
            }
    return g;
}

std::string write(const std::string& path, const openvdb::GridPtrVec& grids) {
    openvdb::io::File(path).write(grids);
    return path;
}

}  // namespace

TEST_CASE("equal VDB files compare equal voxel for voxel", "[grid_compare]") {
    const std::string dir = eikon::test::scratchDir("grid_compare_equal");
    const Grids a = smoke(), b = smoke();
    const auto d = eikon::compareVdbFiles(write(dir + "/b.vdb", {b.density, b.velocity}),
                                          write(dir + "/a.vdb", {a.density, a.velocity}), 0.0);
    CHECK(d.within());
    REQUIRE(d.grids.size() == 2);
    CHECK(d.grids[0].name == "density");
    CHECK(d.grids[0].voxelsCompared == 120);
    CHECK(d.grids[1].maxDifference == 0.0);
}

TEST_CASE("differing voxels are counted and the worst listed with their values", "[grid_compare]") {
    const std::string dir = eikon::test::scratchDir("grid_compare_differ");
    const Grids a = smoke(), b = smoke();
    b.density->tree().setValue({2, 3, 1}, 0.6f + 0.5f);    // 0.6 before
    b.density->tree().setValue({1, 1, 1}, 0.3f + 0.001f);  // within 0.01
    b.density->tree().setValue({40, 0, 0}, 0.25f);         // active in the new file only
    b.velocity->tree().setValue({0, 0, 3}, openvdb::Vec3s(0.0f, 0.5f, -3.2f));  // z by 0.2
    const auto d = eikon::compareVdbFiles(write(dir + "/b.vdb", {b.density, b.velocity}),
                                          write(dir + "/a.vdb", {a.density, a.velocity}), 0.01);
    CHECK_FALSE(d.within());
    REQUIRE(d.grids.size() == 2);
    const eikon::GridDifference& density = d.grids[0];
    CHECK(density.voxelsCompared == 121);
    CHECK(density.voxelsOver == 2);
    CHECK(density.maxDifference == Approx(0.5).epsilon(1e-6));
    REQUIRE(density.worst.size() == 3);
    CHECK(density.worst[0].ijk == glm::ivec3(2, 3, 1));
    CHECK(density.worst[0].reference == Approx(0.6).epsilon(1e-6));
    CHECK(density.worst[0].test == Approx(1.1).epsilon(1e-6));
    CHECK(density.worst[1].ijk == glm::ivec3(40, 0, 0));
    CHECK(density.worst[1].reference == 0.0);  // the background
    const eikon::GridDifference& velocity = d.grids[1];
    CHECK(velocity.voxelsOver == 1);
    CHECK(velocity.maxDifference == Approx(0.2).epsilon(1e-5));
    const std::string same = dir + "/b.vdb";
    CHECK(eikon::compareVdbFiles(same, dir + "/a.vdb", 0.6).within());
}

TEST_CASE("a missing grid, a grid of another type and a grid not asked for", "[grid_compare]") {
    const std::string dir = eikon::test::scratchDir("grid_compare_problems");
    const Grids a = smoke(), b = smoke();
    auto asDouble = openvdb::DoubleGrid::create(0.0);
    asDouble->setName("velocity");
    const std::string ref = write(dir + "/a.vdb", {a.density, a.velocity});
    const auto missing = eikon::compareVdbFiles(write(dir + "/b.vdb", {b.density}), ref, 1.0);
    REQUIRE(missing.problems.size() == 1);
    CHECK(missing.problems[0] == "grid 'velocity' is missing from the new file");
    CHECK_FALSE(missing.within());
    const auto retyped =
        eikon::compareVdbFiles(write(dir + "/c.vdb", {b.density, asDouble}), ref, 1.0);
    REQUIRE(retyped.problems.size() == 1);
    CHECK(retyped.problems[0].find("grid 'velocity' is ") == 0);
    const auto onlyDensity =
        eikon::compareVdbFiles(write(dir + "/d.vdb", {b.density}), ref, 0.0, {"density"});
    CHECK(onlyDensity.within());
    const auto unknown = eikon::compareVdbFiles(dir + "/d.vdb", ref, 0.0, {"smoke"});
    CHECK(unknown.problems.at(0) == "grid 'smoke' is not in the reference");
    CHECK_THROWS_WITH(eikon::compareVdbFiles(dir + "/none.vdb", ref, 0.0),
                      Catch::Contains("none.vdb"));
}
