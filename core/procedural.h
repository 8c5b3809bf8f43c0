#pragma once
// Procedural shapes written into fields: the test and demo scenes use them where a closed-form
// answer is wanted (a homogeneous cube of known extinction and side).
#include <openvdb/openvdb.h>

#include <glm/vec3.hpp>

namespace eikon {

// Grids whose voxel i covers [i·h, (i+1)·h) in world space (cell centres at (i + ½)·h), so that a
// box whose faces lie on multiples of h is covered exactly. Inside the shape the value is
// `value`; outside it falls linearly to zero over `falloff` scene units (0: a sharp edge).
openvdb::FloatGrid::Ptr makeSphereField(glm::vec3 center, float radius, float value, float falloff,
                                        float voxelSize);
openvdb::FloatGrid::Ptr makeBoxField(glm::vec3 boxMin, glm::vec3 boxMax, float value, float falloff,
                                     float voxelSize);

}  // namespace eikon
