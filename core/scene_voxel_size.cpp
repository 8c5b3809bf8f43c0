#include "core/scene_voxel_size.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace eikon::scene_detail {

void checkVoxelSize(const json::Value& value, glm::vec3 voxel, const Bounds3& box,
                    const std::string& what) {
    double reach = 0.0;
    for (int a = 0; a < 3; ++a)
        reach = std::max({reach, std::fabs(double(box.min[a])), std::fabs(double(box.max[a]))});
    const double byDistance = reach * kMinVoxelPerDistance;
    const double least = std::max(kMinVoxelSize, byDistance);
    const double smallest = std::min({double(voxel.x), double(voxel.y), double(voxel.z)});
    if (smallest >= least) return;
    std::ostringstream reason;
    reason << what << " (" << smallest << ") are smaller than the least eikon resolves here, "
           << least;
    if (byDistance > kMinVoxelSize)
        reason << " (float positions " << reach << " from the origin step by "
               << reach * std::ldexp(1.0, -23) << ")";
    else
        reason << " (OpenVDB's transforms need a voxel volume above 3e-15)";
    reason << ": enlarge the box or use fewer voxels";
    value.fail(reason.str());
}

}  // namespace eikon::scene_detail
