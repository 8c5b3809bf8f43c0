// Bindings every volume pass shares: the packed parameters, the field volumes and the light
// transmittance volumes, the environment image, and the fetch hooks shaders/shared/sampling.h and
// shaders/shared/environment.h expect.
//
// Each kind lives in ONE 3D texture with its volumes stacked along z (slot s at z offset
// s·resolution.z), so every fetch goes through one sampler: llvmpipe turns a sampler array
// indexed by a variable into a per-lane loop (~100x slower), and a switch over constant indices
// into masked execution of every case.
#include "shared/gpu_types.h"

layout(std430, binding = 0) readonly buffer ViewParamsBlock { GpuViewParams params; };
layout(binding = 0) uniform sampler3D fieldTex;  // R32F, EK_MAX_MATERIALS slots at most
layout(binding = 1) uniform sampler3D lightTex;  // RGBA32F, one volume per light
layout(binding = 2) uniform sampler3D gradientTex;  // RGBA32F: xyz = ∇n, w = n (curved rays)
// Unit 3 is the photon pass's octree. The smoothed photon volumes (render/transport/photons/photon_radiance.h):
layout(binding = 4) uniform sampler3D photonRadianceTex;   // RGBA32F: rgb = Σ flux·length
layout(binding = 5) uniform sampler3D photonDirectionTex;  // RGBA32F: xyz = Σ weighted direction
// The equirectangular environment image (RGBA32F), when params.environment.x asks for it.
layout(binding = 6) uniform sampler2D environmentTex;

ivec3 stackedVoxel(int slot, ivec3 voxel) {
    return ivec3(voxel.x, voxel.y, voxel.z + slot * params.resolution.z);
}

vec4 fetchVolume(int slot, ivec3 voxel) {
    if (slot < EK_MAX_MATERIALS) return texelFetch(fieldTex, stackedVoxel(slot, voxel), 0);
    if (slot == EK_GRADIENT_SLOT) return texelFetch(gradientTex, voxel, 0);
    if (slot == EK_PHOTON_RADIANCE_SLOT) return texelFetch(photonRadianceTex, voxel, 0);
    if (slot == EK_PHOTON_DIRECTION_SLOT) return texelFetch(photonDirectionTex, voxel, 0);
    return texelFetch(lightTex, stackedVoxel(slot - EK_MAX_MATERIALS, voxel), 0);
}

// Exact texels: the shared code filters, so the GPU matches the CPU twin.
vec4 fetchEnvironment(ivec2 texel) { return texelFetch(environmentTex, texel, 0); }

#ifdef EK_HARDWARE_TRILINEAR
// Trilinear filtering by the texture unit, one lookup instead of eight texelFetch: 2-3x faster on
// llvmpipe. Positions are clamped to the outer voxel centres of their own slot, so neighbouring
// slots in the stack never bleed in (the same clamp-to-edge as the exact path).
vec4 filterStacked(sampler3D tex, int slot, vec3 indexPos) {
    const vec3 res = vec3(params.resolution.x, params.resolution.y, params.resolution.z);
    const vec3 q = clamp(indexPos, vec3(0.5f), res - vec3(0.5f));
    const vec3 size = vec3(textureSize(tex, 0));
    return texture(tex, vec3(q.x, q.y, q.z + float(slot) * res.z) / size);
}

vec4 filterVolume(int slot, vec3 indexPos) {
    if (slot < EK_MAX_MATERIALS) return filterStacked(fieldTex, slot, indexPos);
    if (slot == EK_GRADIENT_SLOT) return filterStacked(gradientTex, 0, indexPos);
    if (slot == EK_PHOTON_RADIANCE_SLOT) return filterStacked(photonRadianceTex, 0, indexPos);
    if (slot == EK_PHOTON_DIRECTION_SLOT) return filterStacked(photonDirectionTex, 0, indexPos);
    return filterStacked(lightTex, slot - EK_MAX_MATERIALS, indexPos);
}
#endif

#include "shared/sampling.h"
#include "shared/optics.h"
#include "shared/receivers.h"
