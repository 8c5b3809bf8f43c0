#version 430 core
// Labels every voxel with its octree leaf level and Δs_max (shaders/shared/octree.h) from the
// finished min/max pyramid.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "shared/bindings.h"
#include "shared/platform.h"

layout(std430, binding = EK_SSBO_OCTREE_PYRAMID) readonly buffer PyramidBlock { vec4 pyramid[]; };
layout(rgba32f, binding = EK_IMAGE_OCTREE) writeonly uniform image3D outOctree;
uniform ivec3 resolution;  // voxels
uniform float epsilon;
uniform float epsilonPrime;
uniform float stepLimit;  // scene units
uniform float minStep;    // scene units
uniform float kappaTolerance;  // optical depth; ≤ 0: κ does not limit steps
uniform float voxelLength;     // scene units

vec4 fetchPyramid(int index) { return pyramid[index]; }

#include "shared/octree.h"

void main() {
    const ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, resolution))) return;
    imageStore(outOctree, v,
               octreeLabel(resolution, v, epsilon, epsilonPrime, stepLimit, minStep,
                           kappaTolerance, voxelLength));
}
