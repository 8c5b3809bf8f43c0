// The slot switch of the volume passes, written once for the GPU and the CPU twin: which volume a
// slot of fetchVolume (sampling.h, optics.h) reads. Slots (gpu_types.h): 0..EK_MAX_MATERIALS-1
// the fields (value in x), the next EK_MAX_LIGHTS the lights' transmittance volumes, then
// EK_GRADIENT_SLOT, EK_FLUENCE_SLOT and EK_FLUENCE_DIRECTION_SLOT.
//
// Needs from the includer one fetch per kind of volume; on the GPU each reads its own sampler,
// with a constant unit in every branch (shaders/volume_bindings.glsl says why that matters on
// llvmpipe), so the switch costs what it cost when each side wrote it out:
//   vec4 fetchFieldVoxel(int field, ivec3 voxel)      the field's value in x
//   vec4 fetchLightVoxel(int light, ivec3 voxel)      rgb: transmittance toward light `light`
//   vec4 fetchGradientVoxel(ivec3 voxel)              xyz = ∇n, w = n
//   vec4 fetchFluenceVoxel(ivec3 voxel)               rgb = Σ flux·length (the fluence)
//   vec4 fetchFluenceDirectionVoxel(ivec3 voxel)      xyz = Σ weighted direction
// and, with EK_HARDWARE_TRILINEAR (GLSL only: the texture unit filters), the same five as
// filterFieldVolume(int, vec3 indexPos) ... filterFluenceDirectionVolume(vec3 indexPos).

// Forced inline (EK_FORCE_INLINE; nothing in GLSL): GCC kept it out of line in the CPU twin, a
// call for each of a sample's eight corners; inlined, the slot's branch leaves the corner loop and
// the twin's view pass took half the time (BENCHMARKS.md, "Inlined sampling").
EK_FORCE_INLINE vec4 fetchVolume(int slot, ivec3 voxel) {
    if (slot < EK_MAX_MATERIALS) return fetchFieldVoxel(slot, voxel);
    if (slot == EK_GRADIENT_SLOT) return fetchGradientVoxel(voxel);
    if (slot == EK_FLUENCE_SLOT) return fetchFluenceVoxel(voxel);
    if (slot == EK_FLUENCE_DIRECTION_SLOT) return fetchFluenceDirectionVoxel(voxel);
    return fetchLightVoxel(slot - EK_MAX_MATERIALS, voxel);
}

#ifdef EK_HARDWARE_TRILINEAR
// The same switch over filtered lookups. GLSL has no templates and cannot pass a sampler out of a
// function, so it is the one switch written a second time; it sits here, beside the first.
vec4 filterVolume(int slot, vec3 indexPos) {
    if (slot < EK_MAX_MATERIALS) return filterFieldVolume(slot, indexPos);
    if (slot == EK_GRADIENT_SLOT) return filterGradientVolume(indexPos);
    if (slot == EK_FLUENCE_SLOT) return filterFluenceVolume(indexPos);
    if (slot == EK_FLUENCE_DIRECTION_SLOT) return filterFluenceDirectionVolume(indexPos);
    return filterLightVolume(slot - EK_MAX_MATERIALS, indexPos);
}
#endif
