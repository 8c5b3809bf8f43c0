#version 430 core
// Voxelization step 3 (shaders/shared/voxelize.h): each voxel's coverage, the fraction of its
// 4×4×4 fine samples inside, into an R32F volume.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "shared/bindings.h"

layout(std430, binding = EK_SSBO_VOXELIZE_BITS) readonly buffer Bits { uint bits[]; };
layout(r32f, binding = EK_IMAGE_COVERAGE) writeonly uniform image3D coverage;

uniform ivec3 resolution;
uniform ivec3 fineResolution;

void toggleSample(int column, int k) {}
uint fetchInsideWord(int index) { return bits[index]; }

#include "shared/platform.h"
#include "shared/voxelize.h"

void main() {
    const ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, resolution))) return;
    imageStore(coverage, v, vec4(voxelizeCoverage(v, fineResolution), 0.0f, 0.0f, 0.0f));
}
