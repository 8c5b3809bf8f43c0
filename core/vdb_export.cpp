#include "core/vdb_export.h"

#include <filesystem>

#include "core/error.h"
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
        if (f.isScalar() && (name == field::kDensity || name == field::kTemperature ||
                             name == field::kFlame))
            g->setGridClass(openvdb::GRID_FOG_VOLUME);
        if (f.isVector()) g->setVectorType(openvdb::VEC_CONTRAVARIANT_RELATIVE);
        g->insertMeta("eikon_field", openvdb::StringMetadata(name));
        grids.push_back(g);
    }

    namespace fs = std::filesystem;
    const fs::path target(path);
    std::error_code ec;
    if (!target.parent_path().empty() && !fs::is_directory(target.parent_path(), ec))
        throw Error(path, "folder '" + target.parent_path().string() + "' does not exist");
    const fs::path partial = target.string() + ".partial";
    try {
        openvdb::io::File file(partial.string());
        openvdb::MetaMap meta;
        meta.insertMeta("creator", openvdb::StringMetadata("Eikon"));
        file.write(grids, meta);
        file.close();
    } catch (const std::exception& e) {
        fs::remove(partial, ec);
        throw Error(path, std::string("could not write: ") + e.what());
    }
    fs::rename(partial, target, ec);
    if (ec) {
        fs::remove(partial, ec);
        throw Error(path, "could not replace the file: " + ec.message());
    }
}

}  // namespace eikon
