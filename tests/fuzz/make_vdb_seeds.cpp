// Writes the VDB seeds in tests/fuzz/corpus/vdb/: small (libFuzzer slows down on big inputs, and
// each file stays under 64 KB), and between them every kind of grid and storage the reader meets.
// Not built by default (tests/fuzz/CMakeLists.txt); regenerate with
//   cmake --build build-fuzz --target make_vdb_seeds
//   build-fuzz/tests/fuzz/make_vdb_seeds ../shared/data/vdb tests/fuzz/corpus/vdb
// The shared caches are cut down, not copied: their grids clipped to a few voxels (metadata,
// half-float flags, classes and the file's compression kept), and the first bytes of each file
// as it came (header, metadata and grid descriptors in the writing tool's own bytes).
#include <openvdb/openvdb.h>
#include <openvdb/points/PointConversion.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <string>

#include "core/field_registry.h"
#include "core/vdb_export.h"
#include "core/vdb_file_id.h"

namespace {

using namespace openvdb;
namespace fs = std::filesystem;

std::string outDir;

void write(const std::string& name, const GridPtrVec& grids, uint32_t compression,
           const MetaMap& meta = MetaMap()) {
    const std::string path = outDir + "/" + name;
    io::File file(path);
    file.setCompression(compression);
    file.write(grids, meta);
    file.close();
    eikon::makeVdbFileIdDeterministic(path);
    std::printf("%-40s %7ju bytes\n", name.c_str(), std::uintmax_t(fs::file_size(path)));
}

// `source`'s grids named in `keep` (all when empty), clipped to `box` in index space.
void cutDown(const std::string& source, const std::string& name, const CoordBBox& box,
             const std::set<std::string>& keep = {}) {
    io::File file(source);
    file.open();
    const GridPtrVecPtr all = file.getGrids();
    GridPtrVec grids;
    for (const GridBase::Ptr& grid : *all) {
        if (!keep.empty() && !keep.count(grid->getName())) continue;
        grid->clip(box);
        grids.push_back(grid);
    }
    const MetaMap::Ptr meta = file.getMetadata();
    const uint32_t compression = file.compression();
    file.close();
    write(name, grids, compression, *meta);
}

// The first `bytes` bytes of `source` as they are.
void prefix(const std::string& source, const std::string& name, std::size_t bytes) {
    std::ifstream in(source, std::ios::binary);
    std::string data(bytes, '\0');
    in.read(data.data(), std::streamsize(bytes));
    data.resize(std::size_t(in.gcount()));
    std::ofstream(outDir + "/" + name, std::ios::binary).write(data.data(), data.size());
    std::printf("%-40s %7zu bytes\n", name.c_str(), data.size());
}

// Everything sits in the positive octant: each octant a tree reaches costs its own top-level
// internal nodes, several kilobytes of masks even when compressed.
const Vec3f kCentre(3.0f);

FloatGrid::Ptr fogBall(const std::string& name, float radius, float voxel) {
    FloatGrid::Ptr grid = tools::createLevelSetSphere<FloatGrid>(radius, kCentre, voxel, 2.0f);
    for (auto it = grid->beginValueOn(); it; ++it) it.setValue(std::max(0.0f, -it.getValue()));
    grid->setGridClass(GRID_FOG_VOLUME);
    grid->setName(name);
    return grid;
}

void synthetic() {
    // Eikon's own exporter: density and a staggered velocity, as `eikon simulate` writes them.
    {
        eikon::FieldRegistry fields;
        fields.set("density", fogBall("density", 1.5f, 0.5f), "seed");
        auto velocity = Vec3SGrid::create(Vec3s(0.0f));
        velocity->tree().setValue(Coord(0, 0, 0), Vec3s(0.0f, 1.0f, 0.0f));
        velocity->tree().setValue(Coord(1, 2, 3), Vec3s(0.5f, 0.0f, -1.0f));
        velocity->setGridClass(GRID_STAGGERED);
        fields.set("velocity", velocity, "seed");
        eikon::exportVdb(outDir + "/eikon_export.vdb", fields, {"density", "velocity"});
        std::printf("%-40s\n", "eikon_export.vdb");
    }
    // A level set with no compression but the active masks (with none at all, one top-level
    // node alone is 128 kB), and the same tree twice (the second an instance of the first).
    {
        FloatGrid::Ptr sdf = tools::createLevelSetSphere<FloatGrid>(2.0f, kCentre, 0.5f, 2.0f);
        sdf->setName("surface");
        GridBase::Ptr instance = sdf->copyGrid();
        instance->setName("surface_instance");
        write("level_set_instanced.vdb", {sdf, instance}, io::COMPRESS_ACTIVE_MASK);
    }
    // Half floats with zip, colour channels that combine into one field, and an active tile.
    {
        GridPtrVec grids;
        for (const char* c : {"color_r", "color_g", "color_b"}) {
            FloatGrid::Ptr g = fogBall(c, 1.0f, 0.5f);
            g->setSaveFloatAsHalf(true);
            grids.push_back(g);
        }
        FloatGrid::Ptr smoke = FloatGrid::create(0.0f);
        smoke->setName("smoke");
        smoke->tree().addTile(1, Coord(0), 0.25f, true);
        smoke->tree().setValue(Coord(9, 9, 9), 1.0f);
        smoke->setTransform(math::Transform::createLinearTransform(0.1));
        grids.push_back(smoke);
        write("half_zip_color_tile.vdb", grids, io::COMPRESS_ZIP | io::COMPRESS_ACTIVE_MASK);
    }
    // Doubles (narrowed on import), an int32, a bool and a mask grid, Blosc, an affine transform.
    {
        DoubleGrid::Ptr d = DoubleGrid::create(0.0);
        d->setName("density");
        d->tree().fill(CoordBBox(Coord(0), Coord(3)), 0.5, true);
        math::Mat4d m = math::Mat4d::identity();
        m.setToRotation(math::Vec3d(0, 0, 1), 0.5);
        m.preScale(math::Vec3d(0.2, 0.3, 0.4));
        d->setTransform(math::Transform::createLinearTransform(m));
        Vec3DGrid::Ptr v = Vec3DGrid::create(Vec3d(0.0));
        v->setName("vel");
        v->tree().setValue(Coord(1, 1, 1), Vec3d(1, 2, 3));
        Int32Grid::Ptr flags = Int32Grid::create(0);
        flags->setName("flags");
        flags->tree().fill(CoordBBox(Coord(0), Coord(9)), 2, true);
        BoolGrid::Ptr b = BoolGrid::create(false);
        b->setName("inside");
        b->tree().setValue(Coord(2, 3, 4), true);
        MaskGrid::Ptr mask = MaskGrid::create();
        mask->setName("mask");
        mask->tree().setValueOn(Coord(5, 0, 5));
        write("double_int_bool_mask_blosc.vdb", {d, v, flags, b, mask},
              io::COMPRESS_BLOSC | io::COMPRESS_ACTIVE_MASK);
    }
    // Points: a grid type whose attributes use codecs (skipped by name when unregistered).
    {
        const std::vector<Vec3R> positions = {{0, 0, 0}, {0.5, 0.25, 1}, {1, 1, 1}, {1, 2, 0}};
        auto transform = math::Transform::createLinearTransform(0.5);
        points::PointDataGrid::Ptr pts =
            points::createPointDataGrid<points::FixedPointCodec<false>, points::PointDataGrid>(
                positions, *transform);
        pts->setName("points");
        write("points.vdb", {pts, fogBall("density", 1.0f, 0.5f)}, io::COMPRESS_BLOSC);
    }
    // Values import rejects: NaN and negative density; and a file with no grids at all.
    {
        FloatGrid::Ptr nan = fogBall("density", 1.0f, 0.5f);
        nan->tree().setValue(Coord(6), std::numeric_limits<float>::quiet_NaN());
        FloatGrid::Ptr negative = fogBall("flame", 1.0f, 0.5f);
        negative->tree().setValue(Coord(6), -1.0f);
        write("nan_negative.vdb", {nan, negative}, io::COMPRESS_ACTIVE_MASK);
        MetaMap meta;
        meta.insertMeta("creator", StringMetadata("seed"));
        write("no_grids.vdb", {}, io::COMPRESS_NONE, meta);
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: make_vdb_seeds SHARED_VDB_DIR OUT_DIR\n");
        return 2;
    }
    const std::string shared = argv[1];
    outDir = argv[2];
    fs::create_directories(outDir);
    initialize();
    cutDown(shared + "/houdini_smoke1.vdb", "houdini_smoke1_cut.vdb",
            CoordBBox(Coord(52, 100, 52), Coord(59, 107, 59)));
    cutDown(shared + "/houdini_vel_constant.vdb", "houdini_vel_cut.vdb",
            CoordBBox(Coord(40), Coord(45)));
    cutDown(shared + "/blender_smoke_c42/fluid_data_0002.vdb", "blender_smoke_cut.vdb",
            CoordBBox(Coord(64, 112, 8), Coord(70, 118, 14)),
            {"density", "color_r", "color_g", "color_b", "velocity", "flags"});
    prefix(shared + "/houdini_smoke1.vdb", "houdini_smoke1_head.vdb", 2048);
    prefix(shared + "/blender_smoke_c42/fluid_data_0002.vdb", "blender_smoke_head.vdb", 4096);
    synthetic();
    return 0;
}
