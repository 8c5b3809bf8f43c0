#version 430 core
// Smooths one RGBA32F volume into another (render/smoothing_gpu.cpp).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "shared/bindings.h"

layout(rgba32f, binding = EK_IMAGE_SMOOTH_SOURCE) readonly uniform image3D source;
layout(rgba32f, binding = EK_IMAGE_SMOOTH_TARGET) writeonly uniform image3D target;
uniform ivec3 resolution;

vec4 fetchUnsmoothed(ivec3 voxel) { return imageLoad(source, voxel); }

#include "shared/platform.h"
#include "shared/smoothing.h"

void main() {
    const ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, resolution))) return;
    imageStore(target, v, smoothedVoxel(v, resolution));
}
