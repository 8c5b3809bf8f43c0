#version 430 core
// Voxelization step 1 (shaders/shared/voxelize.h): one invocation per triangle flips one bit in
// each fine column it crosses, with atomicXor, so the bits do not depend on the order.
layout(local_size_x = 64) in;

#include "shared/bindings.h"

layout(std430, binding = EK_SSBO_VOXELIZE_POSITIONS) readonly buffer Positions {
    vec4 positions[];
};
layout(std430, binding = EK_SSBO_VOXELIZE_TRIANGLES) readonly buffer Triangles {
    uvec4 triangles[];
};
layout(std430, binding = EK_SSBO_VOXELIZE_BITS) buffer Bits { uint bits[]; };

uniform vec3 volumeMin;
uniform vec3 fineVoxelSize;
uniform ivec3 fineResolution;
uniform int triangleCount;
uniform int wordsPerColumn;

void toggleSample(int column, int k) {
    atomicXor(bits[column * wordsPerColumn + k / 32], 1u << uint(k % 32));
}
uint fetchInsideWord(int index) { return bits[index]; }

#include "shared/platform.h"
#include "shared/voxelize.h"

void main() {
    const int t = int(gl_GlobalInvocationID.x);
    if (t >= triangleCount) return;
    const uvec4 tri = triangles[t];
    voxelizeTriangle(positions[tri.x].xyz, positions[tri.y].xyz, positions[tri.z].xyz, volumeMin,
                     fineVoxelSize, fineResolution);
}
