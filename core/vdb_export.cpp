#include "core/vdb_export.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

#include "core/atomic_write.h"
#include "core/error.h"
#include "core/vdb_file_id.h"
#include "core/vdb_import.h"

#include <openvdb/tools/Prune.h>

namespace eikon {
namespace {

// io::File::write writes through a stream of its own and never looks at it afterwards, so a full
// disk or a file-size limit left a truncated file that looked written. This writes the same
// bytes (the seekable archive io::File writes) into a stream the caller checks.
class CheckedVdbArchive final : public openvdb::io::Archive {
public:
    void writeSeekable(std::ostream& out, const openvdb::GridPtrVec& grids,
                       const openvdb::MetaMap& meta) const {
        Archive::write(out, grids, /*seekable=*/true, meta);
    }
};

// Voxels of a fog field below kExportPruneTolerance become inactive background (0) in a copy:
// a solver's decaying smoke leaves values down to denormals (1.4e-45) active, which other tools
// count, bound and march through as smoke.
openvdb::FloatGrid::Ptr prunedFog(const openvdb::FloatGrid& grid) {
    openvdb::FloatGrid::Ptr out = grid.deepCopy();
    for (auto leaf = out->tree().beginLeaf(); leaf; ++leaf)
        for (auto v = leaf->beginValueOn(); v; ++v)
            if (std::abs(*v) < kExportPruneTolerance) {
                v.setValue(0.0f);
                v.setValueOff();
            }
    // Active tiles hold one value for many voxels: the same rule.
    for (auto t = out->tree().beginValueOn(); t; ++t)
        if (t.isTileValue() && std::abs(*t) < kExportPruneTolerance) {
            t.setValue(0.0f);
            t.setActiveState(false);
        }
    openvdb::tools::pruneInactive(out->tree());
    return out;
}

}  // namespace

std::string exportGridName(const std::string& fieldName) {
    return fieldName == field::kColor ? "Cd" : fieldName;
}

void exportVdb(const std::string& path, const FieldRegistry& registry,
               const std::vector<std::string>& fieldNames) {
    ensureOpenVdbInitialized();
    if (fieldNames.empty()) throw Error(path, "nothing to export: no fields given");
    openvdb::GridPtrVec grids;
    for (const std::string& name : fieldNames) {
        const Field& f = registry.get(name);
        const bool fog = f.isScalar() && (name == field::kDensity || name == field::kTemperature ||
                                          name == field::kFlame);
        auto floatGrid = openvdb::GridBase::grid<openvdb::FloatGrid>(f.grid);
        // A shallow copy shares the tree; only the name and metadata change. Fog fields are
        // pruned in a deep copy.
        openvdb::GridBase::Ptr g =
            fog && floatGrid ? openvdb::GridBase::Ptr(prunedFog(*floatGrid)) : f.grid->copyGrid();
        g->setName(exportGridName(name));
        g->setSaveFloatAsHalf(false);
        if (fog) g->setGridClass(openvdb::GRID_FOG_VOLUME);
        if (f.isVector()) g->setVectorType(openvdb::VEC_CONTRAVARIANT_RELATIVE);
        g->insertMeta("eikon_field", openvdb::StringMetadata(name));
        grids.push_back(g);
    }

    writeAtomically(path, [&](const std::string& partial) {
        std::ofstream out(partial, std::ios::binary | std::ios::trunc);
        if (!out)
            throw Error(path, std::string("cannot open for writing: ") + std::strerror(errno));
        openvdb::MetaMap meta;
        meta.insertMeta("creator", openvdb::StringMetadata("Eikon"));
        CheckedVdbArchive().writeSeekable(out, grids, meta);
        out.flush();
        const int writeError = errno;
        if (!out) throw Error(path, std::string("could not write: ") + std::strerror(writeError));
        out.close();
        if (out.fail())
            throw Error(path, std::string("could not finish writing: ") + std::strerror(errno));
        makeVdbFileIdDeterministic(partial);  // the same grids, the same bytes
    });
}

}  // namespace eikon
