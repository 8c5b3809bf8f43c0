#pragma once
// Export of fields as a VDB file that Houdini, Blender and OpenVDB's tools read: grids named by
// the conventions those tools use (density, temperature, flame, velocity; color as "Cd"), fog
// volumes marked as such, velocity keeping its staggered class, full float precision (so that a
// round trip is exact, save fog values below kExportPruneTolerance), and file metadata saying what
// wrote it. The file is written beside the target and renamed over it only when complete, so a
// failure never leaves a half file.
#include <string>
#include <vector>

#include "core/field_registry.h"

namespace eikon {

// Voxels of density, temperature and flame with |value| below this are written inactive, as
// background 0 (a decaying solver leaves values down to denormals, which other tools count and
// march as smoke). 1e-6 density over a whole 256-voxel path of unit voxels and σ = 1 takes
// 0.03 % of the light.
constexpr float kExportPruneTolerance = 1e-6f;

// The grid name a field gets in exported files ("color" -> "Cd", others unchanged).
std::string exportGridName(const std::string& fieldName);

void exportVdb(const std::string& path, const FieldRegistry& registry,
               const std::vector<std::string>& fieldNames);

}  // namespace eikon
