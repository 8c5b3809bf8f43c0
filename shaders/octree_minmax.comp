#version 430 core
// One level of the octree's min/max pyramid (shaders/shared/octree.h): level 0 from n in the
// gradient volume, each coarser level from the one below; the host dispatches the levels in order
// with a storage barrier between them.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

// The params SSBO and the field textures, for κ at voxel centres (optics.h voxelExtinctionRange).
#include "volume_bindings.glsl"

layout(std430, binding = EK_SSBO_OCTREE_PYRAMID) buffer PyramidBlock { vec4 pyramid[]; };
layout(rgba32f, binding = EK_IMAGE_GRADIENT) readonly uniform image3D gradientVolume;  // w: n
uniform ivec3 resolution;  // voxels
uniform int level;

vec4 fetchPyramid(int index) { return pyramid[index]; }
float fetchIndex(ivec3 voxel) { return imageLoad(gradientVolume, voxel).w; }
vec2 fetchKappaRange(ivec3 voxel) { return voxelExtinctionRange(voxel); }

#define EK_OCTREE_LEAF_RANGE
#include "shared/octree.h"

void main() {
    const ivec3 node = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(node, pyramidLevelSize(resolution, level)))) return;
    const int index = pyramidNodeIndex(resolution, level, node);
    if (level == 0) {
        pyramid[index] = pyramidLeafRange(resolution, node);
    } else {
        pyramid[index] = pyramidNodeFromChildren(resolution, level, node);
    }
}
