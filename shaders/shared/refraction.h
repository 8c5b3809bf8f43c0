// Refractive index n and its gradient ∇n (Sun et al. 2008, pipeline stage 2), the same on the GPU
// and in the CPU twin. Functions only; needs sampling.h (params, fetchVolume, sampleField, ...)
// and material_index.h (included at file scope before this one).
//
// Each material adds materialIndexExcess(f) for its field value f to vacuum's n = 1 (f·(ior − 1)
// for ordinary materials), so fields that fade out fade to n = 1 and overlapping materials add
// their excess index. materialIndexSlope(m) is ior − 1 (the slope at f = 0); Gladstone–Dale
// materials carry 1/T_ambient in materialInverseAmbient(m) (emission.w and scattering.w).

// EK_PRECISE (platform.h) keeps the GLSL compiler from reassociating the sum (Mesa turned
// f·(ior − 1) + n into a different rounding, 1 ulp off the CPU twin).

float refractiveIndexAt(vec3 indexPos) {
    EK_PRECISE float n = 1.0f;
    for (int m = 0; m < materialCount(params); ++m) {
        const float f = sampleField(materialSlot(params.materials[m]), indexPos);
        n += materialIndexExcess(f, materialIndexSlope(params.materials[m]),
                                 materialInverseAmbient(params.materials[m]));
    }
    return n;
}

// n at the centre of voxel v: the stored field values themselves, which is what the trilinear
// refractiveIndexAt returns there (its weights are 0 and 1), at one fetch per material instead
// of eight, and with no texture-unit rounding on either sampling path.
float refractiveIndexAtVoxel(ivec3 v) {
    EK_PRECISE float n = 1.0f;
    for (int m = 0; m < materialCount(params); ++m) {
        const float f = fetchVolume(materialSlot(params.materials[m]), v).x;
        n += materialIndexExcess(f, materialIndexSlope(params.materials[m]),
                                 materialInverseAmbient(params.materials[m]));
    }
    return n;
}

// n at voxel centres for gradientAtVoxel: refractiveIndexAtVoxel itself, or (EK_INDEX_VOLUME, the
// CPU twin) the includer's `float indexVolumeAt(ivec3 voxel)`, its values computed once a voxel
// beforehand: seven evaluations a voxel become one.
#ifdef EK_INDEX_VOLUME
#define EK_INDEX_AT_VOXEL indexVolumeAt
#else
#define EK_INDEX_AT_VOXEL refractiveIndexAtVoxel
#endif

// xyz: ∇n in scene units (per world unit along each axis); w: n, both at the centre of voxel v.
// Central differences of n at the neighbouring voxel centres; one-sided at the volume's faces,
// where the outer neighbour does not exist (clamping it would halve the gradient there). An axis
// one voxel thick has no difference to take: its component is 0.
vec4 gradientAtVoxel(ivec3 v) {
    const ivec3 res = volumeResolution();
    const vec3 h = volumeVoxelSize();
    vec3 grad = vec3(0.0f);
    for (int a = 0; a < 3; ++a) {
        ivec3 lo = v;
        ivec3 hi = v;
        lo[a] = max(v[a] - 1, 0);
        hi[a] = min(v[a] + 1, res[a] - 1);
        if (hi[a] == lo[a]) continue;
        const float dn = EK_INDEX_AT_VOXEL(hi) - EK_INDEX_AT_VOXEL(lo);
        grad[a] = dn / (float(hi[a] - lo[a]) * h[a]);
    }
    return vec4(grad, EK_INDEX_AT_VOXEL(v));
}
#undef EK_INDEX_AT_VOXEL
