// Photon tracing, steps 4 and 5 of Sun et al. 2008 (docs/METHODS.md §1), the same on the GPU and
// in the CPU twin (render/photon_tracing_cpu.cpp).
//
// Two parts. The GpuPhoton struct sits under its own include guard, so that C++ can include this
// file once at namespace scope with EK_PHOTON_TYPES_ONLY defined (for the struct alone) and again
// inside a kernel struct body (for the functions, which then see the kernel's members); GLSL
// includes it once at file scope and gets both.
//
// Needs from the includer for the functions: sampling.h and optics.h (params, fetchVolume with
// the ∇n volume at EK_GRADIENT_SLOT), and
//   vec4 fetchOctree(ivec3 voxel)   the octree volume (render/refraction_volume.h): x = level,
//                                   y = Δs_max in scene units, z, w = n range;
//   void depositVoxel(ivec3 voxel, vec3 fluxLength, vec3 weightedDir)
//                                   adds one segment piece to the radiance volume.
//
// Units. A directional light of irradiance E (GpuLight.radiance, power per unit area across the
// beam) sends photons through an N×N grid of cells over the rectangle that the volume box
// projects to on the plane perpendicular to the light; a photon carries flux E × cell area
// (power). Cells whose jittered ray misses the box emit nothing, so the emitted power is
// Σ_hit E·cellArea, whose expectation is E × the box's projected area. Deposits are flux·length
// (power × scene units): every voxel a segment crosses receives ∫ flux ds over the part of the
// segment inside it; divided by the voxel's volume that is the fluence rate (power per area).

#ifndef EIKON_SHARED_PHOTON_TYPES_H
#define EIKON_SHARED_PHOTON_TYPES_H

// GpuPhoton.position.w: where a photon is in its life.
#define EK_PHOTON_INACTIVE 0  // its cell's ray missed the box: it never existed
#define EK_PHOTON_ACTIVE 1
#define EK_PHOTON_ESCAPED 2  // left the box; position and direction are its exit
#define EK_PHOTON_DROPPED 3  // its flux fell below its threshold, or its march went degenerate
#define EK_PHOTON_CUT 4      // still active after the step limit (a trapped path)

// One photon's state between steps; only vec4 members, so std430 and C++ offsets agree.
struct GpuPhoton {
    vec4 position;   // xyz: world position; w: EK_PHOTON_* state
    vec4 direction;  // xyz: v = n dx/ds (|v| = n); w: steps taken so far
    vec4 flux;       // rgb: power carried; w: the flux below which the photon is dropped
};

#endif

#ifndef EK_PHOTON_TYPES_ONLY

// Counter-based random numbers: a hash of (seed, frame, light, photon index, dimension), so any
// photon's numbers are known without a shared generator and every thread count or GPU schedule
// draws the same ones. PCG hash (Jarzynski and Olano 2020); uint arithmetic wraps at 32 bits on
// both sides.
uint pcgHash(uint v) {
    const uint state = v * 747796405u + 2891336453u;
    const uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

uint photonHash(uint seed, uint frame, uint light, uint index, uint dimension) {
    return pcgHash(index ^ pcgHash(dimension ^ pcgHash(light ^ pcgHash(frame ^ pcgHash(seed)))));
}

// The top 24 bits as a float in [0, 1): exactly representable, so never rounds up to 1.
float hashToUnit(uint h) {
    return float(h >> 8u) * (1.0f / 16777216.0f);
}

// A unit basis (u, w) of the plane perpendicular to unit d. For an axis-aligned d both are exact
// axes, so the light-space grid tiles an axis-aligned box face cell for cell.
void lightPlaneBasis(vec3 d, EK_OUT(vec3) u, EK_OUT(vec3) w) {
    const vec3 helper = abs(d.y) < 0.999f ? vec3(0.0f, 1.0f, 0.0f) : vec3(1.0f, 0.0f, 0.0f);
    u = normalize(cross(helper, d));
    w = cross(d, u);
}

// The rectangle the box projects to in the light plane: x, y = min (u, w); z, w = max.
vec4 lightPlaneBounds(vec3 u, vec3 w) {
    vec4 r = vec4(3.0e38f, 3.0e38f, -3.0e38f, -3.0e38f);
    for (int c = 0; c < 8; ++c) {
        const vec3 corner = vec3((c & 1) != 0 ? params.volumeMax.x : params.volumeMin.x,
                                 (c & 2) != 0 ? params.volumeMax.y : params.volumeMin.y,
                                 (c & 4) != 0 ? params.volumeMax.z : params.volumeMin.z);
        const float a = dot(corner, u);
        const float b = dot(corner, w);
        r = vec4(min(r.x, a), min(r.y, b), max(r.z, a), max(r.w, b));
    }
    return r;
}

// Photon `index` (cell index % N, index / N of the N×N grid) of directional light l, placed
// where its jittered ray enters the box. relativeThreshold sets flux.w, the flux below which the
// photon is dropped, relative to the photon's largest initial channel. A photon whose ray misses
// the box comes back EK_PHOTON_INACTIVE with zero flux. Other light types are not generated yet:
// they come back inactive too.
GpuPhoton generateDirectionalPhoton(int l, int photonsPerSide, int index, uint seed, uint frame,
                                    float relativeThreshold) {
    GpuPhoton p;
    p.position = vec4(0.0f, 0.0f, 0.0f, float(EK_PHOTON_INACTIVE));
    p.direction = vec4(0.0f);
    p.flux = vec4(0.0f);
    const GpuLight light = params.lights[l];
    if (int(light.position.w) != EK_LIGHT_DIRECTIONAL) return p;
    const vec3 d = normalize(vec3(light.direction));
    vec3 u;
    vec3 w;
    lightPlaneBasis(d, u, w);
    const vec4 rect = lightPlaneBounds(u, w);
    const float cellU = (rect.z - rect.x) / float(photonsPerSide);
    const float cellW = (rect.w - rect.y) / float(photonsPerSide);
    const int i = index % photonsPerSide;
    const int j = index / photonsPerSide;
    const float ju = hashToUnit(photonHash(seed, frame, uint(l), uint(index), 0u));
    const float jw = hashToUnit(photonHash(seed, frame, uint(l), uint(index), 1u));
    const float a = rect.x + (float(i) + ju) * cellU;
    const float b = rect.y + (float(j) + jw) * cellW;
    // Start one box diagonal before the box's centre along d: outside the box, whatever d is.
    const vec3 centre = 0.5f * (vec3(params.volumeMin) + vec3(params.volumeMax));
    const float diagonal = length(vec3(params.volumeMax) - vec3(params.volumeMin));
    const vec3 origin = centre - diagonal * d + (a - dot(centre, u)) * u + (b - dot(centre, w)) * w;
    const vec2 span = intersectVolume(origin, d);
    if (!(span.x < span.y)) return p;
    const vec3 entry = origin + span.x * d;
    // No refraction at the box's faces: the box is meant to be surrounded by n = 1 (the index
    // field is zero at its rim), so the photon enters along d with v = n·d.
    const float n = sampleVolume(EK_GRADIENT_SLOT, worldToVolumeIndex(entry)).w;
    const vec3 flux = vec3(light.radiance) * (cellU * cellW);
    p.position = vec4(entry, float(EK_PHOTON_ACTIVE));
    p.direction = vec4(n * d, 0.0f);
    p.flux = vec4(flux, relativeThreshold * max(flux.x, max(flux.y, flux.z)));
    return p;
}

// ∫ e^(−κt) dt over [0, s]: (1 − e^(−κs)) / κ, and its series as κs → 0 where that cancels.
float photonDecayIntegral(float kappa, float s) {
    return kappa * s > 1e-4f ? (1.0f - exp(-kappa * s)) / kappa : s * (1.0f - 0.5f * kappa * s);
}

// Deposits the segment a → b (world), of length s and unit direction dir, carrying flux0 at a and
// decaying with constant extinction kappa: each voxel the segment crosses receives the exact
// ∫ flux dt over its piece (3D DDA, Amanatides and Woo 1987), and that amount's luminance times
// dir. Pieces outside the box are skipped.
void depositSegment(vec3 a, vec3 b, float s, vec3 dir, vec3 flux0, vec3 kappa) {
    if (!(s > 0.0f)) return;
    const ivec3 res = volumeResolution();
    const vec3 pa = worldToVolumeIndex(a);
    const vec3 d = worldToVolumeIndex(b) - pa;  // index-space displacement over t ∈ [0, 1]
    ivec3 voxel = ivec3(floor(pa));
    ivec3 stepDir = ivec3(0);
    vec3 tMax = vec3(2.0f);  // past the segment's end: never crossed
    vec3 tDelta = vec3(0.0f);
    for (int k = 0; k < 3; ++k) {
        if (d[k] > 0.0f) {
            stepDir[k] = 1;
            tDelta[k] = 1.0f / d[k];
            tMax[k] = (float(voxel[k] + 1) - pa[k]) * tDelta[k];
        } else if (d[k] < 0.0f) {
            stepDir[k] = -1;
            tDelta[k] = -1.0f / d[k];
            tMax[k] = (pa[k] - float(voxel[k])) * tDelta[k];
        }
    }
    // Every crossing moves one axis by one voxel, so the walk ends within this many pieces.
    const ivec3 span = abs(ivec3(floor(pa + d)) - voxel);
    const int pieces = span.x + span.y + span.z + 1;
    float t = 0.0f;
    for (int i = 0; i < pieces; ++i) {
        const float tNext = min(min(min(tMax.x, tMax.y), tMax.z), 1.0f);
        if (tNext > t && all(greaterThanEqual(voxel, ivec3(0))) && all(lessThan(voxel, res))) {
            const float t0 = t * s;
            const float len = (tNext - t) * s;
            const vec3 fluxLength =
                flux0 * exp(-kappa * t0) *
                vec3(photonDecayIntegral(kappa.x, len), photonDecayIntegral(kappa.y, len),
                     photonDecayIntegral(kappa.z, len));
            // Rec. 709 luminance: one scalar weight per piece for the mean direction.
            const float lum = dot(fluxLength, vec3(0.2126f, 0.7152f, 0.0722f));
            depositVoxel(voxel, fluxLength, lum * dir);
        }
        if (tNext >= 1.0f) break;
        t = tNext;
        if (tMax.x <= tMax.y && tMax.x <= tMax.z) {
            voxel.x += stepDir.x;
            tMax.x += tDelta.x;
        } else if (tMax.y <= tMax.z) {
            voxel.y += stepDir.y;
            tMax.y += tDelta.y;
        } else {
            voxel.z += stepDir.z;
            tMax.z += tDelta.z;
        }
    }
}

// Distance along unit world direction dir from world point x to the boundary of the octree leaf
// containing it, and that leaf's Δs_max. The leaf is looked up a hair ahead of x, so a photon
// sitting on a node face (where the last step ended) sees the node it enters, not the one it
// leaves.
float octreeLeafDistance(vec3 x, vec3 dir, EK_OUT(float) maxStep) {
    const ivec3 res = volumeResolution();
    const vec3 h = volumeVoxelSize();
    const vec3 dirIndex = dir / h;  // index-space change per unit of world length
    const vec3 p = worldToVolumeIndex(x);
    const ivec3 voxel =
        clamp(ivec3(floor(p + 1e-3f * normalize(dirIndex))), ivec3(0), res - ivec3(1));
    const vec4 leaf = fetchOctree(voxel);
    maxStep = leaf.y;
    const int size = 1 << int(leaf.x);
    const ivec3 lo = (voxel / ivec3(size)) * ivec3(size);
    const ivec3 hi = min(lo + ivec3(size), res);
    float t = 3.0e38f;
    for (int k = 0; k < 3; ++k) {
        if (dirIndex[k] > 0.0f) t = min(t, (float(hi[k]) - p[k]) / dirIndex[k]);
        if (dirIndex[k] < 0.0f) t = min(t, (float(lo[k]) - p[k]) / dirIndex[k]);
    }
    return max(t, 0.0f);
}

// One adaptive step of an active photon (§1 step 5): Δs = clamp(Δs_octree, minStep, Δs_max), with
// Δs_max winning where the two conflict (it is the accuracy the octree asks for there);
// x += (Δs/n) v, v += Δs ∇n (rayStep's update, n and ∇n at x); the flux decays by e^(−κ|Δx|)
// with κ at the segment's midpoint, and the segment is deposited. A segment that leaves the box
// is cut at the face and the photon escapes. extinguished gets the flux the step lost. Returns
// the photon's new state (EK_PHOTON_*).
int photonStep(EK_INOUT(GpuPhoton) photon, float minStep, EK_INOUT(vec3) extinguished) {
    const vec3 x = vec3(photon.position);
    const vec3 v = vec3(photon.direction);
    const vec4 g = sampleVolume(EK_GRADIENT_SLOT, worldToVolumeIndex(x));
    const float speed = length(v);  // |v| = n on the exact path; drifts a little in the march
    if (!(speed > 1e-6f) || !(g.w > 1e-6f)) return EK_PHOTON_DROPPED;
    const vec3 dir = v / speed;
    float maxStep;
    const float leafDistance = octreeLeafDistance(x, dir, maxStep);
    // The leaf distance is in world length; |Δx| = Δs |v| / n converts it to the ray parameter.
    const float ds = min(max(leafDistance * g.w / speed, minStep), maxStep);
    vec3 next = x + (ds / g.w) * v;
    const vec3 vNext = v + ds * vec3(g);
    const vec3 delta = next - x;
    float s = length(delta);
    if (!(s > 0.0f) || !(s < 3.0e38f)) return EK_PHOTON_DROPPED;
    const vec3 segmentDir = delta / s;
    const float tExit = intersectVolume(x, segmentDir).y;
    const bool leaves = tExit <= s;
    if (leaves) {
        s = max(tExit, 0.0f);
        next = x + segmentDir * s;
    }
    const vec3 flux = vec3(photon.flux);
    const vec3 kappa = extinctionAt(worldToVolumeIndex(0.5f * (x + next)));
    depositSegment(x, next, s, segmentDir, flux, kappa);
    const vec3 fluxNext = flux * exp(-kappa * s);
    extinguished += flux - fluxNext;
    photon.position = vec4(next, photon.position.w);
    photon.direction = vec4(vNext, photon.direction.w + 1.0f);
    photon.flux = vec4(fluxNext, photon.flux.w);
    if (leaves) return EK_PHOTON_ESCAPED;
    if (any(isnan(vNext)) || any(isinf(vNext))) return EK_PHOTON_DROPPED;  // a degenerate medium
    if (max(fluxNext.x, max(fluxNext.y, fluxNext.z)) < photon.flux.w) return EK_PHOTON_DROPPED;
    return EK_PHOTON_ACTIVE;
}

// Marches a photon until it escapes, is dropped, or has taken maxSteps steps (EK_PHOTON_CUT);
// the state is written to position.w. extinguished gets the flux lost on the way.
void tracePhoton(EK_INOUT(GpuPhoton) photon, float minStep, int maxSteps,
                 EK_INOUT(vec3) extinguished) {
    if (int(photon.position.w) != EK_PHOTON_ACTIVE) return;
    int state = EK_PHOTON_ACTIVE;
    for (int i = 0; i < maxSteps && state == EK_PHOTON_ACTIVE; ++i)
        state = photonStep(photon, minStep, extinguished);
    if (state == EK_PHOTON_ACTIVE) state = EK_PHOTON_CUT;
    photon.position.w = float(state);
}

#endif
