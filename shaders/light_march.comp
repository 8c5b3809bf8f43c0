#version 430 core
// Transmittance toward a point or spot light, marched from every voxel centre
// (render/transport/light_volumes/light_volume_gpu.cpp).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "volume_bindings.glsl"

// All lights, stacked.
layout(rgba32f, binding = EK_IMAGE_LIGHT_TRANSMITTANCE) writeonly uniform image3D outTransmittance;
uniform int lightIndex;

vec4 fetchPreviousSlice(ivec3 voxel) { return vec4(1.0f); }  // unused: marching needs no slices

#include "shared/light_volume.h"

void main() {
    const ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, volumeResolution()))) return;
    imageStore(outTransmittance, stackedVoxel(lightIndex, v),
               vec4(marchedLightTransmittance(lightIndex, v), 1.0f));
}
