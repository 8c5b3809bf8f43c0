#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/error.h"
#include "core/procedural.h"
#include "core/vdb_export.h"
#include "core/vdb_file_id.h"
#include "core/vdb_import.h"
#include "core/vdb_info.h"
#include "support/test_paths.h"

using namespace eikon;

namespace {

template <typename GridT>
void requireSameGrid(const GridT& a, const GridT& b) {
    CHECK(a.activeVoxelCount() == b.activeVoxelCount());
    CHECK(a.transform() == b.transform());
    auto acc = b.getConstAccessor();
    size_t differing = 0;
    for (auto it = a.cbeginValueOn(); it; ++it)
        if (!(acc.getValue(it.getCoord()) == *it) || !acc.isValueOn(it.getCoord())) ++differing;
    CHECK(differing == 0);
}

}  // namespace

TEST_CASE("export then import round-trips values and transforms exactly", "[vdb][export]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("export_roundtrip");
    FieldRegistry original;
    importVdb(test::sharedData("vdb/blender_smoke_c42/fluid_data_0010.vdb"), original);
    // A procedural field with a non-trivial transform too.
    original.set("flame", makeSphereField({1.5f, -2.0f, 0.25f}, 0.7f, 3.0f, 0.2f, 0.07f), "test");

    const std::string path = dir + "/roundtrip.vdb";
    exportVdb(path, original, {"density", "temperature", "velocity", "flame", "color"});

    const VdbFileInfo info = inspectVdb(path);
    CHECK(info.creator == "Eikon");
    std::vector<std::string> names;
    for (const auto& g : info.grids) names.push_back(g.name);
    CHECK(names == std::vector<std::string>{"density", "temperature", "velocity", "flame", "Cd"});
    for (const auto& g : info.grids) {
        if (g.name == "velocity") CHECK(g.gridClass == "staggered");
        if (g.name == "density") CHECK(g.gridClass == "fog volume");
        CHECK_FALSE(g.savedAsHalf);
    }

    FieldRegistry back;
    importVdb(path, back);
    for (const char* f : {"density", "temperature", "flame"})
        requireSameGrid(*original.floatGrid(f), *back.floatGrid(f));
    for (const char* f : {"velocity", "color"}) {
        INFO(f);
        requireSameGrid(*openvdb::gridConstPtrCast<openvdb::Vec3SGrid>(original.get(f).grid),
                        *openvdb::gridConstPtrCast<openvdb::Vec3SGrid>(back.get(f).grid));
    }
    CHECK(back.get("velocity").isStaggered());
}

TEST_CASE("a failed export leaves the existing file untouched", "[vdb][export][bad-input]") {
    const std::string dir = test::scratchDir("export_failure");
    const std::string path = dir + "/keep.vdb";
    std::ofstream(path) << "precious";
    FieldRegistry fields;
    fields.set("density", makeSphereField({0, 0, 0}, 1.0f, 1.0f, 0.0f, 0.25f), "test");
    CHECK_THROWS_WITH(exportVdb(path, fields, {"density", "temperature"}),
                      Catch::Contains("no field 'temperature'"));
    CHECK_THROWS_WITH(exportVdb(dir + "/no/such/folder/x.vdb", fields, {"density"}),
                      Catch::Contains("does not exist"));
    std::ifstream in(path);
    std::string content;
    in >> content;
    CHECK(content == "precious");
    CHECK_FALSE(std::filesystem::exists(path + ".partial"));
}

namespace {

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("exporting the same fields twice gives byte-identical files", "[vdb][export]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("export_repeatable");
    FieldRegistry fields;
    fields.set("density", makeSphereField({0.0f, 0.0f, 0.0f}, 0.5f, 1.0f, 0.1f, 0.05f), "test");
    exportVdb(dir + "/a.vdb", fields, {"density"});
    exportVdb(dir + "/b.vdb", fields, {"density"});
    const std::string a = fileBytes(dir + "/a.vdb");
    REQUIRE(a.size() > 100);
    // OpenVDB alone stamps a random UUID at byte 21; ours is a hash of the rest.
    CHECK(a == fileBytes(dir + "/b.vdb"));
    CHECK(a.substr(21 + 8, 1) == "-");

    // Other contents, another identifier; and the file still reads back.
    fields.set("density", makeSphereField({0.0f, 0.0f, 0.0f}, 0.6f, 1.0f, 0.1f, 0.05f), "test");
    exportVdb(dir + "/c.vdb", fields, {"density"});
    CHECK(fileBytes(dir + "/c.vdb").substr(21, 36) != a.substr(21, 36));
    FieldRegistry back;
    importVdb(dir + "/c.vdb", back);
    CHECK(back.floatGrid("density")->activeVoxelCount() ==
          fields.floatGrid("density")->activeVoxelCount());
}

TEST_CASE("a file that is not a VDB is refused, not patched", "[vdb][export][bad-input]") {
    const std::string dir = test::scratchDir("export_repeatable_bad");
    const std::string path = dir + "/not_a.vdb";
    const std::string text(100, 'x');
    std::ofstream(path, std::ios::binary) << text;
    try {
        makeVdbFileIdDeterministic(path);
        FAIL("expected an error");
    } catch (const Error& e) {
        CHECK(e.where() == path);
        CHECK_THAT(e.reason(), Catch::Matchers::Contains("VDB header"));
    }
    CHECK(fileBytes(path) == text);
}

TEST_CASE("export prunes fog voxels below the stated tolerance, nothing else", "[vdb][export]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("export_prune");
    auto density = openvdb::FloatGrid::create(0.0f);
    auto acc = density->getAccessor();
    acc.setValue({0, 0, 0}, 1.0f);
    acc.setValue({1, 0, 0}, kExportPruneTolerance);  // at the tolerance: kept
    acc.setValue({2, 0, 0}, 1e-7f);
    acc.setValue({3, 0, 0}, 1.4e-45f);  // a denormal, as a decaying solver leaves
    acc.setValue({4, 0, 0}, -1e-8f);
    // An active tile of 8^3 voxels below the tolerance, and one above it.
    density->tree().addTile(1, openvdb::Coord(64, 0, 0), 1e-9f, true);
    density->tree().addTile(1, openvdb::Coord(128, 0, 0), 0.5f, true);
    auto velocity = openvdb::Vec3SGrid::create();
    velocity->getAccessor().setValue({0, 0, 0}, {1e-9f, 0.0f, 0.0f});  // vectors are not pruned
    FieldRegistry fields;
    fields.set("density", density, "test");
    fields.set("velocity", velocity, "test");
    const std::string path = dir + "/pruned.vdb";
    exportVdb(path, fields, {"density", "velocity"});

    FieldRegistry back;
    importVdb(path, back);
    const auto d = back.floatGrid("density");
    CHECK(d->activeVoxelCount() == 2 + 512);
    for (auto it = d->cbeginValueOn(); it; ++it) CHECK(std::abs(*it) >= kExportPruneTolerance);
    CHECK(d->tree().getValue({2, 0, 0}) == 0.0f);  // inactive and exactly background
    CHECK(d->tree().getValue({3, 0, 0}) == 0.0f);
    CHECK(back.get("velocity").grid->activeVoxelCount() == 1);
    // The registry's own grid is untouched: export prunes a copy.
    CHECK(density->activeVoxelCount() == 5 + 2 * 512);
}
