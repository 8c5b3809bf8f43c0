// Level sets as solids (issue 20, core/level_set.h): the coverage of a level-set sphere against the
// sphere's exact volume and its exact per-voxel coverage, under a placement; the grid chosen by
// class, name or index, with every refusal one message naming the file and its grids. The files
// are made here with OpenVDB's own level-set tools.
#include <catch2/catch.hpp>

#include <cmath>

#include <nanovdb/util/IO.h>
#include <nanovdb/util/OpenToNanoVDB.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/LevelSetUtil.h>
#include <glm/gtc/quaternion.hpp>

#include "core/error.h"
#include "core/level_set.h"
#include "core/vdb_import.h"
#include "support/test_paths.h"

using namespace eikon;

namespace {

constexpr float kRadius = 0.5f;
const glm::vec3 kCentre(0.1f, -0.05f, 0.0f);
constexpr float kSetVoxel = 0.02f;
// The sphere's volume from the coverage (measured −0.08 % at 12 and 25 render voxels per radius:
// the level set's own trilinear surface, the same at both).
constexpr double kVolumeTolerance = 0.002;
// Per voxel against the exact fraction (the mean over 12³ points): a plane cut stands in for the
// curved surface across the voxel (measured worst 0.023, mean 0.002; a linear ramp across the
// voxel's extent, tried first, was 0.18 and 0.04: a diagonal plane cuts faster near the centre).
constexpr double kVoxelTolerance = 0.03;
constexpr double kMeanVoxelTolerance = 0.003;

openvdb::FloatGrid::Ptr sphereSet(const std::string& name) {
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
        kRadius, {kCentre.x, kCentre.y, kCentre.z}, kSetVoxel, 3.0f);
    grid->setName(name);
    return grid;
}

void writeGrids(const std::string& path, openvdb::GridPtrVec grids) {
    openvdb::io::File(path).write(grids);
}

RenderVolume cube(float halfWidth, int resolution) {
    return {{glm::vec3(-halfWidth), glm::vec3(halfWidth)}, glm::ivec3(resolution)};
}

double volumeOf(const std::vector<float>& coverage, const RenderVolume& v) {
    double sum = 0.0;
    for (float c : coverage) sum += c;
    const glm::vec3 h = v.voxelSize();
    return sum * double(h.x) * double(h.y) * double(h.z);
}

const double kSphereVolume = 4.0 / 3.0 * M_PI * std::pow(double(kRadius), 3);

}  // namespace

TEST_CASE("a level-set sphere covers its volume and each voxel as the exact sphere does",
          "[level_set]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("level_set_sphere");
    writeGrids(dir + "/sphere.vdb", {sphereSet("surface")});
    const LevelSet set = LevelSet::read(dir + "/sphere.vdb", {});
    CHECK(set.label() == "'surface' (grid 0)");
    const Bounds3 b = set.bounds();
    for (int a = 0; a < 3; ++a) {  // the sphere's box, within two of the set's voxels
        CHECK(b.min[a] <= kCentre[a] - kRadius);
        CHECK(b.min[a] >= kCentre[a] - kRadius - 2.0f * kSetVoxel);
        CHECK(b.max[a] >= kCentre[a] + kRadius);
        CHECK(b.max[a] <= kCentre[a] + kRadius + 2.0f * kSetVoxel);
    }
    const MeshObjectSpec identity;
    // Render voxels as fine as the set's, and twice as coarse (sub-voxels averaged).
    for (int resolution : {80, 40}) {
        INFO("resolution " << resolution);
        const RenderVolume v = cube(0.8f, resolution);
        const std::vector<float> coverage = set.coverage(v, identity);
        CHECK(volumeOf(coverage, v) == Approx(kSphereVolume).epsilon(kVolumeTolerance));
        double worst = 0.0, sum = 0.0;
        int cut = 0;
        const glm::vec3 h = v.voxelSize();
        for (int k = 0; k < resolution; ++k)
            for (int j = 0; j < resolution; ++j)
                for (int i = 0; i < resolution; ++i) {
                    const glm::vec3 c = v.voxelCenter(i, j, k);
                    const float got = coverage[(size_t(k) * resolution + j) * resolution + i];
                    REQUIRE(got >= 0.0f);
                    REQUIRE(got <= 1.0f);
                    if (std::abs(glm::length(c - kCentre) - kRadius) > glm::length(h)) {
                        CHECK(got == (glm::length(c - kCentre) < kRadius ? 1.0f : 0.0f));
                        continue;
                    }
                    int inside = 0;
                    for (int s = 0; s < 12 * 12 * 12; ++s) {
                        const glm::vec3 f((s % 12 + 0.5f) / 12.0f, (s / 12 % 12 + 0.5f) / 12.0f,
                                          (s / 144 + 0.5f) / 12.0f);
                        if (glm::length(c + (f - 0.5f) * h - kCentre) < kRadius) ++inside;
                    }
                    const double error = std::abs(double(got) - inside / 1728.0);
                    worst = std::max(worst, error);
                    sum += error;
                    ++cut;
                }
        CHECK(worst < kVoxelTolerance);
        CHECK(sum / cut < kMeanVoxelTolerance);
    }
}

TEST_CASE("a placed level set covers the scaled, turned and moved solid", "[level_set]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("level_set_placed");
    writeGrids(dir + "/sphere.vdb", {sphereSet("surface")});
    const LevelSet set = LevelSet::read(dir + "/sphere.vdb", {});
    MeshObjectSpec placement;
    placement.scale = glm::vec3(1.2f, 0.6f, 0.9f);
    placement.rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f)));
    placement.translation = glm::vec3(0.2f, 0.1f, -0.15f);
    const RenderVolume v = cube(1.0f, 64);
    const std::vector<float> coverage = set.coverage(v, placement);
    const double scale = double(placement.scale.x) * placement.scale.y * placement.scale.z;
    CHECK(volumeOf(coverage, v) == Approx(kSphereVolume * scale).epsilon(kVolumeTolerance));
    // Its centroid is the sphere's centre placed.
    glm::dvec3 moment(0.0);
    double mass = 0.0;
    for (int k = 0; k < 64; ++k)
        for (int j = 0; j < 64; ++j)
            for (int i = 0; i < 64; ++i) {
                const double c = coverage[(size_t(k) * 64 + j) * 64 + i];
                moment += c * glm::dvec3(v.voxelCenter(i, j, k));
                mass += c;
            }
    const glm::vec3 expected =
        placement.translation + placement.rotation * (placement.scale * kCentre);
    const glm::dvec3 centroid = moment / mass;
    for (int a = 0; a < 3; ++a) CHECK(centroid[a] == Approx(expected[a]).margin(1e-3));

    // The obstacle cells: centres inside the placed ellipsoid.
    const InsideBits bits = set.inside(v.bounds.min, v.voxelSize(), v.resolution, placement);
    int wrong = 0, inside = 0;
    for (int k = 0; k < 64; ++k)
        for (int j = 0; j < 64; ++j)
            for (int i = 0; i < 64; ++i) {
                const glm::vec3 local = (glm::conjugate(placement.rotation) *
                                         (v.voxelCenter(i, j, k) - placement.translation)) /
                                        placement.scale;
                const float r = glm::length(local - kCentre);
                const bool truth = r < kRadius;
                inside += bits.inside(i, j, k);
                // Cells within a voxel of the surface may go either way (trilinear distance).
                if (bits.inside(i, j, k) != truth && std::abs(r - kRadius) > 2.0f * kSetVoxel)
                    ++wrong;
            }
    CHECK(wrong == 0);
    const double cell = std::pow(double(v.voxelSize().x), 3);
    CHECK(inside * cell == Approx(kSphereVolume * scale).epsilon(0.03));
}

TEST_CASE("the level set is chosen by class, name or index", "[level_set]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("level_set_choice");
    auto fog = sphereSet("density");
    openvdb::tools::sdfToFogVolume(*fog);
    auto a = sphereSet("a");
    auto b = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(0.25f, {0, 0, 0}, 0.02f);
    b->setName("b");
    writeGrids(dir + "/two.vdb", {fog, a, b});
    writeGrids(dir + "/fog.vdb", {fog});
    auto unnamed = sphereSet("");
    unnamed->setGridClass(openvdb::GRID_UNKNOWN);  // zeno writes its SDFs so
    writeGrids(dir + "/unnamed.vdb", {fog, unnamed});

    CHECK_THROWS_WITH(
        LevelSet::read(dir + "/two.vdb", {}),
        Catch::Contains("two.vdb: holds 2 level sets") &&
            Catch::Contains("'density' (grid 0): fog volume float") &&
            Catch::Contains("'b' (grid 2): level set float") &&
            Catch::Contains("choose one by its name or index (\"grid\" in a scene's mesh"));
    CHECK(LevelSet::read(dir + "/two.vdb", {"b", -1}).label() == "'b' (grid 2)");
    CHECK(LevelSet::read(dir + "/two.vdb", {"", 1}).label() == "'a' (grid 1)");
    CHECK(LevelSet::read(dir + "/two.vdb", {"b", -1}).bounds().max.x < 0.3f);
    CHECK_THROWS_WITH(LevelSet::read(dir + "/two.vdb", {"c", -1}),
                      Catch::Contains("no grid named 'c' (grids: 'density' (grid 0)"));
    CHECK_THROWS_WITH(LevelSet::read(dir + "/two.vdb", {"", 3}),
                      Catch::Contains("has 3 grids (index 0-2), no grid 3"));
    CHECK_THROWS_WITH(LevelSet::read(dir + "/two.vdb", {"density", -1}),
                      Catch::Contains("'density' (grid 0) has no value below zero") &&
                          Catch::Contains("a fog volume, not a signed distance"));
    CHECK_THROWS_WITH(LevelSet::read(dir + "/fog.vdb", {}),
                      Catch::Contains("fog.vdb: holds no level set (grids: 'density' (grid 0)") &&
                          Catch::Contains("choose a signed-distance grid by its name or index"));
    // An unnamed SDF of no class: by index only, labelled.
    CHECK_THROWS_WITH(LevelSet::read(dir + "/unnamed.vdb", {}),
                      Catch::Contains("unnamed grid 1: unknown float"));
    const LevelSet chosen = LevelSet::read(dir + "/unnamed.vdb", {"", 1});
    CHECK(chosen.label() == "unnamed grid 1");
    const RenderVolume v = cube(0.8f, 40);
    CHECK(volumeOf(chosen.coverage(v, {}), v) == Approx(kSphereVolume).epsilon(kVolumeTolerance));
}

TEST_CASE("a level set whose writer left its inside unflooded is still solid", "[level_set]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("level_set_unflooded");
    auto grid = sphereSet("sdf");
    // The inside tiles and voxels off the band set to +background, as a writer that never ran
    // signedFloodFill leaves them: without the flood the ball would be a hollow shell.
    const float background = grid->background();
    for (auto it = grid->tree().beginValueOff(); it; ++it)
        if (*it < 0.0f) it.setValue(background);
    writeGrids(dir + "/hollow.vdb", {grid});
    const RenderVolume v = cube(0.8f, 40);
    CHECK(volumeOf(LevelSet::read(dir + "/hollow.vdb", {}).coverage(v, {}), v) ==
          Approx(kSphereVolume).epsilon(kVolumeTolerance));
}

TEST_CASE("double and NanoVDB level sets read as float ones", "[level_set]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("level_set_types");
    auto dgrid = openvdb::tools::createLevelSetSphere<openvdb::DoubleGrid>(
        kRadius, {kCentre.x, kCentre.y, kCentre.z}, kSetVoxel, 3.0f);
    dgrid->setName("d");
    writeGrids(dir + "/double.vdb", {dgrid});
    auto handle = nanovdb::openToNanoVDB<nanovdb::HostBuffer, openvdb::FloatTree, float>(
        *sphereSet("surface"), nanovdb::StatsMode::Default, nanovdb::ChecksumMode::Full);
    nanovdb::io::writeGrid(dir + "/sphere.nvdb", handle);
    const RenderVolume v = cube(0.8f, 40);
    for (const char* file : {"/double.vdb", "/sphere.nvdb"}) {
        INFO(file);
        const LevelSet set = LevelSet::read(dir + file, {});
        CHECK(volumeOf(set.coverage(v, {}), v) == Approx(kSphereVolume).epsilon(kVolumeTolerance));
    }
}

TEST_CASE("a level set with NaN or of a vector type is refused with one message", "[level_set]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("level_set_refused");
    auto grid = sphereSet("surface");
    grid->tree().setValue(openvdb::Coord(0, 0, 0), NAN);
    writeGrids(dir + "/nan.vdb", {grid});
    CHECK_THROWS_WITH(LevelSet::read(dir + "/nan.vdb", {}),
                      Catch::Contains("nan.vdb: 'surface' (grid 0) has 1 NaN/Inf values"));
    auto vel = openvdb::Vec3SGrid::create();
    vel->setName("vel");
    vel->tree().setValue(openvdb::Coord(0, 0, 0), openvdb::Vec3s(1, 0, 0));
    writeGrids(dir + "/vel.vdb", {vel});
    CHECK_THROWS_WITH(LevelSet::read(dir + "/vel.vdb", {"vel", -1}),
                      Catch::Contains("'vel' (grid 0) is vec3s, not a signed distance"));
    CHECK_THROWS_WITH(LevelSet::read(dir + "/missing.vdb", {}), Catch::Contains("missing.vdb"));
}
