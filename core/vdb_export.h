#pragma once
// Export of fields as a VDB file that Houdini, Blender and OpenVDB's tools read: grids named by
// the conventions those tools use (density, temperature, flame, velocity; color as "Cd"), fog
// volumes marked as such, velocity keeping its staggered class, full float precision (so that a
// round trip is exact), and file metadata saying what wrote it. The file is written beside the
// target and renamed over it only when complete, so a failure never leaves a half file.
#include <string>
#include <vector>

#include "core/field_registry.h"

namespace eikon {

// The grid name a field gets in exported files ("color" -> "Cd", others unchanged).
std::string exportGridName(const std::string& fieldName);

void exportVdb(const std::string& path, const FieldRegistry& registry,
               const std::vector<std::string>& fieldNames);

}  // namespace eikon
