#include "core/vdb_info.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "core/error.h"
#include "core/field_registry.h"
#include "core/printable.h"
#include "core/vdb_import.h"
#include "core/vdb_reader.h"

namespace eikon {
namespace {

template <typename GridT, typename Measure>
void valueRange(const GridT& grid, Measure measure, GridInfo& info) {
    bool first = true;
    for (auto it = grid.cbeginValueOn(); it; ++it) {
        const double v = measure(*it);
        if (first || v < info.minValue) info.minValue = v;
        if (first || v > info.maxValue) info.maxValue = v;
        first = false;
    }
}

void fillValueRange(const openvdb::GridBase& grid, GridInfo& info) {
    using namespace openvdb;
    if (auto g = dynamic_cast<const FloatGrid*>(&grid))
        valueRange(
            *g, [](float v) { return double(v); }, info);
    else if (auto g = dynamic_cast<const DoubleGrid*>(&grid))
        valueRange(
            *g, [](double v) { return v; }, info);
    else if (auto g = dynamic_cast<const Int32Grid*>(&grid))
        valueRange(
            *g, [](int32_t v) { return double(v); }, info);
    else if (auto g = dynamic_cast<const Vec3SGrid*>(&grid))
        valueRange(
            *g, [](const Vec3s& v) { return double(v.length()); }, info);
    else if (auto g = dynamic_cast<const Vec3DGrid*>(&grid))
        valueRange(
            *g, [](const Vec3d& v) { return v.length(); }, info);
}

void fillGeometry(const openvdb::GridBase& grid, GridInfo& info) {
    const openvdb::Vec3d vs = grid.voxelSize();
    info.voxelSize = {vs.x(), vs.y(), vs.z()};
    const openvdb::CoordBBox box = grid.evalActiveVoxelBoundingBox();
    info.empty = box.empty();
    info.activeVoxels = grid.activeVoxelCount();
    if (info.empty) return;
    for (int a = 0; a < 3; ++a) {
        info.indexMin[a] = box.min()[a];
        info.indexMax[a] = box.max()[a];
    }
    const openvdb::Vec3d lo = grid.transform().indexToWorld(box.min().asVec3d() - 0.5);
    const openvdb::Vec3d hi = grid.transform().indexToWorld(box.max().asVec3d() + 0.5);
    for (int a = 0; a < 3; ++a) {
        info.worldMin[a] = std::min(lo[a], hi[a]);
        info.worldMax[a] = std::max(lo[a], hi[a]);
    }
}

}  // namespace

VdbFileInfo inspectVdb(const std::string& path) {
    ensureOpenVdbInitialized();
    VdbFileInfo out;
    out.path = path;
    VdbReader reader(path);
    out.fileVersion = reader.fileVersion();
    out.creator = reader.creator();
    for (size_t i = 0; i < reader.entries().size(); ++i) {
        const VdbReader::Entry& e = reader.entries()[i];
        GridInfo info;
        info.name = e.name;
        info.type = e.type;
        info.savedAsHalf = e.savedAsHalf;
        try {
            openvdb::GridBase::Ptr g = reader.readGrid(i);
            info.type = g->valueType();
            info.gridClass = openvdb::GridBase::gridClassToString(g->getGridClass());
            fillGeometry(*g, info);
            fillValueRange(*g, info);
        } catch (const UnsupportedGridError& err) {
            info.readable = false;
            info.problem = err.reason();
        }
        out.grids.push_back(info);
    }
    return out;
}

std::string formatVdbInfo(const VdbFileInfo& info) {
    std::ostringstream s;
    s << info.path << ": VDB " << info.fileVersion;
    // Names, types and the creator are the file's bytes: a terminal escape in one must not
    // reach the terminal raw (core/printable.h).
    if (!info.creator.empty()) s << ", written by " << printable(info.creator, 200);
    s << ", " << info.grids.size() << " grid" << (info.grids.size() == 1 ? "" : "s") << "\n";
    auto triple = [&](const auto& v) {
        std::ostringstream t;
        t << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
        return t.str();
    };
    for (const GridInfo& g : info.grids) {
        s << "  " << printable(g.name, 200) << "  " << printable(g.type)
          << (g.savedAsHalf ? " (stored as half)" : "") << ", class " << printable(g.gridClass)
          << "\n";
        if (!g.readable) {
            s << "    not readable here: " << g.problem << "\n";
            continue;
        }
        s << "    voxel size " << triple(g.voxelSize) << "\n";
        if (g.empty) {
            s << "    no active voxels\n";
            continue;
        }
        s << "    index bounds " << triple(g.indexMin) << " -> " << triple(g.indexMax) << "\n";
        s << "    world bounds " << triple(g.worldMin) << " -> " << triple(g.worldMax) << "\n";
        s << "    active voxels " << g.activeVoxels << "\n";
        s << "    values " << g.minValue << " .. " << g.maxValue
          << (g.type.rfind("vec3", 0) == 0 ? " (length)" : "") << "\n";
    }
    return s.str();
}

}  // namespace eikon
