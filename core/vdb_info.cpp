#include "core/vdb_info.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "core/field_registry.h"
#include "core/file_kind.h"
#include "core/nanovdb_reader.h"
#include "core/printable.h"
#include "core/vdb_import.h"
#include "core/vdb_reader.h"
#include "core/world_box.h"

namespace eikon {
namespace {

template <typename GridT, typename Measure>
void valueRange(const GridT& grid, Measure measure, GridInfo& info) {
    bool first = true;
    for (auto it = grid.cbeginValueOn(); it; ++it) {
        const double v = measure(*it);  // NaN when any component is, Inf when one is infinite
        if (std::isnan(v)) {
            ++info.nanValues;
            continue;
        }
        if (std::isinf(v)) {
            ++info.infValues;
            continue;
        }
        if (first || v < info.minValue) info.minValue = v;
        if (first || v > info.maxValue) info.maxValue = v;
        first = false;
        info.anyFinite = true;
    }
}

// A vector's length, NaN when a component is NaN (a length could hide it as Inf).
template <typename Vec>
double lengthOf(const Vec& v) {
    if (std::isnan(double(v[0])) || std::isnan(double(v[1])) || std::isnan(double(v[2])))
        return std::numeric_limits<double>::quiet_NaN();
    return std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
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
            *g, [](const Vec3s& v) { return lengthOf(v); }, info);
    else if (auto g = dynamic_cast<const Vec3DGrid*>(&grid))
        valueRange(
            *g, [](const Vec3d& v) { return lengthOf(v); }, info);
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
    const openvdb::BBoxd world = worldBoxOf(grid.transform(), box);
    for (int a = 0; a < 3; ++a) {
        info.worldMin[a] = world.min()[a];
        info.worldMax[a] = world.max()[a];
    }
}

}  // namespace

VdbFileInfo inspectVdb(const std::string& path) {
    ensureOpenVdbInitialized();
    VdbFileInfo out;
    out.path = path;
    if (isNanoVdbFile(path)) {
        out.fileVersion = "NanoVDB";
        for (const NanoVdbGrid& g : readNanoVdb(path)) {
            GridInfo info;
            info.name = g.name;
            info.type = g.type;
            if (!g.grid) {
                info.readable = false;
                info.problem = g.skipped;
            } else {
                info.gridClass = openvdb::GridBase::gridClassToString(g.grid->getGridClass());
                fillGeometry(*g.grid, info);
                fillValueRange(*g.grid, info);
            }
            out.grids.push_back(info);
        }
        return out;
    }
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
    // NanoVDB files name themselves; OpenVDB's print their format version.
    s << info.path << ": " << (info.fileVersion == "NanoVDB" ? "" : "VDB ") << info.fileVersion;
    // Names, types and the creator are the file's bytes: a terminal escape in one must not
    // reach the terminal raw (core/printable.h).
    if (!info.creator.empty()) s << ", written by " << printable(info.creator, 200);
    s << ", " << info.grids.size() << " grid" << (info.grids.size() == 1 ? "" : "s") << "\n";
    auto triple = [&](const auto& v) {
        std::ostringstream t;
        t << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
        return t.str();
    };
    size_t index = 0;
    for (const GridInfo& g : info.grids) {
        // A grid with no name (some tools write one) is labelled, not shown as a blank.
        const std::string name = g.name.empty() ? "(unnamed grid " + std::to_string(index) + ")"
                                                : printable(g.name, 200);
        // Half storage applies to floating-point values only; the file's flag says nothing of
        // an int32 or bool grid.
        const bool halfApplies = g.type == "float" || g.type == "double" ||
                                 g.type.rfind("vec3s", 0) == 0 || g.type.rfind("vec3d", 0) == 0;
        s << "  " << name << "  " << printable(g.type)
          << (g.savedAsHalf && halfApplies ? " (stored as half)" : "") << ", class "
          << printable(g.gridClass) << "\n";
        ++index;
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
        if (g.anyFinite)
            s << "    values " << g.minValue << " .. " << g.maxValue
              << (g.type.rfind("vec3", 0) == 0 ? " (length)" : "") << "\n";
        if (g.nanValues + g.infValues > 0)
            s << "    non-finite values: " << g.nanValues << " NaN, " << g.infValues
              << " Inf (eikon render refuses a field holding them)\n";
    }
    return s.str();
}

}  // namespace eikon
