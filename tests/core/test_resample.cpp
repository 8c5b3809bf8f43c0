// From sparse fields to the dense render volume: exact on aligned grids, translation-equivariant,
// and the scene-level choices (auto bounds and resolution, procedural unions, missing fields).
#include <catch2/catch.hpp>

#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <random>

#include "core/error.h"
#include "core/procedural.h"
#include "core/resample.h"
#include "core/scene_sources.h"
#include "core/vdb_import.h"
#include "support/scene_builders.h"

#include <openvdb/tools/Interpolation.h>

using namespace eikon;

namespace {

Scene sceneReading(const std::string& field) {
    Scene scene;
    scene.path = "test.json";
    MaterialSpec m;
    m.name = "m";
    m.field = field;
    scene.materials.push_back(m);
    return scene;
}

SourceSpec sphere(glm::vec3 c, float r, float value, float voxel) {
    SourceSpec s = eikon::test::sphereSource("density", c, r, value, 0.0f, voxel);
    s.jsonPath = "/sources/x";
    return s;
}

}  // namespace

TEST_CASE("a cell-aligned box resamples to its value, with auto bounds and resolution",
          "[resample]") {
    ensureOpenVdbInitialized();
    FieldRegistry fields;
    fields.set("density", makeBoxField(glm::vec3(-1.0f), glm::vec3(1.0f), 0.75f, 0.0f, 0.05f),
               "test");
    const Scene scene = sceneReading("density");
    const RenderVolume v = chooseRenderVolume(scene, fields);
    CHECK(v.bounds.min.x == Approx(-1.0f));
    CHECK(v.bounds.max.z == Approx(1.0f));
    CHECK(v.resolution == glm::ivec3(40));
    const DenseGrid d = resampleToDense(fields.get("density"), v);
    float lo = 1e9f, hi = -1e9f;
    for (float x : d.values) lo = std::min(lo, x), hi = std::max(hi, x);
    // Voxel centres coincide; only the rounding of world -> index positions remains.
    CHECK(lo == Approx(0.75f).epsilon(1e-5));
    CHECK(hi == Approx(0.75f).epsilon(1e-5));
}

TEST_CASE("resampling follows the field's transform: a translated field gives a translated volume",
          "[resample]") {
    ensureOpenVdbInitialized();
    const glm::vec3 shift(0.5f, -0.25f, 0.75f);  // a multiple of the 0.05 voxel
    FieldRegistry a, b;
    a.set("density", makeSphereField({0, 0, 0}, 0.6f, 1.0f, 0.3f, 0.05f), "a");
    b.set("density", makeSphereField(shift, 0.6f, 1.0f, 0.3f, 0.05f), "b");
    RenderVolume va{{glm::vec3(-1.0f), glm::vec3(1.0f)}, glm::ivec3(23, 19, 17)};
    RenderVolume vb = va;
    vb.bounds.min += shift;
    vb.bounds.max += shift;
    const DenseGrid da = resampleToDense(a.get("density"), va);
    const DenseGrid db = resampleToDense(b.get("density"), vb);
    double worst = 0.0, total = 0.0;
    for (size_t i = 0; i < da.values.size(); ++i) {
        worst = std::max(worst, double(std::abs(da.values[i] - db.values[i])));
        total += da.values[i];
    }
    CHECK(total > 100.0);  // the sphere is there
    CHECK(worst < 1e-5);   // float rounding of the shifted sample positions only
}

TEST_CASE(
    "resampling gives BoxSampler's samples to the bit, whatever box of grid voxels it reads "
    "and in both compiled copies",
    "[resample]") {
    // resampleToDense reads each slab's grid voxels into a dense box first; every sample must
    // still be openvdb::tools::BoxSampler::sample's, for any linear transform, where the render
    // volume reaches past the grid's voxels, and where it is coarser than the grid (too large a
    // box: the accessor alone).
    ensureOpenVdbInitialized();
    auto grid = openvdb::FloatGrid::create(0.125f);  // the background shows past the voxels
    std::mt19937 random(7);
    std::uniform_real_distribution<float> value(-1.0f, 2.0f);
    auto acc = grid->getAccessor();
    for (int z = -9; z < 14; ++z)
        for (int y = -6; y < 11; ++y)
            for (int x = -12; x < 8; ++x) acc.setValue(openvdb::Coord(x, y, z), value(random));
    grid->tree().setValue(openvdb::Coord(20, 0, 0), -0.0f);  // a lone voxel in another leaf
    struct Case {
        const char* name;
        openvdb::math::Transform::Ptr xform;
        RenderVolume volume;
    };
    auto rotated = openvdb::math::Transform::createLinearTransform(0.1);
    rotated->postRotate(0.4, openvdb::math::Y_AXIS);
    rotated->postRotate(-0.7, openvdb::math::X_AXIS);
    rotated->postTranslate(openvdb::Vec3d(0.03, -0.11, 0.2));
    auto scaled = openvdb::math::Transform::createLinearTransform(0.1);
    scaled->preScale(openvdb::Vec3d(1.0, 0.7, 1.3));
    scaled->postTranslate(openvdb::Vec3d(-0.017, 0.05, 0.0));
    // The maps OpenVDB, Houdini and Blender write, which resampleToDense calls directly.
    const auto uniformShift = openvdb::math::Transform::Ptr(
        new openvdb::math::Transform(std::make_shared<openvdb::math::UniformScaleTranslateMap>(
            0.1, openvdb::Vec3d(0.013, -0.2, 0.05))));
    const auto scaleShift = openvdb::math::Transform::Ptr(
        new openvdb::math::Transform(std::make_shared<openvdb::math::ScaleTranslateMap>(
            openvdb::Vec3d(0.1, 0.07, 0.13), openvdb::Vec3d(-0.017, 0.05, 0.0))));
    REQUIRE(uniformShift->mapType() == openvdb::math::UniformScaleTranslateMap::mapType());
    REQUIRE(scaleShift->mapType() == openvdb::math::ScaleTranslateMap::mapType());
    const Case cases[] = {
        {"uniform scale and translation",
         uniformShift,
         {{glm::vec3(-1.2f, -0.6f, -0.9f), glm::vec3(0.8f, 1.1f, 1.4f)}, glm::ivec3(23, 17, 29)}},
        {"scale and translation",
         scaleShift,
         {{glm::vec3(-1.7f, -0.9f, -1.6f), glm::vec3(1.1f, 1.3f, 2.2f)}, glm::ivec3(37, 29, 45)}},
        {"aligned",
         openvdb::math::Transform::createLinearTransform(0.1),
         {{glm::vec3(-1.2f, -0.6f, -0.9f), glm::vec3(0.8f, 1.1f, 1.4f)}, glm::ivec3(20, 17, 23)}},
        {"finer, offset, past the voxels",
         scaled,
         {{glm::vec3(-1.7f, -0.9f, -1.6f), glm::vec3(1.1f, 1.3f, 2.2f)}, glm::ivec3(37, 29, 45)}},
        {"rotated",
         rotated,
         {{glm::vec3(-1.0f, -1.0f, -1.0f), glm::vec3(1.0f, 1.0f, 1.0f)}, glm::ivec3(31, 26, 19)}},
        {"coarser than the grid",
         openvdb::math::Transform::createLinearTransform(0.02),
         {{glm::vec3(-0.3f, -0.15f, -0.2f), glm::vec3(0.45f, 0.2f, 0.3f)}, glm::ivec3(9, 5, 6)}},
        {"one plane",
         openvdb::math::Transform::createLinearTransform(0.1),
         {{glm::vec3(-1.0f, -0.5f, 0.0f), glm::vec3(0.5f, 0.8f, 0.1f)}, glm::ivec3(15, 13, 1)}},
    };
    if (!resampleRunsAvx2())
        WARN(
            "no AVX2 copy here (not x86-64 with AVX2, a sanitizer build, or EIKON_CPU_AVX2=0): "
            "both copies below run the baseline");
    for (const ResampleCopy copy : {ResampleCopy::Auto, ResampleCopy::Baseline})
        for (const Case& c : cases) {
            INFO(c.name << (copy == ResampleCopy::Auto ? " (the AVX2 copy where it runs)"
                                                       : " (the baseline copy)"));
            grid->setTransform(c.xform);
            Field field;
            field.name = "density";
            field.grid = grid;
            const DenseGrid dense = resampleToDense(field, c.volume, copy);
            const auto reader = grid->getConstAccessor();
            const glm::ivec3 res = c.volume.resolution;
            size_t differ = 0;
            for (int k = 0; k < res.z; ++k)
                for (int j = 0; j < res.y; ++j)
                    for (int i = 0; i < res.x; ++i) {
                        const glm::vec3 w = c.volume.voxelCenter(i, j, k);
                        const float expected = openvdb::tools::BoxSampler::sample(
                            reader, c.xform->worldToIndex(openvdb::Vec3d(w.x, w.y, w.z)));
                        const float got = dense.values[dense.index(i, j, k)];
                        if (std::memcmp(&expected, &got, sizeof(float)) != 0) ++differ;
                    }
            CHECK(differ == 0);
        }
}

TEST_CASE("procedural shapes on one field form a union, mismatched voxels are an error",
          "[resample][sources]") {
    Scene scene = sceneReading("density");
    scene.sources = {sphere({-0.5f, 0, 0}, 0.4f, 1.0f, 0.05f),
                     sphere({0.5f, 0, 0}, 0.4f, 2.0f, 0.05f)};
    FieldRegistry fields;
    SceneSources(scene).loadFrame(0, fields);
    auto grid = fields.floatGrid("density");
    const auto& xform = grid->transform();
    auto valueAt = [&](glm::vec3 p) {
        return openvdb::tools::BoxSampler::sample(
            grid->tree(), xform.worldToIndex(openvdb::Vec3d(p.x, p.y, p.z)));
    };
    CHECK(valueAt({-0.5f, 0, 0}) == Approx(1.0f));
    CHECK(valueAt({0.5f, 0, 0}) == Approx(2.0f));
    CHECK(valueAt({0, 0.9f, 0}) == Approx(0.0f));

    scene.sources[1].voxelSize = 0.1f;
    FieldRegistry other;
    CHECK_THROWS_WITH(SceneSources(scene).loadFrame(0, other),
                      Catch::Contains("must share one voxel_size"));
}

TEST_CASE("a material reading a field no source provides names the JSON path", "[resample]") {
    ensureOpenVdbInitialized();
    FieldRegistry fields;
    fields.set("density", makeSphereField({0, 0, 0}, 1.0f, 1.0f, 0.0f, 0.1f), "test");
    const Scene scene = sceneReading("flame");
    CHECK_THROWS_WITH(chooseRenderVolume(scene, fields),
                      Catch::StartsWith("test.json:/materials/0/field: material 'm' reads field "
                                        "'flame', which no source provides (fields present: "
                                        "density)"));
}

TEST_CASE("NaN in a field is stopped at resampling, naming the field and its origin",
          "[resample][bad-input]") {
    ensureOpenVdbInitialized();
    FieldRegistry fields;
    auto grid = makeBoxField(glm::vec3(-1.0f), glm::vec3(1.0f), 1.0f, 0.0f, 0.1f);
    grid->tree().setValue(openvdb::Coord(3, 3, 3), std::numeric_limits<float>::quiet_NaN());
    fields.set("n", grid, "glass.json:/sources/1");
    const RenderVolume v{{glm::vec3(-1.0f), glm::vec3(1.0f)}, glm::ivec3(20)};
    CHECK_THROWS_WITH(resampleToDense(fields.get("n"), v),
                      Catch::StartsWith("glass.json:/sources/1: field 'n' has NaN/Inf values ("));
}

TEST_CASE("a negative field that a refracting material reads: n < 1 is an error naming it",
          "[resample][bad-input]") {
    ensureOpenVdbInitialized();
    // Temperature may be negative; a material of ior 1.5 reading it would make n = 1 − 0.25.
    Scene scene = sceneReading("temperature");
    scene.materials[0].name = "hot_glass";
    scene.materials[0].ior = 1.5f;
    FieldRegistry fields;
    fields.set("temperature",
               makeBoxField(glm::vec3(0.0f, 0.0f, 0.0f), glm::vec3(0.5f), -0.5f, 0.0f, 0.1f),
               "cold.vdb:temperature");
    const RenderVolume v{{glm::vec3(-1.0f), glm::vec3(1.0f)}, glm::ivec3(20)};
    std::map<std::string, DenseGrid> dense{
        {"temperature", resampleToDense(fields.get("temperature"), v)}};
    CHECK_THROWS_WITH(checkRefractiveIndex(scene, fields, dense),
                      Catch::StartsWith("test.json:/materials/0/field: material 'hot_glass' (ior "
                                        "1.5) reads field 'temperature' (from "
                                        "cold.vdb:temperature), which is -0.5 at (0.05, 0.05, "
                                        "0.05): the materials make n = 0.75 there (the lowest; "
                                        "n < 1 in 125 voxels), and n must be >= 1"));
    // With ior 1 the field bends nothing, and a second material's positive index that makes up
    // for it keeps n >= 1.
    scene.materials[0].ior = 1.0f;
    CHECK_NOTHROW(checkRefractiveIndex(scene, fields, dense));
    scene.materials[0].ior = 1.5f;
    MaterialSpec glass;
    glass.name = "glass";
    glass.field = "n";
    glass.ior = 2.0f;
    scene.materials.push_back(glass);
    fields.set("n", makeBoxField(glm::vec3(-1.0f), glm::vec3(1.0f), 0.25f, 0.0f, 0.1f), "n");
    dense["n"] = resampleToDense(fields.get("n"), v);
    CHECK_NOTHROW(checkRefractiveIndex(scene, fields, dense));
}

TEST_CASE("Gladstone-Dale air: hot air's n < 1 is meant, a temperature below absolute zero is not",
          "[resample][bad-input]") {
    ensureOpenVdbInitialized();
    Scene scene = sceneReading("temperature");
    scene.materials[0].name = "hot_air";
    scene.materials[0].gladstoneDale = 0.5f;
    scene.materials[0].ambientKelvin = 300.0f;
    scene.materials[0].ior = 1.0f - 0.5f / 300.0f;
    const RenderVolume v{{glm::vec3(-1.0f), glm::vec3(1.0f)}, glm::ivec3(20)};
    FieldRegistry fields;
    auto check = [&](float excess) {
        fields.set("temperature",
                   makeBoxField(glm::vec3(0.0f), glm::vec3(0.5f), excess, 0.0f, 0.1f),
                   "plume.vdb:temperature");
        std::map<std::string, DenseGrid> dense{
            {"temperature", resampleToDense(fields.get("temperature"), v)}};
        checkRefractiveIndex(scene, fields, dense);
    };
    // 600 K above ambient: n = 1 − 0.5·600/900 there, well below 1, and valid.
    CHECK_NOTHROW(check(600.0f));
    CHECK_NOTHROW(check(-250.0f));  // cold air, still above absolute zero
    CHECK_THROWS_WITH(check(-300.0f),
                      Catch::StartsWith("test.json:/materials/0/field: material 'hot_air' "
                                        "(gladstone_dale 0.5, ambient_kelvin 300) reads field "
                                        "'temperature' (from plume.vdb:temperature) as a "
                                        "temperature excess in kelvin, which is -300 at (0.05, "
                                        "0.05, 0.05): at or below absolute zero"));
}
