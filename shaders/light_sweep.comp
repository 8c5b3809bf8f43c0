#version 430 core
// One slice of the sweep for a directional light (render/transport/light_volumes/light_volume_gpu.cpp): the host
// dispatches the slices in the light's order with an image barrier between them.
layout(local_size_x = 8, local_size_y = 8) in;

#include "volume_bindings.glsl"

// All lights, stacked.
layout(rgba32f, binding = EK_IMAGE_LIGHT_TRANSMITTANCE) uniform image3D transmittance;
uniform int lightIndex;
uniform int slice;

vec4 fetchPreviousSlice(ivec3 voxel) {
    return imageLoad(transmittance, stackedVoxel(lightIndex, voxel));
}

#include "shared/light_volume.h"

void main() {
    const int axis = sweepAxis(vec3(params.lights[lightIndex].direction));
    const int u = (axis + 1) % 3;
    const int w = (axis + 2) % 3;
    const ivec3 res = volumeResolution();
    const ivec2 g = ivec2(gl_GlobalInvocationID.xy);
    if (g.x >= res[u] || g.y >= res[w]) return;
    ivec3 v;
    v[axis] = slice;
    v[u] = g.x;
    v[w] = g.y;
    imageStore(transmittance, stackedVoxel(lightIndex, v),
               vec4(sweptLightTransmittance(lightIndex, v), 1.0f));
}
