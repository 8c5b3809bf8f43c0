// Bindings every volume pass shares: the packed parameters, the field volumes and the light
// transmittance volumes, the environment image, and the fetch hooks shaders/shared/sampling.h and
// shaders/shared/environment.h expect. The binding numbers are named in shaders/shared/bindings.h,
// which the host binds by.
//
// Each kind lives in ONE 3D texture with its volumes stacked along z (slot s at z offset
// s·resolution.z), so every fetch goes through one sampler: llvmpipe turns a sampler array
// indexed by a variable into a per-lane loop (~100x slower), and a switch over constant indices
// into masked execution of every case. The switch from a slot to its kind is
// shaders/shared/volume_slots.h, which the CPU twin runs too; the hooks below give it one sampler
// per kind.
#include "shared/bindings.h"
#include "shared/gpu_types.h"

layout(std430, binding = EK_SSBO_VIEW_PARAMS) readonly buffer ViewParamsBlock {
    GpuViewParams params;
};
// R32F, EK_MAX_MATERIALS slots at most.
layout(binding = EK_UNIT_FIELDS) uniform sampler3D fieldTex;
// RGBA32F, one volume per light.
layout(binding = EK_UNIT_LIGHT_TRANSMITTANCE) uniform sampler3D lightTex;
// RGBA32F: xyz = ∇n, w = n (curved rays).
layout(binding = EK_UNIT_GRADIENT) uniform sampler3D gradientTex;
// EK_UNIT_OCTREE is the photon pass's octree. The light-transport method's fluence volumes (the
// output contract, render/light_transport.h), RGBA32F: rgb = Σ flux·length, and xyz = Σ
// weighted direction.
layout(binding = EK_UNIT_FLUENCE) uniform sampler3D fluenceTex;
layout(binding = EK_UNIT_FLUENCE_DIRECTION) uniform sampler3D fluenceDirectionTex;
// The equirectangular environment image (RGBA32F), when environmentType(params) asks for it.
layout(binding = EK_UNIT_ENVIRONMENT) uniform sampler2D environmentTex;

ivec3 stackedVoxel(int slot, ivec3 voxel) {
    return ivec3(voxel.x, voxel.y, voxel.z + slot * params.resolution.z);
}

vec4 fetchFieldVoxel(int field, ivec3 voxel) {
    return texelFetch(fieldTex, stackedVoxel(field, voxel), 0);
}
vec4 fetchLightVoxel(int light, ivec3 voxel) {
    return texelFetch(lightTex, stackedVoxel(light, voxel), 0);
}
vec4 fetchGradientVoxel(ivec3 voxel) { return texelFetch(gradientTex, voxel, 0); }
#ifndef EK_FLUENCE_WINDOW
vec4 fetchFluenceVoxel(ivec3 voxel) { return texelFetch(fluenceTex, voxel, 0); }
vec4 fetchFluenceDirectionVoxel(ivec3 voxel) { return texelFetch(fluenceDirectionTex, voxel, 0); }
#else
// The plane sweep's interleaved view (view_interleaved.comp): the fluence units hold only the
// last fluenceWindow.y slices swept across axis fluenceWindow.x, slice k at layer k % slices of
// a volume of res[u] × res[w] × slices (u, w the next two axes); a lookup elsewhere along the
// axis takes the nearest slice held, fluenceWindow.z … .w (the CPU twin's FluenceWindow,
// render/volume_kernels_cpu.h).
uniform ivec4 fluenceWindow;  // axis, slices, first, last
ivec3 fluenceWindowTexel(ivec3 voxel) {
    const int axis = fluenceWindow.x;
    const int k = clamp(voxel[axis], fluenceWindow.z, fluenceWindow.w);
    return ivec3(voxel[(axis + 1) % 3], voxel[(axis + 2) % 3], k % fluenceWindow.y);
}
vec4 fetchFluenceVoxel(ivec3 voxel) {
    return texelFetch(fluenceTex, fluenceWindowTexel(voxel), 0);
}
vec4 fetchFluenceDirectionVoxel(ivec3 voxel) {
    return texelFetch(fluenceDirectionTex, fluenceWindowTexel(voxel), 0);
}
#endif

// Exact texels: the shared code filters, so the GPU matches the CPU twin.
vec4 fetchEnvironment(ivec2 texel) { return texelFetch(environmentTex, texel, 0); }

#if defined(EK_HARDWARE_TRILINEAR) && defined(EK_FLUENCE_WINDOW)
#error "the fluence window's slices wrap around: the texture unit cannot filter across them"
#endif

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

vec4 filterFieldVolume(int field, vec3 indexPos) {
    return filterStacked(fieldTex, field, indexPos);
}
vec4 filterLightVolume(int light, vec3 indexPos) {
    return filterStacked(lightTex, light, indexPos);
}
vec4 filterGradientVolume(vec3 indexPos) { return filterStacked(gradientTex, 0, indexPos); }
vec4 filterFluenceVolume(vec3 indexPos) {
    return filterStacked(fluenceTex, 0, indexPos);
}
vec4 filterFluenceDirectionVolume(vec3 indexPos) {
    return filterStacked(fluenceDirectionTex, 0, indexPos);
}
#endif

#include "shared/volume_slots.h"
#include "shared/sampling.h"
#include "shared/optics.h"
#include "shared/receivers.h"
#include "shared/ray_equation.h"
