#pragma once
// The smallest voxel a scene may ask for, checked where the scene is read so that the message
// names the file and the JSON pointer. Internal to core (scene.cpp, scene_simulation.cpp).
//
// Two limits, whichever is larger:
//  - OpenVDB refuses a transform whose voxel volume is below 3e-15 ("ArithmeticError: Non-zero
//    scale values required", which reached users as an anonymous internal error for a domain
//    1e-30 wide); kMinVoxelSize cubed stays above it;
//  - float positions must resolve a voxel: at distance r from the origin a float's step is
//    r·2^-23, and a voxel of at least r·2^-16 keeps 128 of them per voxel.
#include <string>

#include <glm/vec3.hpp>

#include "core/bounds.h"
#include "core/json_reader.h"

namespace eikon::scene_detail {

constexpr double kMinVoxelSize = 2e-5;                  // scene units; 8e-15 > 3e-15 cubed
constexpr double kMinVoxelPerDistance = 1.0 / 65536.0;  // 2^-16 of the distance from the origin

// Throws at `value`'s pointer when the smallest of `voxel`'s edges, for a grid spanning `box`, is
// below the limits above; `what` starts the reason ("the volume's voxels").
void checkVoxelSize(const json::Value& value, glm::vec3 voxel, const Bounds3& box,
                    const std::string& what);

}  // namespace eikon::scene_detail
