#include "core/vdb_export.h"

#include "core/atomic_write.h"
#include "core/error.h"
#include "core/vdb_file_id.h"
#include "core/vdb_import.h"

namespace eikon {

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
        // A shallow copy shares the tree; only the name and metadata change.
        openvdb::GridBase::Ptr g = f.grid->copyGrid();
        g->setName(exportGridName(name));
        g->setSaveFloatAsHalf(false);
        if (f.isScalar() &&
            (name == field::kDensity || name == field::kTemperature || name == field::kFlame))
            g->setGridClass(openvdb::GRID_FOG_VOLUME);
        if (f.isVector()) g->setVectorType(openvdb::VEC_CONTRAVARIANT_RELATIVE);
        g->insertMeta("eikon_field", openvdb::StringMetadata(name));
        grids.push_back(g);
    }

    writeAtomically(path, [&](const std::string& partial) {
        openvdb::io::File file(partial);
        openvdb::MetaMap meta;
        meta.insertMeta("creator", openvdb::StringMetadata("Eikon"));
        file.write(grids, meta);
        file.close();
        makeVdbFileIdDeterministic(partial);  // the same grids, the same bytes
    });
}

}  // namespace eikon
