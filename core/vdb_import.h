#pragma once
// Import of VDB files written by other tools (Houdini, Blender/Mantaflow, EmberGen) into a
// FieldRegistry. Grid names map to canonical fields through an alias table (overridable);
// grids of types Eikon does not use, or that OpenVDB cannot decode here, are skipped by name with
// a warning while the rest of the file loads. Everything else that is wrong with the file is an
// eikon::Error naming the file: missing, truncated or corrupt, nothing usable, NaN/Inf values,
// negative values of density, flame, kappa, sigma or n (field_registry.h).
#include <map>
#include <string>
#include <vector>

#include "core/field_registry.h"

namespace eikon {

using GridAliases = std::map<std::string, std::vector<std::string>>;

// The built-in table: canonical field -> grid names, in order of preference. A name ending in
// ".*" matches any grid whose name starts with what precedes the "*" (density.* matches
// "density.1"). color_r/g/b are combined into one vec3 field.
const GridAliases& defaultGridAliases();

// The canonical field a grid name maps to ("" if none). `extra` is tried before the defaults.
std::string canonicalFieldFor(const std::string& gridName, const GridAliases& extra = {});

struct VdbImportReport {
    std::string file;
    std::string creator;                                      // the file's "creator" metadata
    std::vector<std::pair<std::string, std::string>> loaded;  // (field name, grid name(s))
    std::vector<std::string> skipped;  // "flags: int32 grid, not a field type"
};

VdbImportReport importVdb(const std::string& path, FieldRegistry& registry,
                          const GridAliases& extraAliases = {});

// Makes sure OpenVDB's types are registered (safe to call from many places and threads).
void ensureOpenVdbInitialized();

}  // namespace eikon
