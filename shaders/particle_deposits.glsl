// The deposit hooks of shared/photons.h for the particle traces on the GPU (photon_trace.comp,
// wavefront_trace.comp): fixed-point sums (fixed_point.glsl) into the deposit volume and the
// receiver maps, with the CPU twin's scales. The includer declares the buffers `deposits` (per
// voxel, x fastest, 6 int64 sums as (low, high) word pairs: r, g, b, then the weighted direction
// x, y, z) and `receiverDeposits` (3 int64 pairs per receiver map texel), and the uniforms
// depositScale (rgb: power·length channels; w: weighted direction) and totalScale (per channel).

void depositVoxel(ivec3 voxel, vec3 fluxLength, vec3 weightedDir) {
    const ivec3 res = volumeResolution();
    const int base = ((voxel.z * res.y + voxel.y) * res.x + voxel.x) * 12;
    for (int c = 0; c < 3; ++c) {
        const uvec2 f = toFixed(fluxLength[c], depositScale[c]);
        EK_ADD_FIXED(deposits, base + 2 * c, f);
        const uvec2 d = toFixed(weightedDir[c], depositScale.w);
        EK_ADD_FIXED(deposits, base + 6 + 2 * c, d);
    }
}

void depositReceiverTexel(int index, vec3 flux) {
    for (int c = 0; c < 3; ++c) {
        const uvec2 f = toFixed(flux[c], totalScale[c]);
        EK_ADD_FIXED(receiverDeposits, index * 6 + 2 * c, f);
    }
}
