#include "core/vdb_import.h"

#include <cmath>
#include <filesystem>
#include <mutex>
#include <set>

#include "core/error.h"
#include "core/file_kind.h"
#include "core/log.h"
#include "core/nanovdb_reader.h"
#include "core/printable.h"
#include "core/vdb_reader.h"

namespace eikon {
namespace {

bool aliasMatches(const std::string& alias, const std::string& gridName) {
    if (alias.size() >= 2 && alias.compare(alias.size() - 2, 2, ".*") == 0) {
        const std::string prefix = alias.substr(0, alias.size() - 1);  // keeps the dot
        return gridName.size() > prefix.size() && gridName.compare(0, prefix.size(), prefix) == 0;
    }
    return alias == gridName;
}

// Counts active values (voxels and tiles) that are not finite, and those below zero.
struct ValueStats {
    openvdb::Index64 nonFinite = 0;
    openvdb::Index64 negative = 0;
    float minimum = 0.0f;
};

ValueStats scanFloatGrid(const openvdb::FloatGrid& grid) {
    ValueStats s;
    s.minimum = std::numeric_limits<float>::max();
    for (auto it = grid.cbeginValueOn(); it; ++it) {
        const float v = *it;
        if (!std::isfinite(v)) {
            ++s.nonFinite;
            continue;
        }
        if (v < 0.0f) ++s.negative;
        s.minimum = std::min(s.minimum, v);
    }
    if (!std::isfinite(grid.background())) ++s.nonFinite;
    return s;
}

openvdb::Index64 countNonFiniteVectors(const openvdb::Vec3SGrid& grid) {
    openvdb::Index64 n = 0;
    for (auto it = grid.cbeginValueOn(); it; ++it) {
        const openvdb::Vec3s v = *it;
        if (!std::isfinite(v.x()) || !std::isfinite(v.y()) || !std::isfinite(v.z())) ++n;
    }
    return n;
}

// Copies the active values (voxels and tiles) of a double-precision grid into its float twin.
template <typename SrcGrid, typename DstGrid>
typename DstGrid::Ptr narrowGrid(const SrcGrid& src) {
    using DstValue = typename DstGrid::ValueType;
    auto dst = DstGrid::create(DstValue(src.background()));
    dst->setTransform(src.transform().copy());
    dst->setGridClass(src.getGridClass());
    dst->setVectorType(src.getVectorType());
    for (auto it = src.cbeginValueOn(); it; ++it) {
        openvdb::CoordBBox box;
        it.getBoundingBox(box);
        dst->tree().fill(box, DstValue(*it), /*active=*/true);
    }
    return dst;
}

// Float and vec3 grids are fields; doubles are narrowed (tools write them rarely, Eikon computes
// in float); everything else (int32 flags, masks, points) is skipped by the caller.
openvdb::GridBase::Ptr asFieldGrid(const openvdb::GridBase::Ptr& grid) {
    if (grid->isType<openvdb::FloatGrid>() || grid->isType<openvdb::Vec3SGrid>()) return grid;
    if (auto d = openvdb::gridPtrCast<openvdb::DoubleGrid>(grid))
        return narrowGrid<openvdb::DoubleGrid, openvdb::FloatGrid>(*d);
    if (auto d = openvdb::gridPtrCast<openvdb::Vec3DGrid>(grid))
        return narrowGrid<openvdb::Vec3DGrid, openvdb::Vec3SGrid>(*d);
    return nullptr;
}

// color_r, color_g, color_b (Mantaflow) -> one vec3 field, sampled on the red grid's voxels.
openvdb::Vec3SGrid::Ptr combineColorChannels(const openvdb::FloatGrid& r,
                                             const openvdb::FloatGrid& g,
                                             const openvdb::FloatGrid& b) {
    auto out = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
    out->setTransform(r.transform().copy());
    out->setName(field::kColor);
    out->topologyUnion(r);
    out->topologyUnion(g);
    out->topologyUnion(b);
    auto ra = r.getConstAccessor();
    auto ga = g.getConstAccessor();
    auto ba = b.getConstAccessor();
    for (auto it = out->beginValueOn(); it; ++it) {
        const openvdb::Coord c = it.getCoord();
        it.setValue(openvdb::Vec3s(ra.getValue(c), ga.getValue(c), ba.getValue(c)));
    }
    return out;
}

bool isFieldValueType(const std::string& valueType) {
    return valueType == "float" || valueType == "double" || valueType == "vec3s" ||
           valueType == "vec3d";
}

// Grid names come from the file and may hold control characters: `gridName` and `fieldName`
// (a grid's own name when no alias maps it) go through printable() in every message.
void validate(const std::string& path, const std::string& gridName, const std::string& fieldName,
              const openvdb::GridBase& grid) {
    const std::string quotedGrid = "grid '" + printable(gridName) + "'";
    const std::string field = printable(fieldName);
    if (auto f = dynamic_cast<const openvdb::FloatGrid*>(&grid)) {
        const ValueStats s = scanFloatGrid(*f);
        if (s.nonFinite > 0)
            throw Error(path,
                        quotedGrid + " has " + std::to_string(s.nonFinite) + " NaN/Inf values");
        if (fieldMustBeNonNegative(fieldName) && s.negative > 0) {
            const std::string why = fieldKind(fieldName) == field::kIor
                                        ? " (a material maps it to n = 1 + f·(ior − 1) >= 1)"
                                        : "";
            throw Error(path, quotedGrid + " (" + field + ") has " + std::to_string(s.negative) +
                                  " negative values (minimum " + std::to_string(s.minimum) + "); " +
                                  field + " must be >= 0" + why);
        }
    } else if (auto v = dynamic_cast<const openvdb::Vec3SGrid*>(&grid)) {
        const openvdb::Index64 n = countNonFiniteVectors(*v);
        if (n > 0) throw Error(path, quotedGrid + " has " + std::to_string(n) + " NaN/Inf values");
    }
}

// Every grid of the file that can be a field, as one (float, vec3s); the others are named in
// report.skipped without being decoded. NanoVDB files (core/nanovdb_reader.h) as OpenVDB's.
std::vector<openvdb::GridBase::Ptr> readFieldGrids(const std::string& path,
                                                   VdbImportReport& report) {
    std::vector<openvdb::GridBase::Ptr> grids;
    if (isNanoVdbFile(path)) {
        for (const NanoVdbGrid& g : readNanoVdb(path)) {
            if (!g.grid) {
                report.skipped.push_back(printable(g.name) + ": " + g.skipped);
                continue;
            }
            openvdb::GridBase::Ptr asField = asFieldGrid(g.grid);
            asField->setName(g.name);
            grids.push_back(asField);
        }
        return grids;
    }
    VdbReader reader(path);
    report.creator = reader.creator();
    for (size_t i = 0; i < reader.entries().size(); ++i) {
        const VdbReader::Entry& e = reader.entries()[i];
        const std::string name = printable(e.name);
        if (!e.registered) {
            report.skipped.push_back(name + ": grid type " + printable(e.type) +
                                     " is not registered here");
            continue;
        }
        const std::string valueType = openvdb::GridBase::createGrid(e.type)->valueType();
        if (!isFieldValueType(valueType)) {
            report.skipped.push_back(name + ": " + valueType +
                                     " grid, not a field type (float, double, vec3s, vec3d)");
            continue;
        }
        openvdb::GridBase::Ptr grid;
        try {
            grid = reader.readGrid(i);
        } catch (const UnsupportedGridError& err) {
            report.skipped.push_back(name + ": " + err.reason());
            continue;
        }
        openvdb::GridBase::Ptr asField = asFieldGrid(grid);
        asField->setName(e.name);
        grids.push_back(asField);
    }
    return grids;
}

}  // namespace

void ensureOpenVdbInitialized() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

const GridAliases& defaultGridAliases() {
    static const GridAliases aliases = {
        {field::kDensity, {"density", "smoke", "soot", "density.*"}},
        {field::kTemperature, {"temperature", "heat"}},
        {field::kFlame, {"flame", "fire"}},
        {field::kVelocity, {"velocity", "vel", "v"}},
        {field::kColor, {"Cd", "color"}},
    };
    return aliases;
}

namespace {

// The canonical field a grid name maps to and how strongly: a lower rank is an earlier entry of
// the alias lists, the scene's extra aliases before the built-in ones.
std::pair<std::string, int> aliasMatch(const std::string& gridName, const GridAliases& extra) {
    int rank = 0;
    for (const GridAliases* table : {&extra, &defaultGridAliases()})
        for (const auto& [canonical, names] : *table)
            for (const auto& alias : names) {
                if (aliasMatches(alias, gridName)) return {canonical, rank};
                ++rank;
            }
    return {"", rank};
}

}  // namespace

std::string canonicalFieldFor(const std::string& gridName, const GridAliases& extra) {
    return aliasMatch(gridName, extra).first;
}

VdbImportReport importVdb(const std::string& path, FieldRegistry& registry,
                          const GridAliases& extraAliases) {
    ensureOpenVdbInitialized();
    VdbImportReport report;
    report.file = path;
    std::vector<openvdb::GridBase::Ptr> grids = readFieldGrids(path, report);

    // Map names: each canonical field takes the matching grid of lowest alias rank; the other
    // grids keep their own names.
    std::map<std::string, std::pair<int, size_t>> best;  // canonical -> (rank, grid index)
    for (size_t i = 0; i < grids.size(); ++i) {
        const auto [canonical, rank] = aliasMatch(grids[i]->getName(), extraAliases);
        if (canonical.empty()) continue;
        auto it = best.find(canonical);
        if (it == best.end() || rank < it->second.first) best[canonical] = {rank, i};
    }
    std::vector<std::string> target(grids.size());
    for (size_t i = 0; i < grids.size(); ++i) target[i] = grids[i]->getName();
    for (const auto& [canonical, choice] : best) target[choice.second] = canonical;
    // A grid that lost its own canonical name to a preferred alias is not loaded under it.
    for (size_t i = 0; i < grids.size(); ++i) {
        auto it = best.find(target[i]);
        if (it != best.end() && it->second.second != i) target[i].clear();
    }

    std::set<std::string> assigned;
    std::map<std::string, openvdb::FloatGrid::Ptr> colorChannels;
    for (size_t i = 0; i < grids.size(); ++i) {
        const auto& grid = grids[i];
        const std::string& name = grid->getName();
        const std::string shown = printable(name);
        if (name == "color_r" || name == "color_g" || name == "color_b") {
            if (auto f = openvdb::gridPtrCast<openvdb::FloatGrid>(grid)) colorChannels[name] = f;
        }
        if (target[i].empty()) {
            const auto& chosen = grids[best[name].second]->getName();
            report.skipped.push_back(shown + ": field " + shown + " comes from grid '" +
                                     printable(chosen) + "' (alias)");
            continue;
        }
        if (assigned.count(target[i])) {
            report.skipped.push_back(shown + ": its name is taken by another grid of the file");
            continue;
        }
        validate(path, name, target[i], *grid);
        assigned.insert(target[i]);
        registry.set(target[i], grid, path + ":" + shown);
        report.loaded.emplace_back(target[i], name);
    }
    if (!assigned.count(field::kColor) && colorChannels.size() == 3) {
        auto color = combineColorChannels(*colorChannels["color_r"], *colorChannels["color_g"],
                                          *colorChannels["color_b"]);
        registry.set(field::kColor, color, path + ":color_r/g/b");
        report.loaded.emplace_back(field::kColor, "color_r/g/b");
        assigned.insert(field::kColor);
    }

    for (const auto& s : report.skipped) logWarning(path + ": skipped grid " + s);
    if (report.loaded.empty()) {
        std::string why;
        for (const auto& s : report.skipped) why += (why.empty() ? "" : "; ") + s;
        throw Error(path, "no usable grid" + (why.empty() ? std::string(" (the file holds none)")
                                                          : " (skipped: " + why + ")"));
    }
    return report;
}

}  // namespace eikon
