// Light transmittance volumes: for every light, exp(−∫κ) from each voxel centre toward the light,
// computed once per change of lights or extinction and then looked up by the viewing pass (a
// camera move costs nothing here). Needs optics.h and, from the includer,
// `vec4 fetchPreviousSlice(ivec3 voxel)`: the transmittance already computed for a voxel of the
// previous slice of a sweep.
//
// By default every voxel marches toward the light (transmittanceToward): O(N) per voxel, exact
// for the trilinear medium up to the step. With EK_SHADOWS_SWEPT directional lights sweep instead,
// slice by slice along the axis where the light direction is largest: a voxel's transmittance is
// the previous slice's, interpolated bilinearly where the ray toward the light crosses it, times
// exp(−κ̄ Δ) over the step Δ between the two (trapezoid rule): O(1) work per voxel instead of
// O(N). Along an axis-aligned direction the lookups land on voxel centres and the sweep is
// exact for piecewise-linear κ; obliquely the bilinear lookups blur shadows by a fraction of a
// voxel per slice (measured against the marched reference in BENCHMARKS.md).

bool sweepsLight(int l) {
    // A light with a disc marches its disc's directions (lightTransmittance in optics.h).
    return shadowMode(params) == EK_SHADOWS_SWEPT &&
           lightType(params.lights[l]) == EK_LIGHT_DIRECTIONAL &&
           !(lightDiscVersine(params.lights[l]) > 0.0f);
}

// The axis a directional light is swept along, and the order: +1 when it travels toward +axis.
int sweepAxis(vec3 d) {
    const vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) return 0;
    return a.y >= a.z ? 1 : 2;
}

int sweepOrder(vec3 d, int axis) {
    return d[axis] >= 0.0f ? 1 : -1;
}

// Transmittance from voxel v toward light l by marching (point and spot lights, the first slice
// of a sweep, and voxels whose path leaves through a side of the volume).
vec3 marchedLightTransmittance(int l, ivec3 v) {
    const vec3 x = voxelCenterWorld(v);
    vec3 toLight;
    float lightDistance;
    lightIrradiance(l, x, toLight, lightDistance);
    return lightTransmittance(l, x, toLight, lightDistance);
}

vec3 sweptLightTransmittance(int l, ivec3 v) {
    const vec3 d = vec3(params.lights[l].direction);
    const int axis = sweepAxis(d);
    const int order = sweepOrder(d, axis);
    const ivec3 res = volumeResolution();
    const int previous = v[axis] - order;
    if (previous < 0 || previous >= res[axis]) return marchedLightTransmittance(l, v);

    const vec3 voxel = volumeVoxelSize();
    const float delta = voxel[axis] / abs(d[axis]);  // path length between two slices
    const vec3 p = voxelCenterIndex(v);
    vec3 pPrev = p - d * (delta / voxel);  // toward the light, in index units
    pPrev[axis] = float(previous) + 0.5f;  // exactly on the previous slice's centre plane
    const int u = (axis + 1) % 3;
    const int w = (axis + 2) % 3;
    // Interpolate only between voxel centres. Beyond the outer centres the path toward the light
    // is about to leave through a side face, where transmittance jumps to 1; clamping to the
    // edge voxel would instead carry the edge's shadow on, so those voxels march.
    if (pPrev[u] < 0.5f || pPrev[u] > float(res[u]) - 0.5f || pPrev[w] < 0.5f ||
        pPrev[w] > float(res[w]) - 0.5f)
        return marchedLightTransmittance(l, v);

    const float qu = pPrev[u] - 0.5f;
    const float qw = pPrev[w] - 0.5f;
    const float bu = floor(qu);
    const float bw = floor(qw);
    const int u0 = clamp(int(bu), 0, res[u] - 1);
    const int u1 = clamp(int(bu) + 1, 0, res[u] - 1);
    const int w0 = clamp(int(bw), 0, res[w] - 1);
    const int w1 = clamp(int(bw) + 1, 0, res[w] - 1);
    ivec3 c = ivec3(0);
    c[axis] = previous;
    c[u] = u0;
    c[w] = w0;
    const vec3 t00 = vec3(fetchPreviousSlice(c));
    c[u] = u1;
    const vec3 t10 = vec3(fetchPreviousSlice(c));
    c[w] = w1;
    const vec3 t11 = vec3(fetchPreviousSlice(c));
    c[u] = u0;
    const vec3 t01 = vec3(fetchPreviousSlice(c));
    const vec3 tPrev = mix(mix(t00, t10, qu - bu), mix(t01, t11, qu - bu), qw - bw);
    return tPrev * channelDecay(0.5f * (extinctionAt(p) + extinctionAt(pPrev)), delta);
}
