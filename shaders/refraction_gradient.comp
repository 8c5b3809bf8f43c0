#version 430 core
// Pipeline stage 2: n and ∇n at every voxel centre (shaders/shared/refraction.h), written to the
// gradient volume (render/refraction_volume_gpu.cpp).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "volume_bindings.glsl"
#include "shared/material_index.h"
#include "shared/refraction.h"

// xyz: ∇n; w: n.
layout(rgba32f, binding = EK_IMAGE_GRADIENT) writeonly uniform image3D outGradient;

void main() {
    const ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, volumeResolution()))) return;
    imageStore(outGradient, v, gradientAtVoxel(v));
}
