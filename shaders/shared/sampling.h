// Trilinear sampling of the dense field volumes, the same on the GPU and in the CPU twin.
// Needs from the includer: the global `params` (GpuViewParams) and
// `vec4 fetchVolume(int slot, ivec3 voxel)` returning what a volume stores for a voxel: slots
// 0..EK_MAX_MATERIALS-1 are field textures (value in x), the next EK_MAX_LIGHTS are the light
// transmittance volumes (rgb).
// Volume index space: voxel i spans [i, i+1); its value sits at its centre i + 1/2. Outside the
// outer centres the edge value holds (clamp to edge), as GL_CLAMP_TO_EDGE would.

ivec3 volumeResolution() {
    return ivec3(params.resolution.x, params.resolution.y, params.resolution.z);
}

// The edge of a voxel along each axis, in scene units, of the volume params p describe.
#define EK_VOXEL_SIZE_OF(p)                        \
    ((vec3((p).volumeMax) - vec3((p).volumeMin)) / \
     vec3(ivec3((p).resolution.x, (p).resolution.y, (p).resolution.z)))

vec3 volumeVoxelSize() {
#ifdef EK_VOXEL_SIZE_MEMBER
    // CPU twins (render/volume_kernels_cpu.h): the includer's `voxelSize`, EK_VOXEL_SIZE_OF(params)
    // taken once. The twins read params through a reference, which any float store might change
    // as far as the compiler knows, so a call took its three divisions every time.
    return voxelSize;
#else
    return EK_VOXEL_SIZE_OF(params);
#endif
}

vec3 worldToVolumeIndex(vec3 world) {
    return (world - vec3(params.volumeMin)) / volumeVoxelSize();
}

#ifdef EK_HARDWARE_TRILINEAR
// GLSL only: the texture unit filters (volume_bindings.glsl). On llvmpipe its weights are float
// and the result matches the CPU twin to ~1e-6; on hardware GPUs they are fixed point (8
// fractional bits), so the exact path below is their default (render/frame_renderer.cpp).
vec4 sampleVolume(int slot, vec3 indexPos) {
    return filterVolume(slot, indexPos);
}
#else
// Forced inline in the CPU twin, as fetchVolume (volume_slots.h): the slot is a constant at most
// calls, and its branch then folds away.
EK_FORCE_INLINE vec4 sampleVolume(int slot, vec3 indexPos) {
    const ivec3 last = volumeResolution() - ivec3(1);
    const vec3 q = indexPos - vec3(0.5f);
    const vec3 base = floor(q);
    const vec3 f = q - base;
    const ivec3 i0 = clamp(ivec3(base), ivec3(0), last);
#ifdef EK_CONSTANT_BRICKS
    // CPU twins only (render/constant_bricks.h): where the volume holds one value c over every
    // voxel a sample from corner i0 reads, the eight corners are c, and these are the mixes below
    // of those corners, without fetching them.
    vec4 c;
    if (constantBrickValue(slot, i0, c)) {
        const vec4 a = mix(c, c, f.x);
        const vec4 b = mix(a, a, f.y);
        return mix(b, b, f.z);
    }
#endif
    const ivec3 i1 = clamp(ivec3(base) + ivec3(1), ivec3(0), last);
    const vec4 c000 = fetchVolume(slot, ivec3(i0.x, i0.y, i0.z));
    const vec4 c100 = fetchVolume(slot, ivec3(i1.x, i0.y, i0.z));
    const vec4 c010 = fetchVolume(slot, ivec3(i0.x, i1.y, i0.z));
    const vec4 c110 = fetchVolume(slot, ivec3(i1.x, i1.y, i0.z));
    const vec4 c001 = fetchVolume(slot, ivec3(i0.x, i0.y, i1.z));
    const vec4 c101 = fetchVolume(slot, ivec3(i1.x, i0.y, i1.z));
    const vec4 c011 = fetchVolume(slot, ivec3(i0.x, i1.y, i1.z));
    const vec4 c111 = fetchVolume(slot, ivec3(i1.x, i1.y, i1.z));
    const vec4 c00 = mix(c000, c100, f.x);
    const vec4 c10 = mix(c010, c110, f.x);
    const vec4 c01 = mix(c001, c101, f.x);
    const vec4 c11 = mix(c011, c111, f.x);
    return mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
}
#endif

float sampleField(int slot, vec3 indexPos) {
    return sampleVolume(slot, indexPos).x;
}

// Volume-index position and world position of the centre of voxel v.
vec3 voxelCenterIndex(ivec3 v) {
    return vec3(v) + vec3(0.5f);
}
vec3 voxelCenterWorld(ivec3 v) {
    return vec3(params.volumeMin) + voxelCenterIndex(v) * volumeVoxelSize();
}
