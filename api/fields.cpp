#include "eikon/fields.h"

#include <set>

#include "api/session_impl.h"
#include "core/error.h"
#include "core/vdb_export.h"
#include "core/vdb_reader.h"

namespace eikon {

std::vector<std::string> fieldNames(Session& session) {
    Session::Impl& s = session.impl();
    std::set<std::string> names;
    for (const std::string& n : s.steppedFields.names()) names.insert(n);
    for (const std::string& n : s.renderer->fields().names()) names.insert(n);
    return {names.begin(), names.end()};
}

openvdb::GridBase::ConstPtr fieldGrid(Session& session, const std::string& name) {
    Session::Impl& s = session.impl();
    if (s.steppedFields.has(name)) return s.steppedFields.get(name).grid;
    if (s.renderer->fields().has(name)) return s.renderer->fields().get(name).grid;
    std::string names;
    for (const std::string& n : fieldNames(session)) names += (names.empty() ? "" : ", ") + n;
    throw Error("field '" + name + "'",
                "the session has no field of that name (it has: " +
                    (names.empty() ? "none yet: step or render a frame first" : names) + ")");
}

openvdb::GridPtrVec readFields(const std::string& path) {
    openvdb::initialize();
    VdbReader reader(path);
    openvdb::GridPtrVec grids;
    for (size_t i = 0; i < reader.entries().size(); ++i)
        if (reader.entries()[i].registered) grids.push_back(reader.readGrid(i));
    return grids;
}

void writeFields(const std::string& path, const openvdb::GridCPtrVec& grids) {
    openvdb::initialize();
    FieldRegistry registry;
    std::vector<std::string> names;
    for (const auto& g : grids) {
        if (!g) throw Error(path, "a grid to write is null");
        if (g->getName().empty()) throw Error(path, "every grid to write needs a name");
        if (registry.has(g->getName())) throw Error(path, "two grids named '" + g->getName() + "'");
        registry.set(g->getName(), g->deepCopyGrid(), "writeFields");
        names.push_back(g->getName());
    }
    exportVdb(path, registry, names);
}

}  // namespace eikon
