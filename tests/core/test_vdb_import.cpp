// Import of the real caches in ../shared/data/vdb, asserted against what OpenVDB's own
// `vdb_print -l` reports for them (see ../shared/data/vdb/SOURCES.md).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/log.h"
#include "core/printable.h"
#include "core/vdb_import.h"
#include "core/vdb_info.h"
#include "support/test_paths.h"

using namespace eikon;
using eikon::test::scratchDir;
using eikon::test::sharedData;

namespace {

const GridInfo& gridNamed(const VdbFileInfo& info, const std::string& name) {
    for (const auto& g : info.grids)
        if (g.name == name) return g;
    FAIL("no grid " << name << " in " << info.path);
    throw;
}

void checkBox(const GridInfo& g, std::array<int, 3> lo, std::array<int, 3> hi) {
    CHECK(g.indexMin == lo);
    CHECK(g.indexMax == hi);
}

// Copies the first `bytes` bytes of `from` to `to`.
void truncatedCopy(const std::string& from, const std::string& to, std::uintmax_t bytes) {
    std::ifstream in(from, std::ios::binary);
    std::vector<char> data(bytes);
    in.read(data.data(), std::streamsize(bytes));
    std::ofstream(to, std::ios::binary).write(data.data(), std::streamsize(bytes));
}

std::string importError(const std::string& path) {
    FieldRegistry fields;
    try {
        importVdb(path, fields);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("Houdini smoke: density, half float, translated origin, as vdb_print reports", "[vdb]") {
    const std::string path = sharedData("vdb/houdini_smoke1.vdb");
    const VdbFileInfo info = inspectVdb(path);
    CHECK(info.creator == "Houdini/SOP_OpenVDB_Write");
    REQUIRE(info.grids.size() == 1);
    const GridInfo& d = gridNamed(info, "density");
    CHECK(d.type == "float");
    CHECK(d.gridClass == "fog volume");
    CHECK(d.savedAsHalf);
    CHECK(d.activeVoxels == 1049275);
    // vdb_print rounds to 3 digits: voxel 0.476, translation (-34, -13.1, -26.4).
    CHECK(d.voxelSize[0] == Approx(0.476).epsilon(1e-3));
    checkBox(d, {1, 2, 1}, {111, 223, 112});
    // The outer face of voxel 1 in x is at voxel·(1 - 0.5) + translation.
    CHECK(d.worldMin[0] == Approx(0.476 * 0.5 - 34.0).margin(0.1));
    CHECK(d.worldMax[1] == Approx(0.476 * 223.5 - 13.1).margin(0.1));
    CHECK(d.minValue == Approx(1.00136e-05).epsilon(1e-3));
    CHECK(d.maxValue == Approx(5.71484).epsilon(1e-5));

    FieldRegistry fields;
    const VdbImportReport report = importVdb(path, fields);
    REQUIRE(fields.has("density"));
    CHECK(fields.get("density").grid->activeVoxelCount() == 1049275);
    CHECK(report.skipped.empty());
}

TEST_CASE("Houdini vel maps to velocity, a constant vec3 field with tiles", "[vdb]") {
    const std::string path = sharedData("vdb/houdini_vel_constant.vdb");
    const VdbFileInfo info = inspectVdb(path);  // gridNamed returns a reference into it
    const GridInfo& v = gridNamed(info, "vel");
    CHECK(v.type == "vec3s");
    CHECK(v.activeVoxels == 1000000);
    CHECK(v.voxelSize[0] == Approx(0.04));
    checkBox(v, {0, 0, 0}, {99, 99, 99});
    CHECK(v.minValue == Approx(15.0));
    CHECK(v.maxValue == Approx(15.0));

    FieldRegistry fields;
    importVdb(path, fields);
    REQUIRE(fields.has("velocity"));
    const Field& f = fields.get("velocity");
    CHECK(f.isVector());
    CHECK_FALSE(f.isStaggered());
    auto grid = openvdb::gridPtrCast<openvdb::Vec3SGrid>(f.grid);
    CHECK(grid->getConstAccessor().getValue(openvdb::Coord(50, 50, 50)) ==
          openvdb::Vec3s(0, -15, 0));
    const Bounds3 b = f.activeWorldBounds();
    CHECK(b.min.x == Approx(-1.98 - 0.02));
    CHECK(b.max.x == Approx(-1.98 + 0.04 * 99.5));
}

TEST_CASE("Blender Mantaflow cache: 24 grids, staggered velocity, int32 flags skipped", "[vdb]") {
    const std::string path = sharedData("vdb/blender_smoke_c42/fluid_data_0001.vdb");
    const VdbFileInfo info = inspectVdb(path);
    CHECK(info.grids.size() == 24);
    const GridInfo& d = gridNamed(info, "density");
    CHECK(d.type == "float");
    CHECK(d.gridClass == "fog volume");
    CHECK(d.savedAsHalf);
    CHECK(d.activeVoxels == 1665);
    CHECK(d.voxelSize[0] == Approx(0.8));
    checkBox(d, {63, 115, 7}, {73, 123, 34});
    const GridInfo& vel = gridNamed(info, "velocity");
    CHECK(vel.type == "vec3s");
    CHECK(vel.gridClass == "staggered");
    CHECK(vel.activeVoxels == 1650);
    checkBox(vel, {63, 115, 9}, {73, 123, 34});
    const GridInfo& flags = gridNamed(info, "flags");
    CHECK(flags.type == "int32");
    CHECK(flags.activeVoxels == 937500);
    CHECK(gridNamed(info, "temperature").activeVoxels == 1647);
    CHECK(gridNamed(info, "flame").empty);

    ScopedWarningCapture warnings;
    FieldRegistry fields;
    const VdbImportReport report = importVdb(path, fields);
    CHECK(fields.get("density").grid->activeVoxelCount() == 1665);
    CHECK(fields.get("temperature").grid->activeVoxelCount() == 1647);
    CHECK(fields.get("velocity").isStaggered());
    CHECK(fields.has("flame"));
    CHECK(fields.has("color"));  // combined from color_r/g/b
    CHECK(fields.get("color").isVector());
    CHECK_FALSE(fields.has("flags"));
    CHECK(warnings.contains("skipped grid flags: int32 grid"));
    CHECK(report.creator.empty());
}

TEST_CASE("alias table maps tool names to canonical fields, overridable", "[vdb]") {
    CHECK(canonicalFieldFor("vel") == "velocity");
    CHECK(canonicalFieldFor("v") == "velocity");
    CHECK(canonicalFieldFor("heat") == "temperature");
    CHECK(canonicalFieldFor("smoke") == "density");
    CHECK(canonicalFieldFor("density.2") == "density");
    CHECK(canonicalFieldFor("density_inflow") == "");
    CHECK(canonicalFieldFor("fire") == "flame");
    CHECK(canonicalFieldFor("Cd") == "color");
    CHECK(canonicalFieldFor("soot_fine", {{"density", {"soot_fine"}}}) == "density");

    // A file whose only scalar is named "heat" yields a temperature field; with an override
    // the grid "density_inflow" of a Blender cache becomes the density.
    FieldRegistry fields;
    importVdb(sharedData("vdb/blender_smoke_c42/fluid_data_0001.vdb"), fields,
              {{"density", {"density_inflow"}}});
    CHECK(fields.get("density").grid->activeVoxelCount() == 1151);
    CHECK(fields.get("density").origin.find("density_inflow") != std::string::npos);
}

TEST_CASE("truncated and corrupt files fail with the file and the reason", "[vdb][bad-input]") {
    const std::string dir = scratchDir("vdb_truncated");
    for (const char* name : {"houdini_smoke1.vdb", "houdini_vel_constant.vdb",
                             "blender_smoke_c42/fluid_data_0002.vdb"}) {
        const std::string src = sharedData(std::string("vdb/") + name);
        const auto size = std::filesystem::file_size(src);
        for (double fraction : {0.0, 0.001, 0.01, 0.3, 0.7, 0.999}) {
            const std::string cut = dir + "/cut.vdb";
            truncatedCopy(src, cut, std::uintmax_t(double(size) * fraction));
            const std::string message = importError(cut);
            INFO(name << " cut at " << fraction << ": " << message);
            CHECK(message.rfind(cut + ": ", 0) == 0);
            CHECK((message.find("not a readable VDB file") != std::string::npos ||
                   message.find("truncated or corrupt") != std::string::npos));
            CHECK_THROWS_AS(inspectVdb(cut), Error);
        }
    }
    // Not a VDB at all.
    const std::string text = dir + "/text.vdb";
    std::ofstream(text) << "this is not a VDB file, just text";
    CHECK(importError(text).find("not a readable VDB file") != std::string::npos);
    // The right magic number, then garbage.
    const std::string garbled = dir + "/garbled.vdb";
    truncatedCopy(sharedData("vdb/houdini_smoke1.vdb"), garbled, 4096);
    {
        std::fstream f(garbled, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(300);
        for (int i = 0; i < 2000; ++i) f.put(char((i * 131 + 7) & 0xff));
    }
    CHECK(importError(garbled).rfind(garbled + ": ", 0) == 0);
    CHECK(importError(dir + "/absent.vdb") == dir + "/absent.vdb: no such file");
}

TEST_CASE("NaN, Inf and negative density are rejected with a count", "[vdb][bad-input]") {
    ensureOpenVdbInitialized();
    const std::string dir = scratchDir("vdb_bad_values");
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("density");
    auto acc = grid->getAccessor();
    for (int i = 0; i < 10; ++i) acc.setValue(openvdb::Coord(i, 0, 0), 1.0f);
    acc.setValue(openvdb::Coord(3, 0, 0), std::numeric_limits<float>::quiet_NaN());
    acc.setValue(openvdb::Coord(4, 0, 0), std::numeric_limits<float>::infinity());
    openvdb::io::File(dir + "/nan.vdb").write({grid});
    CHECK(importError(dir + "/nan.vdb") == dir + "/nan.vdb: grid 'density' has 2 NaN/Inf values");

    acc.setValue(openvdb::Coord(3, 0, 0), -0.5f);
    acc.setValue(openvdb::Coord(4, 0, 0), 1.0f);
    openvdb::io::File(dir + "/negative.vdb").write({grid});
    const std::string message = importError(dir + "/negative.vdb");
    CHECK(message.find("grid 'density' (density) has 1 negative values") != std::string::npos);
    CHECK(message.find("must be >= 0") != std::string::npos);

    // Negative values in a field where they make sense (temperature in Celsius) load.
    grid->setName("temperature");
    openvdb::io::File(dir + "/cold.vdb").write({grid});
    FieldRegistry fields;
    importVdb(dir + "/cold.vdb", fields);
    CHECK(fields.has("temperature"));
}

TEST_CASE("a file with no usable grid is an error naming what was skipped", "[vdb][bad-input]") {
    ensureOpenVdbInitialized();
    const std::string dir = scratchDir("vdb_unusable");
    auto flags = openvdb::Int32Grid::create(0);
    flags->setName("flags");
    flags->tree().setValue(openvdb::Coord(1, 2, 3), 7);
    openvdb::io::File(dir + "/flags.vdb").write({flags});
    const std::string message = importError(dir + "/flags.vdb");
    CHECK(message == dir +
                         "/flags.vdb: no usable grid (skipped: flags: int32 grid, not a field "
                         "type (float, double, vec3s, vec3d))");
    openvdb::io::File(dir + "/empty.vdb").write(openvdb::GridPtrVec{});
    CHECK(importError(dir + "/empty.vdb") ==
          dir + "/empty.vdb: no usable grid (the file holds none)");
}

TEST_CASE("double-precision grids are narrowed to float fields", "[vdb]") {
    ensureOpenVdbInitialized();
    const std::string dir = scratchDir("vdb_double");
    auto grid = openvdb::DoubleGrid::create(0.0);
    grid->setName("smoke");
    grid->tree().setValue(openvdb::Coord(2, 2, 2), 0.25);
    grid->tree().fill(openvdb::CoordBBox({8, 8, 8}, {15, 15, 15}), 0.5, true);  // a tile
    openvdb::io::File(dir + "/double.vdb").write({grid});
    FieldRegistry fields;
    importVdb(dir + "/double.vdb", fields);
    auto f = fields.floatGrid("density");
    CHECK(f->tree().getValue(openvdb::Coord(2, 2, 2)) == 0.25f);
    CHECK(f->tree().getValue(openvdb::Coord(9, 9, 9)) == 0.5f);
    CHECK(f->activeVoxelCount() == 1 + 512);
}

TEST_CASE("a grid of an unregistered type is skipped by name, the rest of the file loads",
          "[vdb][bad-input]") {
    ensureOpenVdbInitialized();
    const std::string dir = scratchDir("vdb_unregistered");
    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->tree().setValue(openvdb::Coord(1, 1, 1), 0.5f);
    auto mystery = openvdb::FloatGrid::create(0.0f);
    mystery->setName("mystery");
    mystery->tree().setValue(openvdb::Coord(2, 2, 2), 1.0f);
    const std::string path = dir + "/unregistered.vdb";
    openvdb::io::File(path).write({mystery, density});

    // Rename the stored type of "mystery" to one no OpenVDB registers (same length, so every
    // offset in the file stays valid), as a point grid with an unknown codec or a newer tool's
    // grid type would look to this build.
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    const size_t name = bytes.find("mystery");
    REQUIRE(name != std::string::npos);
    const size_t type = bytes.find("Tree_float_5_4_3", name);
    REQUIRE(type != std::string::npos);
    bytes.replace(type, 16, "Tree_flaot_5_4_3");
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;

    ScopedWarningCapture warnings;
    FieldRegistry fields;
    const VdbImportReport report = importVdb(path, fields);
    CHECK(fields.has("density"));
    CHECK(fields.floatGrid("density")->tree().getValue(openvdb::Coord(1, 1, 1)) == 0.5f);
    CHECK_FALSE(fields.has("mystery"));
    CHECK(warnings.contains("skipped grid mystery: grid type Tree_flaot_5_4_3 is not registered"));

    const VdbFileInfo info = inspectVdb(path);
    REQUIRE(info.grids.size() == 2);
    CHECK_FALSE(gridNamed(info, "mystery").readable);
    CHECK(gridNamed(info, "density").activeVoxels == 1);
}

TEST_CASE("negative n is rejected: a material would map it below 1", "[vdb][bad-input]") {
    ensureOpenVdbInitialized();
    const std::string dir = scratchDir("vdb_negative_n");
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("n");
    grid->tree().setValue(openvdb::Coord(0, 0, 0), 0.5f);
    grid->tree().setValue(openvdb::Coord(1, 0, 0), -0.25f);
    openvdb::io::File(dir + "/n.vdb").write({grid});
    CHECK(importError(dir + "/n.vdb") ==
          dir +
              "/n.vdb: grid 'n' (n) has 1 negative values (minimum -0.250000); n must be >= 0 (a "
              "material maps it to n = 1 + f·(ior − 1) >= 1)");
}

TEST_CASE("grid names and types from the file are escaped in errors and warnings",
          "[vdb][bad-input]") {
    // A grid name is the file's bytes: a terminal escape or a line end in one would break the
    // one-line promise of eikon::Error (core/printable.h), so messages quote it escaped.
    ensureOpenVdbInitialized();
    const std::string dir = scratchDir("vdb_control_names");
    auto check = [](const std::string& message, const std::string& part) {
        INFO(message);
        CHECK_FALSE(hasControlCharacter(message));
        CHECK(message.find(part) != std::string::npos);
    };

    auto nan = openvdb::FloatGrid::create(0.0f);
    nan->setName("smoke\x1b[2J\n");
    nan->tree().setValue(openvdb::Coord(1, 2, 3), std::numeric_limits<float>::quiet_NaN());
    openvdb::io::File(dir + "/nan.vdb").write({nan});
    check(importError(dir + "/nan.vdb"), "grid 'smoke\\x1b[2J\\n' has 1 NaN/Inf values");

    // "density.*" maps this name to the density field, which must not be negative.
    auto negative = openvdb::FloatGrid::create(0.0f);
    negative->setName("density.\r");
    negative->tree().setValue(openvdb::Coord(0, 0, 0), -1.0f);
    openvdb::io::File(dir + "/negative.vdb").write({negative});
    check(importError(dir + "/negative.vdb"), "grid 'density.\\r' (density) has 1 negative");

    auto flags = openvdb::Int32Grid::create(0);
    flags->setName("flags\a");
    flags->tree().setValue(openvdb::Coord(0, 0, 0), 1);
    openvdb::io::File(dir + "/flags.vdb").write({flags});
    check(importError(dir + "/flags.vdb"), "(skipped: flags\\x07: int32 grid");

    // A stored type no OpenVDB registers, with a control character in it (same length).
    auto density = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->tree().setValue(openvdb::Coord(1, 1, 1), 0.5f);
    auto other = openvdb::FloatGrid::create(0.0f);
    other->setName("other");
    const std::string path = dir + "/type.vdb";
    openvdb::io::File(path).write({other, density});
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    const size_t type = bytes.find("Tree_float_5_4_3", bytes.find("other"));
    REQUIRE(type != std::string::npos);
    bytes.replace(type, 16,
                  "Tree_fl\x1b"
                  "at_5_4_3");
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    ScopedWarningCapture warnings;
    FieldRegistry fields;
    importVdb(path, fields);
    REQUIRE(warnings.warnings().size() == 1);
    check(warnings.warnings()[0], "skipped grid other: grid type Tree_fl\\x1bat_5_4_3 is not");

    // The fields a missing one is looked up among may be such names too.
    try {
        fields.set("n\t", fields.get("density").grid, "test");
        fields.get("absent");
        FAIL("no error");
    } catch (const Error& e) {
        check(e.what(), "fields present: density, n\\t)");
    }
}
