// NanoVDB files (issue 20): read through the same importer as OpenVDB's, float and half-like
// (Fp16) grids, listed by eikon info, in sequences; truncated and corrupt files are errors, never
// a crash. The files are made here from OpenVDB grids with NanoVDB's own converter and writer.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <nanovdb/util/IO.h>
#include <nanovdb/util/OpenToNanoVDB.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/LevelSetUtil.h>

#include "core/error.h"
#include "core/field_registry.h"
#include "core/nanovdb_reader.h"
#include "core/vdb_import.h"
#include "core/vdb_info.h"
#include "core/vdb_sequence.h"
#include "support/test_paths.h"

using namespace eikon;

namespace {

// A fog ball: density 1 inside radius 4 voxels of 0.1, with a falloff, named "density".
openvdb::FloatGrid::Ptr fogBall() {
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(0.4f, {1.0f, 2.0f, 0.5f},
                                                                         0.1f, 3.0f);
    openvdb::tools::sdfToFogVolume(*grid);
    grid->setName("density");
    return grid;
}

template <typename NanoBuildT = float>
void writeNano(const std::string& path, const openvdb::FloatGrid& grid) {
    auto handle = nanovdb::openToNanoVDB<nanovdb::HostBuffer, openvdb::FloatTree, NanoBuildT>(
        grid, nanovdb::StatsMode::Default, nanovdb::ChecksumMode::Full);
    nanovdb::io::writeGrid(path, handle);
}

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace

TEST_CASE("a NanoVDB float grid imports as the OpenVDB grid it was made from", "[nanovdb]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("nanovdb_float");
    const auto ball = fogBall();
    writeNano(dir + "/ball.nvdb", *ball);
    FieldRegistry fields;
    importVdb(dir + "/ball.nvdb", fields);
    REQUIRE(fields.has("density"));
    const auto back = fields.floatGrid("density");
    CHECK(back->activeVoxelCount() == ball->activeVoxelCount());
    CHECK(back->transform() == ball->transform());
    size_t differing = 0;
    auto acc = back->getConstAccessor();
    for (auto it = ball->cbeginValueOn(); it; ++it) differing += acc.getValue(it.getCoord()) != *it;
    CHECK(differing == 0);

    const VdbFileInfo info = inspectVdb(dir + "/ball.nvdb");
    REQUIRE(info.grids.size() == 1);
    CHECK(info.grids[0].name == "density");
    CHECK(info.grids[0].type == "float");
    CHECK(info.grids[0].gridClass == "fog volume");
    CHECK(info.grids[0].activeVoxels == ball->activeVoxelCount());
    CHECK(formatVdbInfo(info).find("ball.nvdb: NanoVDB, 1 grid") != std::string::npos);
}

TEST_CASE("a NanoVDB Fp16 grid imports as float within half precision", "[nanovdb]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("nanovdb_fp16");
    const auto ball = fogBall();
    writeNano<nanovdb::Fp16>(dir + "/ball16.nvdb", *ball);
    FieldRegistry fields;
    importVdb(dir + "/ball16.nvdb", fields);
    const auto back = fields.floatGrid("density");
    auto acc = back->getConstAccessor();
    float worst = 0.0f;
    for (auto it = ball->cbeginValueOn(); it; ++it)
        worst = std::max(worst, std::abs(acc.getValue(it.getCoord()) - *it));
    // Fp16 quantizes each leaf's range [min, max] in 2^16 steps: here [0, 1].
    CHECK(worst <= 1.0f / 65535.0f);
    CHECK(inspectVdb(dir + "/ball16.nvdb").grids[0].type == "Float16");  // NanoVDB's name for Fp16
}

TEST_CASE("NanoVDB sequences are found like OpenVDB's", "[nanovdb][sequence]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("nanovdb_sequence");
    for (int f = 1; f <= 3; ++f)
        writeNano(dir + "/ball_000" + std::to_string(f) + ".nvdb", *fogBall());
    const VdbSequence seq = findVdbSequence(dir + "/ball_####.nvdb");
    CHECK(seq.frames.size() == 3);
    CHECK(seq.pattern() == dir + "/ball_####.nvdb");
}

TEST_CASE("truncated or corrupt NanoVDB files are one error, not a crash", "[nanovdb][bad-input]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("nanovdb_bad");
    writeNano(dir + "/good.nvdb", *fogBall());
    const std::string good = readBytes(dir + "/good.nvdb");
    REQUIRE(good.size() > 1000);
    for (size_t keep : {size_t(10), size_t(100), good.size() / 2, good.size() - 1}) {
        INFO("kept " << keep << " bytes");
        writeBytes(dir + "/cut.nvdb", good.substr(0, keep));
        FieldRegistry fields;
        CHECK_THROWS_WITH(importVdb(dir + "/cut.nvdb", fields),
                          Catch::StartsWith(dir + "/cut.nvdb: ") && Catch::Contains("truncated"));
    }
    // A flipped byte in the voxel data: the checksum says so.
    std::string flipped = good;
    flipped[good.size() - 200] = char(flipped[good.size() - 200] ^ 0x5a);
    writeBytes(dir + "/flipped.nvdb", flipped);
    FieldRegistry fields;
    CHECK_THROWS_WITH(importVdb(dir + "/flipped.nvdb", fields),
                      Catch::Contains("fails NanoVDB's validation"));
    // A grid name size past any name: refused before it is allocated.
    std::string badName = good;
    const size_t nameSizeAt = 16 + 136;  // header, then MetaData up to nameSize
    badName[nameSizeAt + 3] = char(0x7f);
    writeBytes(dir + "/badname.nvdb", badName);
    CHECK_THROWS_WITH(importVdb(dir + "/badname.nvdb", fields), Catch::Contains("grid name of"));
    // The tree's offset to its root pointing past the grid: refused before anything follows it
    // (NanoVDB itself would read that memory).
    std::string badRoot = good;
    const size_t nameSize =
        size_t(uint8_t(good[nameSizeAt])) | size_t(uint8_t(good[nameSizeAt + 1])) << 8;
    const size_t treeAt = 16 + 176 + nameSize + sizeof(nanovdb::GridData);
    badRoot[treeAt + 3 * 8 + 5] = char(0x40);  // mNodeOffset[3], the root's
    writeBytes(dir + "/badroot.nvdb", badRoot);
    CHECK_THROWS_WITH(importVdb(dir + "/badroot.nvdb", fields),
                      Catch::Contains("node offsets outside its bytes"));
}

TEST_CASE("a NanoVDB grid without a checksum is refused", "[nanovdb][bad-input]") {
    ensureOpenVdbInitialized();
    const std::string dir = test::scratchDir("nanovdb_no_checksum");
    auto handle = nanovdb::openToNanoVDB<nanovdb::HostBuffer, openvdb::FloatTree, float>(
        *fogBall(), nanovdb::StatsMode::Default, nanovdb::ChecksumMode::Disable);
    nanovdb::io::writeGrid(dir + "/plain.nvdb", handle);
    FieldRegistry fields;
    CHECK_THROWS_WITH(importVdb(dir + "/plain.nvdb", fields),
                      Catch::Contains("written without a checksum"));
}
