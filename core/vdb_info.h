#pragma once
// What `eikon info FILE.vdb` prints: every grid with its type, class, voxel size, index and world
// bounds of the active voxels, active voxel count, value range and its NaN and Inf values.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace eikon {

struct GridInfo {
    std::string name;
    std::string type;       // OpenVDB value type: float, vec3s, int32, ...
    std::string gridClass;  // fog volume, level set, staggered, unknown
    bool savedAsHalf = false;
    bool readable = true;  // false: type or codec unknown here; only metadata is shown
    std::string problem;   // why it is not readable
    std::array<double, 3> voxelSize{};
    bool empty = true;
    std::array<int, 3> indexMin{}, indexMax{};  // active voxel bbox, inclusive
    // The box around the outer faces of those voxels, all eight corners through the transform
    // (a rotated grid's box is wider than its two extreme corners).
    std::array<double, 3> worldMin{}, worldMax{};
    std::uint64_t activeVoxels = 0;     // voxels plus voxels in active tiles
    double minValue = 0, maxValue = 0;  // of the finite values; scalars, vectors by length
    // Active values (a tile counted once) that are NaN or ±Inf, in any component: `eikon render`
    // refuses a field holding one, so `info` names them.
    std::uint64_t nanValues = 0, infValues = 0;
    bool anyFinite = false;  // min/maxValue hold something
};

struct VdbFileInfo {
    std::string path;
    std::string creator;
    std::string fileVersion;
    std::vector<GridInfo> grids;
};

// Throws eikon::Error for a missing, truncated or corrupt file.
VdbFileInfo inspectVdb(const std::string& path);
std::string formatVdbInfo(const VdbFileInfo& info);

}  // namespace eikon
