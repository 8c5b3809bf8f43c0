// Eikonal wavefront tracing (Ihrke et al. 2007, docs/methods.md `wavefront`), the same on the
// GPU and in the CPU twin (render/transport/wavefront/wavefront_tracing_cpu.cpp).
//
// A light's wavefront is a mesh of quadrilateral patches, each with its own four corner
// particles (patches are independent, as in the paper's GPU version). Every particle advances by
// the same optical time step Δt (t = optical path length, dt = n ds) along the eikonal system
//     dx/dt = v / (n |v|),   dv/dt = ∇n / n     (v = n dx/ds),
// so all particles stay on one wavefront (a surface of equal optical path from the light). The
// paper's eqs. 12-13 write dx/dt = v / n², the same where |v| = n as on the exact path; but n and
// ∇n come from a grid, sampled apart, and are not each other's derivative, so |v| drifts from n
// where n changes fast, and with v / n² the drift scales the step's length and each step's turn
// (2 % more bending through a 6-voxel GRIN lens, its focus 2 % short). With v / (n |v|) the
// position moves at 1/n along v whatever |v|, and v gains ∫∇n ds exactly, as the ray equation
// d/ds(n dx/ds) = ∇n says (tests/render/test_wavefront.cpp, the converging lens).
//
// Intensity law. A patch carries power Φ = E·A (irradiance × area). Geometric optics conserves
// power in a tube of rays, so Φ changes only by extinction, Φ(t) = Φ(0)·exp(−∫κ ds), and the
// irradiance E(t) = Φ(t)/A(t) = E(0)·A(0)/A(t)·exp(−∫κ ds) is the paper's eqs. 15-16
// (∫σ_t/n dt = ∫κ ds). Carrying Φ instead of E keeps a patch finite where A → 0 at a caustic.
//
// Surfaces. Where a patch's centroid crosses the sharp surface of a material marked `fresnel`
// (fresnel.h finds it), the power that goes on is scaled by the Fresnel transmittance 1 − R; the
// reflected R is counted apart and not followed (eq. 5's T(t), the paper's product of the
// transmission factors met along the way).
//
// Deposits. Each step deposits the patch's power × the length of chords through it inside the
// box into the voxels they cross (photons.h depositSegment: flux·length, the output contract's
// fluence units, with the luminance-weighted direction): the paper deposits at patch midpoints
// (one chord) after splitting patches wider than a voxel; depositPatchStep takes a grid of
// chords over the patch, so its power is spread over the voxels it covers. Patches wider than
// the split length (one voxel by default) are split into four.
//
// Two parts, as photons.h: GpuWavefrontPatch under its own guard (EK_WAVEFRONT_TYPES_ONLY for the
// struct alone), then the functions, which need photons.h (and what it needs) included before.

#ifndef EIKON_SHARED_WAVEFRONT_TYPES_H
#define EIKON_SHARED_WAVEFRONT_TYPES_H

// GpuWavefrontPatch.state.x: EK_PHOTON_* (photons.h), or:
#define EK_PATCH_REMOVED 6  // crossed a caustic with at_caustic = remove: its power is dropped
#define EK_PATCH_SPLIT 7    // replaced by its four children (its power lives on in them)
// Still wider than the split length at the level cap: the wavefront has torn there (its corners
// follow rays that part for good, as across a refracting object's silhouette), and splitting
// again would not mend it. It ends; its power counts as dropped.
#define EK_PATCH_TORN 8
// A round's outcome only (patchRound), never a final state: the patch is wider than the split
// length and asks to be split between rounds, where the patch budget grants or refuses it.
#define EK_PATCH_WANTS_SPLIT 9

// What happens to a patch whose orientation flips (it passed through a caustic).
#define EK_WAVEFRONT_KEEP 0    // it goes on, inverted: power is conserved through the focus
#define EK_WAVEFRONT_REMOVE 1  // the paper's rule: it is removed and its power counted as dropped

// Integrators of the eikonal system (a subset of ray_equation.h's, in t instead of τ).
#define EK_WAVEFRONT_EULER 0
#define EK_WAVEFRONT_MIDPOINT 1
#define EK_WAVEFRONT_RK4 2

// One patch of a wavefront; only vec4 members, so std430 and C++ offsets agree. Corners in grid
// order (0,0), (1,0), (1,1), (0,1) of the patch's own parameter square.
struct GpuWavefrontPatch {
    vec4 corner[4];      // xyz: world position; w: 0
    vec4 velocity[4];    // xyz: v = n dx/ds of the corner's particle; w: 0
    vec4 power;          // rgb: Φ, the power the patch carries; w: Φ below which it is dropped
    vec4 state;          // x: EK_PHOTON_* or EK_PATCH_*; y: steps taken; z: split level;
                         // w: the sign its orientation had when it started (±1)
    vec4 surface;        // its centroid's walk across surfaces (fresnel.h surfaceWalkStart)
    vec4 surfaceNormal;  // xyz: the ∇n met in the surface crossing under way; w: 0
};

// What a patch has lost so far, carried between rounds beside it so that its account adds the
// same float sums as one uninterrupted trace; zero in a new patch (a child starts its own) but for
// its root.
struct GpuWavefrontTally {
    vec4 lost;       // xyz: power extinguished; w: 1 once the budget refused it a split
    vec4 reflected;  // xyz: power reflected at surfaces (Fresnel), not followed; w: 0
    ivec4 root;      // x: the starting patch it descends from (its index in the pass's first
                     // list, shared/wavefront_rounds.h); yzw: 0
};

// A patch and its tally: one entry of a round's list on the GPU (shared/wavefront_rounds.h).
struct GpuWavefrontEntry {
    GpuWavefrontPatch piece;  // ("patch" is a GLSL keyword)
    GpuWavefrontTally tally;
};

#endif

#ifndef EK_WAVEFRONT_TYPES_ONLY

#include "fresnel.h"

bool insideVolumeBox(vec3 x) {
    return all(greaterThanEqual(x, vec3(params.volumeMin))) &&
           all(lessThanEqual(x, vec3(params.volumeMax)));
}

// ∇n (xyz) and n (w) at world point x. Outside the box n keeps the value at its rim and ∇n is
// zero, so particles there travel straight at the rim's speed and stay on the wavefront (the
// box is meant to be surrounded by n = 1, as for photons).
vec4 wavefrontIndexAt(vec3 x) {
    const vec4 g = sampleVolume(EK_GRADIENT_SLOT, worldToVolumeIndex(x));
    if (insideVolumeBox(x)) return g;
    return vec4(0.0f, 0.0f, 0.0f, g.w);
}

// d/dt of (x, v) at (x, v): the eikonal system above. False where n ≤ 10⁻⁶ or |v| ≤ 10⁻⁶ (a
// degenerate medium).
bool wavefrontDerivative(vec3 x, vec3 v, EK_OUT(vec3) dx, EK_OUT(vec3) dv) {
    const vec4 g = wavefrontIndexAt(x);
    dx = vec3(0.0f);
    dv = vec3(0.0f);
    if (!(g.w > 1e-6f)) return false;
    const float speed = length(v);
    if (!(speed > 1e-6f)) return false;
    dx = v / (g.w * speed);
    dv = vec3(g) / g.w;
    return true;
}

// One step of optical time dt for one particle with `integrator` (EK_WAVEFRONT_*). Returns false
// where the medium is degenerate; x and v are then left as they were.
bool wavefrontAdvance(int integrator, EK_INOUT(vec3) x, EK_INOUT(vec3) v, float dt) {
    vec3 k1x;
    vec3 k1v;
    if (!wavefrontDerivative(x, v, k1x, k1v)) return false;
    if (integrator == EK_WAVEFRONT_EULER) {
        x = x + dt * k1x;
        v = v + dt * k1v;
        return true;
    }
    vec3 k2x;
    vec3 k2v;
    if (!wavefrontDerivative(x + (0.5f * dt) * k1x, v + (0.5f * dt) * k1v, k2x, k2v)) return false;
    if (integrator == EK_WAVEFRONT_MIDPOINT) {
        x = x + dt * k2x;
        v = v + dt * k2v;
        return true;
    }
    vec3 k3x;
    vec3 k3v;
    if (!wavefrontDerivative(x + (0.5f * dt) * k2x, v + (0.5f * dt) * k2v, k3x, k3v)) return false;
    vec3 k4x;
    vec3 k4v;
    if (!wavefrontDerivative(x + dt * k3x, v + dt * k3v, k4x, k4v)) return false;
    const float sixth = dt * (1.0f / 6.0f);
    x = x + sixth * (k1x + 2.0f * k2x + 2.0f * k3x + k4x);
    v = v + sixth * (k1v + 2.0f * k2v + 2.0f * k3v + k4v);
    return true;
}

vec3 patchCentroid(GpuWavefrontPatch p) {
    return 0.25f * (vec3(p.corner[0]) + vec3(p.corner[1]) + vec3(p.corner[2]) + vec3(p.corner[3]));
}

// The quadrilateral's vector area: half the cross product of its diagonals (exact for a planar
// quad, the mean of its two triangulations' for a skew one).
vec3 patchVectorArea(GpuWavefrontPatch p) {
    return 0.5f *
           cross(vec3(p.corner[2]) - vec3(p.corner[0]), vec3(p.corner[3]) - vec3(p.corner[1]));
}

float patchArea(GpuWavefrontPatch p) {
    return length(patchVectorArea(p));
}

// The patch's orientation against its direction of travel: positive while its corners run
// counter-clockwise seen from ahead of it, and it changes sign when the patch passes through a
// caustic (its rays cross, so the patch turns inside out).
float patchOrientation(GpuWavefrontPatch p) {
    const vec3 v =
        vec3(p.velocity[0]) + vec3(p.velocity[1]) + vec3(p.velocity[2]) + vec3(p.velocity[3]);
    return dot(patchVectorArea(p), v);
}

// Eq. 16: the irradiance Φ/A (rgb) over the patch.
vec3 patchIrradiance(GpuWavefrontPatch p) {
    const float a = patchArea(p);
    return a > 0.0f ? vec3(p.power) / a : vec3(3.0e38f);
}

// Whether the patch spans more than splitVoxels voxels along some index axis while its centroid
// is inside the box (outside, nothing is deposited and light travels straight: no need).
bool patchNeedsSplit(GpuWavefrontPatch p, float splitVoxels) {
    if (!insideVolumeBox(patchCentroid(p))) return false;
    vec3 lo = worldToVolumeIndex(vec3(p.corner[0]));
    vec3 hi = lo;
    for (int k = 1; k < 4; ++k) {
        const vec3 q = worldToVolumeIndex(vec3(p.corner[k]));
        lo = min(lo, q);
        hi = max(hi, q);
    }
    const vec3 extent = hi - lo;
    return max(extent.x, max(extent.y, extent.z)) > splitVoxels;
}

// The point at (a, b) of the patch's parameter square, bilinear in the corners; v likewise,
// rescaled to |v| = n there (its direction is the corners' blend).
void patchPointAt(GpuWavefrontPatch p, float a, float b, EK_OUT(vec4) x, EK_OUT(vec4) v) {
    const float w0 = (1.0f - a) * (1.0f - b);
    const float w1 = a * (1.0f - b);
    const float w2 = a * b;
    const float w3 = (1.0f - a) * b;
    const vec3 xp = w0 * vec3(p.corner[0]) + w1 * vec3(p.corner[1]) + w2 * vec3(p.corner[2]) +
                    w3 * vec3(p.corner[3]);
    const vec3 vp = w0 * vec3(p.velocity[0]) + w1 * vec3(p.velocity[1]) + w2 * vec3(p.velocity[2]) +
                    w3 * vec3(p.velocity[3]);
    const float speed = length(vp);
    const float n = wavefrontIndexAt(xp).w;
    x = vec4(xp, 0.0f);
    v = vec4(speed > 0.0f ? (n / speed) * vp : vp, 0.0f);
}

// Quarter k (0..3: the parameter square's quarters in corner order) of the patch, before its
// power is assigned: corners at the parent's corners, edge midpoints and centre.
GpuWavefrontPatch patchQuarter(GpuWavefrontPatch p, int k) {
    const float a0 = (k == 1 || k == 2) ? 0.5f : 0.0f;
    const float b0 = (k >= 2) ? 0.5f : 0.0f;
    GpuWavefrontPatch c = p;
    patchPointAt(p, a0, b0, c.corner[0], c.velocity[0]);
    patchPointAt(p, a0 + 0.5f, b0, c.corner[1], c.velocity[1]);
    patchPointAt(p, a0 + 0.5f, b0 + 0.5f, c.corner[2], c.velocity[2]);
    patchPointAt(p, a0, b0 + 0.5f, c.corner[3], c.velocity[3]);
    c.state = vec4(float(EK_PHOTON_ACTIVE), p.state.y, p.state.z + 1.0f, p.state.w);
    return c;
}

// Child k of a patch split in four: its quarter, carrying the parent's power (and drop
// threshold) in proportion to its area among the four quarters' areas; the last child takes what
// the first three leave, so the four sum to the parent's power.
GpuWavefrontPatch patchChild(GpuWavefrontPatch p, int k) {
    float areas[4];
    float total = 0.0f;
    for (int q = 0; q < 4; ++q) {
        areas[q] = patchArea(patchQuarter(p, q));
        total += areas[q];
    }
    GpuWavefrontPatch c = patchQuarter(p, k);
    vec4 given = vec4(0.0f);
    for (int q = 0; q < k; ++q) given += p.power * (total > 0.0f ? areas[q] / total : 0.25f);
    c.power = k == 3 ? p.power - given : p.power * (total > 0.0f ? areas[k] / total : 0.25f);
    c.power = max(c.power, vec4(0.0f));
    // The walk across surfaces goes on from the child's own centroid (a crossing under way stays
    // under way); only for the child kept, not the quarters measured for their areas.
    const vec3 centre = patchCentroid(c);
    c.surface.x = surfaceIndexAt(worldToVolumeIndex(centre));
    c.surface.z = wavefrontIndexAt(centre).w;
    return c;
}

// A patch with corners x_k moving along unit directions d_k, at the same optical time, with
// v = n·d_k (n read where each starts), carrying `power` (rgb); inactive with no power when
// `hits` is false (its centroid's ray misses the box) or it carries nothing.
GpuWavefrontPatch startPatch(vec3 x0, vec3 x1, vec3 x2, vec3 x3, vec3 d0, vec3 d1, vec3 d2, vec3 d3,
                             vec3 power, bool hits, float relativeThreshold) {
    GpuWavefrontPatch p;
    p.corner[0] = vec4(x0, 0.0f);
    p.corner[1] = vec4(x1, 0.0f);
    p.corner[2] = vec4(x2, 0.0f);
    p.corner[3] = vec4(x3, 0.0f);
    p.velocity[0] = vec4(wavefrontIndexAt(x0).w * d0, 0.0f);
    p.velocity[1] = vec4(wavefrontIndexAt(x1).w * d1, 0.0f);
    p.velocity[2] = vec4(wavefrontIndexAt(x2).w * d2, 0.0f);
    p.velocity[3] = vec4(wavefrontIndexAt(x3).w * d3, 0.0f);
    const float largest = max(power.x, max(power.y, power.z));
    const bool lit = hits && largest > 0.0f;
    p.power = lit ? vec4(power, relativeThreshold * largest) : vec4(0.0f);
    const float orientation = patchOrientation(p);
    p.state = vec4(float(lit ? EK_PHOTON_ACTIVE : EK_PHOTON_INACTIVE), 0.0f, 0.0f,
                   orientation < 0.0f ? -1.0f : 1.0f);
    const vec3 centre = patchCentroid(p);
    p.surface =
        surfaceWalkStart(wavefrontIndexAt(centre).w, surfaceIndexAt(worldToVolumeIndex(centre)));
    p.surfaceNormal = vec4(0.0f);
    return p;
}

// Patch `index` (column index % N, row index / N) of directional light l: the grid cell of the
// rectangle the box projects to on the plane perpendicular to the light (photons.h), its corners
// on that plane where it first touches the box, all at t = 0, power E × the cell's area.
GpuWavefrontPatch generateDirectionalPatch(int l, int perSide, int index, float relativeThreshold) {
    const GpuLight light = params.lights[l];
    const vec3 d = normalize(vec3(light.direction));
    vec3 u;
    vec3 w;
    lightPlaneBasis(d, u, w);
    const vec4 rect = lightPlaneBounds(u, w);
    float start = 3.0e38f;
    for (int c = 0; c < 8; ++c) start = min(start, dot(volumeCorner(c), d));
    const float cellU = (rect.z - rect.x) / float(perSide);
    const float cellW = (rect.w - rect.y) / float(perSide);
    const float i = float(index % perSide);
    const float j = float(index / perSide);
    const vec3 base = start * d + (rect.x + i * cellU) * u + (rect.y + j * cellW) * w;
    const vec3 x0 = base;
    const vec3 x1 = base + cellU * u;
    const vec3 x2 = base + cellU * u + cellW * w;
    const vec3 x3 = base + cellW * w;
    const vec3 centre = 0.25f * (x0 + x1 + x2 + x3);
    const vec2 span = intersectVolume(centre, d);
    return startPatch(x0, x1, x2, x3, d, d, d, d, vec3(light.radiance) * (cellU * cellW),
                      span.x < span.y, relativeThreshold);
}

// The solid angle of the rectangle [s0, s1] × [t0, t1] on the plane at unit distance: exact
// (the corners' signed sum of atan(st/√(1 + s² + t²))).
float unitPlaneSolidAngle(vec4 r) {
    const float a = atan(r.z * r.w / sqrt(1.0f + r.z * r.z + r.w * r.w));
    const float b = atan(r.x * r.w / sqrt(1.0f + r.x * r.x + r.w * r.w));
    const float c = atan(r.z * r.y / sqrt(1.0f + r.z * r.z + r.y * r.y));
    const float e = atan(r.x * r.y / sqrt(1.0f + r.x * r.x + r.y * r.y));
    return a - b - c + e;
}

// Patch `index` of point or spot light l laid out as `grid` (photonGrid, photonGridFaces · N²
// patches): the cell of its face's grid at unit distance, its corners on the sphere of radius
// startRadius around the light (the distance to the box, so all start outside it at equal time,
// or a small radius inside it), power I × the cell's exact solid angle × the spot falloff
// toward its centre.
GpuWavefrontPatch generatePointPatch(int l, int grid, int perSide, int index, float startRadius,
                                     float relativeThreshold) {
    const GpuLight light = params.lights[l];
    int cell = index;
    vec3 a;
    vec3 u;
    vec3 w;
    const vec4 rect = lightGridFace(light, grid, perSide * perSide, cell, a, u, w);
    const float cellU = (rect.z - rect.x) / float(perSide);
    const float cellW = (rect.w - rect.y) / float(perSide);
    const float s0 = rect.x + float(cell % perSide) * cellU;
    const float t0 = rect.y + float(cell / perSide) * cellW;
    const vec4 r = vec4(s0, t0, s0 + cellU, t0 + cellW);
    const vec3 d0 = normalize(a + r.x * u + r.y * w);
    const vec3 d1 = normalize(a + r.z * u + r.y * w);
    const vec3 d2 = normalize(a + r.z * u + r.w * w);
    const vec3 d3 = normalize(a + r.x * u + r.w * w);
    const vec3 dc = normalize(a + (0.5f * (r.x + r.z)) * u + (0.5f * (r.y + r.w)) * w);
    float solidAngle = unitPlaneSolidAngle(r);
    if (lightType(light) == EK_LIGHT_SPOT) solidAngle *= spotFalloff(light, dc);
    const vec3 p = vec3(light.position);
    const vec2 span = intersectVolume(p, dc);
    return startPatch(p + startRadius * d0, p + startRadius * d1, p + startRadius * d2,
                      p + startRadius * d3, d0, d1, d2, d3, vec3(light.radiance) * solidAngle,
                      span.x < span.y, relativeThreshold);
}

// Where point light patches start: the distance from the light to the box, or a small radius
// (a quarter of the smallest voxel edge) for a light inside it.
float pointPatchStartRadius(int l) {
    const vec3 p = vec3(params.lights[l].position);
    const float outside = length(p - clamp(p, vec3(params.volumeMin), vec3(params.volumeMax)));
    const vec3 h = volumeVoxelSize();
    return max(outside, 0.25f * min(h.x, min(h.y, h.z)));
}

// Patch `index` of light l laid out as `grid` (photonGrid(l)).
GpuWavefrontPatch generatePatch(int l, int grid, int perSide, int index, float relativeThreshold) {
    if (grid == EK_PHOTON_GRID_PARALLEL)
        return generateDirectionalPatch(l, perSide, index, relativeThreshold);
    return generatePointPatch(l, grid, perSide, index, pointPatchStartRadius(l), relativeThreshold);
}

// The patch's corners blended bilinearly at (a, b) of its parameter square.
vec3 patchBilinear(GpuWavefrontPatch p, float a, float b) {
    return (1.0f - a) * (1.0f - b) * vec3(p.corner[0]) + a * (1.0f - b) * vec3(p.corner[1]) +
           a * b * vec3(p.corner[2]) + (1.0f - a) * b * vec3(p.corner[3]);
}

// Whether every corner is outside the box with the box behind it: outside, particles travel
// straight, so none will enter again. (Corners, not the centroid: after a caustic a patch can
// grow about a centroid that barely moves, and would linger.) The patch's interior is taken to
// leave with its corners.
bool patchHasLeft(GpuWavefrontPatch p) {
    for (int k = 0; k < 4; ++k) {
        const vec3 x = vec3(p.corner[k]);
        if (insideVolumeBox(x)) return false;
        const vec3 v = vec3(p.velocity[k]);
        const float speed = length(v);
        if (!(speed > 0.0f)) continue;
        const vec2 ahead = intersectVolume(x, v / speed);
        if (ahead.x < ahead.y) return false;
    }
    return true;
}

// Deposits one step of a patch, from `before` to `after`, carrying `power` (its value at the
// step's start): samples × samples chords through the centres of a samples × samples grid over
// the patch's parameter square, each with 1/samples² of the power, cut to the box and to
// `fraction` of their length (a receiver's hit), decaying with the extinction at their own
// midpoint. One sample is the paper's patch midpoint; more spread the patch's power over the
// voxels it covers, so a wavefront whose patches are not voxel-aligned does not alias into
// stripes (BENCHMARKS.md measures it).
void depositPatchStep(GpuWavefrontPatch before, GpuWavefrontPatch after, int samples, vec3 power,
                      float fraction) {
    const float share = 1.0f / float(samples * samples);
    for (int j = 0; j < samples; ++j)
        for (int i = 0; i < samples; ++i) {
            const float a = (float(i) + 0.5f) / float(samples);
            const float b = (float(j) + 0.5f) / float(samples);
            const vec3 x0 = patchBilinear(before, a, b);
            const vec3 chord = fraction * (patchBilinear(after, a, b) - x0);
            const float s = length(chord);
            if (!(s > 0.0f) || !(s < 3.0e38f)) continue;
            const vec3 dir = chord / s;
            const vec2 span = intersectVolume(x0, dir);
            const float t0 = span.x;
            const float t1 = min(span.y, s);
            if (!(t0 < t1)) continue;
            const vec3 kappa = extinctionAt(worldToVolumeIndex(x0 + (0.5f * (t0 + t1)) * dir));
            depositSegment(x0 + t0 * dir, x0 + t1 * dir, t1 - t0, dir, share * power, kappa);
        }
}

// One time step Δt of an active patch: its four particles advance (wavefrontAdvance), the step
// is deposited (depositPatchStep, `samples` per side), and the patch's power decays by e^(−κ s)
// over its centroid's chord inside the box (κ at that chord's midpoint); extinguished gets the
// power lost. With surfaceSlope > 0 (n_surface changing faster than that per voxel marks a
// surface, fresnel.h) the power is then scaled by the Fresnel transmittance where the centroid
// has crossed a surface, and reflected gets the rest. A centroid chord that crosses a receiver
// stops the patch there. Returns the new state: EK_PHOTON_ESCAPED once the patch has left the box
// (patchHasLeft) or its centroid moves away outside it, EK_PATCH_REMOVED if the orientation flipped
// and atCaustic is EK_WAVEFRONT_REMOVE (with EK_WAVEFRONT_KEEP the patch goes on and state.w takes
// the new sign), EK_PHOTON_DROPPED below the threshold or in a degenerate medium.
int patchStep(EK_INOUT(GpuWavefrontPatch) p, float dt, int integrator, int atCaustic, int samples,
              float surfaceSlope, EK_INOUT(vec3) extinguished, EK_INOUT(vec3) reflected) {
    const GpuWavefrontPatch before = p;
    const vec3 c0 = patchCentroid(p);
    for (int k = 0; k < 4; ++k) {
        vec3 x = vec3(p.corner[k]);
        vec3 v = vec3(p.velocity[k]);
        if (!wavefrontAdvance(integrator, x, v, dt)) return EK_PHOTON_DROPPED;
        if (any(isnan(x)) || any(isinf(x)) || any(isnan(v)) || any(isinf(v)))
            return EK_PHOTON_DROPPED;
        p.corner[k] = vec4(x, 0.0f);
        p.velocity[k] = vec4(v, 0.0f);
    }
    p.state.y += 1.0f;
    vec3 c1 = patchCentroid(p);
    float s = length(c1 - c0);
    if (!(s < 3.0e38f)) return EK_PHOTON_DROPPED;
    const vec3 dir = s > 0.0f ? (c1 - c0) / s : vec3(0.0f, 0.0f, 1.0f);
    // A receiver in the centroid's way stops the patch on its plane.
    float tHit = 1.0f;
    bool front;
    const int receiver = s > 0.0f ? receiverCrossing(c0, c1, tHit, front) : -1;
    if (receiver >= 0) {
        c1 = receiverHitPoint(receiver, c0, c1, tHit);
        s *= tHit;
    } else {
        tHit = 1.0f;
    }
    vec3 power = vec3(p.power);
    depositPatchStep(before, p, samples, power, tHit);
    // The patch's own account: extinction over its centroid's chord inside the box.
    const vec2 span = intersectVolume(c0, dir);
    const float a = span.x;
    const float b = min(span.y, s);
    if (s > 0.0f && a < b) {
        const vec3 kappa = extinctionAt(worldToVolumeIndex(c0 + (0.5f * (a + b)) * dir));
        const vec3 next = power * channelDecay(kappa, b - a);
        extinguished += power - next;
        power = next;
    }
    // Outside the box light goes straight (wavefrontIndexAt): no surface there either.
    if (surfaceSlope > 0.0f && s > 0.0f && insideVolumeBox(c1)) {
        const vec3 v =
            vec3(p.velocity[0]) + vec3(p.velocity[1]) + vec3(p.velocity[2]) + vec3(p.velocity[3]);
        const vec3 h = volumeVoxelSize();
        const float perVoxel = surfaceSlope / min(h.x, min(h.y, h.z));  // per scene unit
        const float transmitted = surfaceWalkStep(p.surface, p.surfaceNormal, wavefrontIndexAt(c1),
                                                  surfaceIndexAt(worldToVolumeIndex(c1)), 0.25f * v,
                                                  perVoxel * s, perVoxel);
        if (transmitted < 1.0f) {
            reflected += power * (1.0f - transmitted);
            power *= transmitted;
        }
    }
    p.power = vec4(power, p.power.w);
    if (receiver >= 0) {
        if (front && receiverKind(params.receivers[receiver]) == EK_RECEIVER_PLANE)
            depositOnReceiver(receiver, c1, power);
        return EK_PHOTON_RECEIVED;
    }
    if (patchHasLeft(p)) return EK_PHOTON_ESCAPED;
    if (!insideVolumeBox(c1) && s > 0.0f) {
        const vec2 ahead = intersectVolume(c1, dir);
        if (!(ahead.x < ahead.y)) return EK_PHOTON_ESCAPED;
    }
    const float orientation = patchOrientation(p);
    if (orientation * p.state.w < 0.0f) {
        if (atCaustic == EK_WAVEFRONT_REMOVE) return EK_PATCH_REMOVED;
        p.state.w = -p.state.w;
    }
    if (max(power.x, max(power.y, power.z)) < p.power.w) return EK_PHOTON_DROPPED;
    return EK_PHOTON_ACTIVE;
}

// One round of a patch's trace, the loop both backends run on every patch of a round's list
// (render/transport/wavefront/wavefront_tracing_cpu.cpp, shaders/wavefront_trace.comp): steps
// until the patch ends, asks to be split, or has taken roundSteps steps. Before each step, as a
// trace without rounds would: past maxSteps the patch is cut; wider than splitVoxels it tears at
// maxLevel and otherwise asks for a split (EK_PATCH_WANTS_SPLIT, 0 steps of that request), unless
// the budget refused it one before (tally.lost.w), when it goes on unsplit for good. Returns
// EK_PHOTON_ACTIVE when the round's steps ran out, EK_PATCH_WANTS_SPLIT, or the state it ended
// in; steps and crossings (orientation flips, removals) count this round's.
int patchRound(EK_INOUT(GpuWavefrontPatch) p, EK_INOUT(GpuWavefrontTally) tally, int roundSteps,
               int maxSteps, float splitVoxels, int maxLevel, float dt, int integrator,
               int atCaustic, int samples, float surfaceSlope, EK_INOUT(int) steps,
               EK_INOUT(int) crossings) {
    vec3 lost = vec3(tally.lost);
    vec3 reflected = vec3(tally.reflected);
    const bool refused = tally.lost.w != 0.0f;
    int state = EK_PHOTON_ACTIVE;
    for (int i = 0; i < roundSteps && state == EK_PHOTON_ACTIVE; ++i) {
        if (int(p.state.y) >= maxSteps) {
            state = EK_PHOTON_CUT;
            break;
        }
        if (!refused && patchNeedsSplit(p, splitVoxels)) {
            state = int(p.state.z) >= maxLevel ? EK_PATCH_TORN : EK_PATCH_WANTS_SPLIT;
            break;
        }
        const float sign = p.state.w;
        state = patchStep(p, dt, integrator, atCaustic, samples, surfaceSlope, lost, reflected);
        steps += 1;
        if (p.state.w != sign || state == EK_PATCH_REMOVED) crossings += 1;
    }
    tally.lost = vec4(lost, tally.lost.w);
    tally.reflected = vec4(reflected, tally.reflected.w);
    return state;
}

#endif
