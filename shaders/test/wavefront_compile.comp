#version 430 core
// Compiles shaders/shared/wavefront.h as GLSL (tests/render/test_wavefront.cpp): the CPU twin
// runs it as C++, and the GPU port must find it valid GLSL 4.30.
layout(local_size_x = 64) in;

#include "../volume_bindings.glsl"

// The hooks photons.h calls, declared before it and defined after.
vec4 fetchOctree(ivec3 voxel);
void depositVoxel(ivec3 voxel, vec3 fluxLength, vec3 weightedDir);
void depositReceiverTexel(int index, vec3 flux);
uniform vec3 photonChannels;

#include "../shared/material_index.h"
#include "../shared/photons.h"
#include "../shared/wavefront.h"

layout(binding = EK_UNIT_OCTREE) uniform sampler3D octreeTex;
layout(std430, binding = EK_SSBO_PHOTONS) buffer Patches { GpuWavefrontPatch patches[]; };
layout(std430, binding = EK_SSBO_PHOTON_DEPOSITS) buffer Deposits { uint deposits[]; };

vec4 fetchOctree(ivec3 voxel) { return texelFetch(octreeTex, voxel, 0); }

void depositVoxel(ivec3 voxel, vec3 fluxLength, vec3 weightedDir) {
    atomicAdd(deposits[voxel.x], uint(fluxLength.x + weightedDir.x));
}

void depositReceiverTexel(int index, vec3 flux) { atomicAdd(deposits[index], uint(flux.x)); }

void main() {
    const int i = int(gl_GlobalInvocationID.x);
    GpuWavefrontPatch p = generatePatch(0, EK_PHOTON_GRID_PARALLEL, 8, i, 1e-4f);
    vec3 extinguished = vec3(0.0f);
    vec3 reflected = vec3(0.0f);
    for (int s = 0; s < 100 && int(p.state.x) == EK_PHOTON_ACTIVE; ++s) {
        if (patchNeedsSplit(p, 1.0f)) p = patchChild(p, s % 4);
        // every integrator, with and without surfaces
        p.state.x = float(patchStep(p, 0.1f, i % 3, i % 2, 1 + i % 3, 0.01f * float(i % 2),
                                    extinguished, reflected));
    }
    patches[i] = p;
}
