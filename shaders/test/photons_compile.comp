#version 430 core
// Compiles shaders/shared/photons.h as GLSL (tests/render/test_photons.cpp): the CPU twin runs
// it as C++, and the GPU port must find it valid GLSL 4.30.
layout(local_size_x = 64) in;

#include "../volume_bindings.glsl"

// The hooks photons.h calls, declared before it and defined after (they need its struct).
vec4 fetchOctree(ivec3 voxel);
void depositVoxel(ivec3 voxel, vec3 fluxLength, vec3 weightedDir);
void depositReceiverTexel(int index, vec3 flux);
uniform vec3 photonChannels;

#include "../shared/photons.h"

layout(binding = EK_UNIT_OCTREE) uniform sampler3D octreeTex;
layout(std430, binding = EK_SSBO_PHOTONS) buffer Photons { GpuPhoton photons[]; };
layout(std430, binding = EK_SSBO_PHOTON_DEPOSITS) buffer Deposits { uint deposits[]; };

vec4 fetchOctree(ivec3 voxel) { return texelFetch(octreeTex, voxel, 0); }

void depositVoxel(ivec3 voxel, vec3 fluxLength, vec3 weightedDir) {
    atomicAdd(deposits[voxel.x], uint(fluxLength.x + weightedDir.x));
}

void depositReceiverTexel(int index, vec3 flux) { atomicAdd(deposits[index], uint(flux.x)); }

void main() {
    const int i = int(gl_GlobalInvocationID.x);
    GpuPhoton p = generateDirectionalPhoton(0, 8, i, 1u, 0u, 1e-4f);
    vec3 extinguished = vec3(0.0f);
    tracePhoton(p, 0.1f, i % 4, 100, extinguished);  // every integrator (EK_RAY_*)
    photons[i] = p;
}
