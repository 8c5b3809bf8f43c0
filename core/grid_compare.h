#pragma once
// Voxel-by-voxel comparison of two VDB files, the way a regression suite compares simulation
// caches (Mantaflow's own harness compares grids against a threshold on the largest difference):
// every grid of the reference must be in the new file, with the same type, and every voxel
// active in either must agree within a tolerance (a voxel active in one file only is compared
// against the other's background). Vector grids compare their largest component difference.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace eikon {

struct VoxelDifference {
    glm::ivec3 ijk{0};
    double reference = 0.0;  // the value, or the vector's length for vector grids
    double test = 0.0;
    double difference = 0.0;  // |test − reference| (largest component for vectors)
};

struct GridDifference {
    std::string name;
    std::string type;  // "float", "double", "vec3s", ...
    int64_t voxelsCompared = 0;
    int64_t voxelsOver = 0;  // differing by more than the tolerance
    double maxDifference = 0.0;
    std::vector<VoxelDifference> worst;  // the largest differences first, at most kWorstVoxels
};

struct VdbFileDifference {
    std::vector<GridDifference> grids;  // the reference's grids (or those asked for), in order
    std::vector<std::string> problems;  // a grid missing, a type that differs, one unreadable
    // No problem and no voxel over the tolerance the comparison was made with.
    bool within() const;
};

inline constexpr int kWorstVoxels = 8;

// Compares `testPath` against `referencePath`. `gridNames` empty: every grid of the reference.
// Throws eikon::Error naming the file when either cannot be read as VDB.
VdbFileDifference compareVdbFiles(const std::string& testPath, const std::string& referencePath,
                                  double tolerance, const std::vector<std::string>& gridNames = {});

}  // namespace eikon
