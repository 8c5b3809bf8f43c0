// Smoothing of the radiance (and direction) volume, pipeline step 6 of Sun et al. 2008: a
// 3×3×3 Gaussian, here the binomial (1, 2, 1)/4 along each axis (σ = 1/√2 voxel). Functions only;
// needs from the includer `vec4 fetchUnsmoothed(ivec3 voxel)`.
//
// At the volume's faces the missing neighbours are left out and the weights renormalized, so a
// constant volume stays constant (the estimate is a weighted mean, not a redistribution).

vec4 smoothedVoxel(ivec3 v, ivec3 res) {
    vec4 sum = vec4(0.0f);
    float weightSum = 0.0f;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const ivec3 n = ivec3(v.x + dx, v.y + dy, v.z + dz);
                if (n.x < 0 || n.y < 0 || n.z < 0 || n.x >= res.x || n.y >= res.y || n.z >= res.z)
                    continue;
                const float w = float((2 - abs(dx)) * (2 - abs(dy)) * (2 - abs(dz)));
                sum += w * fetchUnsmoothed(n);
                weightSum += w;
            }
    return sum / weightSum;
}

#ifdef __cplusplus
// The CPU twin's shortcut for a voxel whose 26 neighbours all exist (none on a face):
// smoothedVoxel's sums in the same order, without its bounds tests, so the same floats; the loops
// unroll and the weights fold (weightSum is 64 exactly either way).
vec4 smoothedInteriorVoxel(ivec3 v) {
    vec4 sum = vec4(0.0f);
    float weightSum = 0.0f;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const float w = float((2 - abs(dx)) * (2 - abs(dy)) * (2 - abs(dz)));
                sum += w * fetchUnsmoothed(ivec3(v.x + dx, v.y + dy, v.z + dz));
                weightSum += w;
            }
    return sum / weightSum;
}
#endif
