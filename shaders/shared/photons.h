// Photon tracing, steps 4 and 5 of Sun et al. 2008 (docs/methods.md, `photons`), the same on the
// GPU and in the CPU twin (render/transport/photons/photon_tracing_cpu.cpp).
//
// Two parts. The GpuPhoton struct sits under its own include guard, so that C++ can include this
// file once at namespace scope with EK_PHOTON_TYPES_ONLY defined (for the struct alone) and again
// inside a kernel struct body (for the functions, which then see the kernel's members); GLSL
// includes it once at file scope and gets both.
//
// Needs from the includer for the functions: sampling.h, optics.h and ray_equation.h (params,
// fetchVolume with the ∇n volume at EK_GRADIENT_SLOT), and
//   vec4 fetchOctree(ivec3 voxel)   the octree volume (render/refraction_volume.h): x = level,
//                                   y = Δs_max in scene units, z, w = n range;
//   void depositVoxel(ivec3 voxel, vec3 fluxLength, vec3 weightedDir)
//                                   adds one segment piece to the radiance volume;
//   void depositReceiverTexel(int index, vec3 flux)
//                                   adds flux (power) to texel `index` of the receiver map
//                                   (receivers.h, which must be included before this file);
//   vec3 photonChannels             the colour channels this trace deposits (1 each; under
//                                   dispersion one pass per channel, that channel's 1 alone:
//                                   render/transport/photons/photon_tracing.h). A photon carries
//                                   all three channels' flux whatever the mask, so it is dropped
//                                   and cut exactly when a photon of one pass would be; only
//                                   what it deposits and leaves in the totals is masked.
//
// Units. A directional light of irradiance E (GpuLight.radiance, power per unit area across the
// beam) sends photons through an N×N grid of cells over the rectangle that the volume box
// projects to on the plane perpendicular to the light; a photon carries flux E × cell area
// (power). Cells whose jittered ray misses the box emit nothing, so the emitted power is
// Σ_hit E·cellArea, whose expectation is E × the box's projected area.
// A point or spot light of radiant intensity I (GpuLight.radiance, power per steradian) sends
// photons from its position through N×N grids on planes at unit distance from it (photonGrid):
// one grid over the box's or the spot cone's projection when the light is well outside the box,
// else the six faces of a cube around it (N² photons per face). A photon carries flux I × its
// cell's solid angle × the spot falloff (power), so the emitted power's expectation is I × the
// solid angle the box subtends (4π·I for a point light inside it), weighted by the falloff for
// a spot; it starts where its ray enters the box, or at the light if that is inside.
// Deposits are flux·length (power × scene units): every voxel a segment crosses receives
// ∫ flux ds over the part of the segment inside it; divided by the voxel's volume that is the
// fluence rate (power per area: E in a clear medium lit by a directional light, I/r² by a point
// light).

#ifndef EIKON_SHARED_PHOTON_TYPES_H
#define EIKON_SHARED_PHOTON_TYPES_H

// GpuPhoton.position.w: where a photon is in its life.
#define EK_PHOTON_INACTIVE 0  // its ray missed the box or carried nothing: it never existed
#define EK_PHOTON_ACTIVE 1
#define EK_PHOTON_ESCAPED 2   // left the box; position and direction are its exit
#define EK_PHOTON_DROPPED 3   // its flux fell below its threshold, or its march went degenerate
#define EK_PHOTON_CUT 4       // still active after the step limit (a trapped path)
#define EK_PHOTON_RECEIVED 5  // stopped on a receiver (receivers.h); position is the hit point

// How a light's photons are laid out (photonGrid): N×N grids of cells, one photon per cell.
#define EK_PHOTON_GRID_NONE 0      // a spot whose cone misses the box: no photons
#define EK_PHOTON_GRID_PARALLEL 1  // directional: one grid over the box's projection
#define EK_PHOTON_GRID_BOX 2       // point or spot: one perspective grid toward the box's centre
#define EK_PHOTON_GRID_SPOT 3      // spot: one perspective grid along the spot's axis
#define EK_PHOTON_GRID_CUBE 4      // point or spot in or beside the box: the six faces of a cube

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

// Corner c (bit 0: x, bit 1: y, bit 2: z at the maximum) of the volume box.
vec3 volumeCorner(int c) {
    return vec3((c & 1) != 0 ? params.volumeMax.x : params.volumeMin.x,
                (c & 2) != 0 ? params.volumeMax.y : params.volumeMin.y,
                (c & 4) != 0 ? params.volumeMax.z : params.volumeMin.z);
}

// The rectangle the box projects to in the light plane: x, y = min (u, w); z, w = max.
vec4 lightPlaneBounds(vec3 u, vec3 w) {
    vec4 r = vec4(3.0e38f, 3.0e38f, -3.0e38f, -3.0e38f);
    for (int c = 0; c < 8; ++c) {
        const vec3 corner = volumeCorner(c);
        const float a = dot(corner, u);
        const float b = dot(corner, w);
        r = vec4(min(r.x, a), min(r.y, b), max(r.z, a), max(r.w, b));
    }
    return r;
}

// The jittered point of cell `cell` (column cell % N, row cell / N) of the N×N grid over rect,
// from photon `index`'s two random numbers (hash dimensions 0 and 1); cellArea gets the area of
// one cell. Jittered (stratified) sampling: one uniform point per cell, so a cell's photon is an
// unbiased estimate of the cell's integral and the grid as a whole has little variance.
vec2 jitteredCellPoint(vec4 rect, int photonsPerSide, int cell, int l, int index, uint seed,
                       uint frame, EK_OUT(float) cellArea) {
    const float cellU = (rect.z - rect.x) / float(photonsPerSide);
    const float cellW = (rect.w - rect.y) / float(photonsPerSide);
    cellArea = cellU * cellW;
    const int i = cell % photonsPerSide;
    const int j = cell / photonsPerSide;
    const float ju = hashToUnit(photonHash(seed, frame, uint(l), uint(index), 0u));
    const float jw = hashToUnit(photonHash(seed, frame, uint(l), uint(index), 1u));
    return vec2(rect.x + (float(i) + ju) * cellU, rect.y + (float(j) + jw) * cellW);
}

// A photon carrying flux from origin along unit d, placed where that ray enters the box (at
// origin itself if that is inside). relativeThreshold sets flux.w, the flux below which the
// photon is dropped, relative to its largest initial channel. A ray that misses the box, or zero
// flux, gives an EK_PHOTON_INACTIVE photon with zero flux: it never existed.
GpuPhoton startPhoton(vec3 origin, vec3 d, vec3 flux, float relativeThreshold) {
    GpuPhoton p;
    p.position = vec4(0.0f, 0.0f, 0.0f, float(EK_PHOTON_INACTIVE));
    p.direction = vec4(0.0f);
    p.flux = vec4(0.0f);
    const float largest = max(flux.x, max(flux.y, flux.z));
    if (!(largest > 0.0f)) return p;
    const vec2 span = intersectVolume(origin, d);
    if (!(span.x < span.y)) return p;
    const vec3 entry = origin + span.x * d;
    // No refraction at the box's faces: the box is meant to be surrounded by n = 1 (the index
    // field is zero at its rim), so the photon enters along d with v = n·d.
    const float n = sampleVolume(EK_GRADIENT_SLOT, worldToVolumeIndex(entry)).w;
    p.position = vec4(entry, float(EK_PHOTON_ACTIVE));
    p.direction = vec4(n * d, 0.0f);
    p.flux = vec4(flux, relativeThreshold * largest);
    return p;
}

// A direction uniform over the solid angle of the cap of versine `versine` (1 − cos of its
// angular radius) around unit d, (u, w) a basis of the plane across d: the direction a sun-like
// disc of uniform radiance sends photon `index`. A point uniform on the unit disc, by rejection
// from the square (hash dimensions 2, 3, then 4, 5, ...; sixteen tries all miss once in 10^10
// photons, which then keeps d), gives the azimuth as (x, y)/r and, since r² is uniform, the
// versine v = versine·r², uniform as a cap's cos θ is. No sine or cosine: +, −, ×, ÷ and sqrt
// round alike in the twin and on llvmpipe (exact_math.glsl), trigonometric built-ins do not.
// sin θ comes from v (√(v(2 − v))), not from cos θ: at a 0.5° disc cos θ = 1 − 1e-5 is too near
// 1 for float to give its sine.
vec3 discDirection(vec3 d, vec3 u, vec3 w, float versine, int l, int index, uint seed, uint frame) {
    for (uint attempt = 0u; attempt < 16u; ++attempt) {
        const uint dimension = 2u + 2u * attempt;
        const float x =
            2.0f * hashToUnit(photonHash(seed, frame, uint(l), uint(index), dimension)) - 1.0f;
        const float y =
            2.0f * hashToUnit(photonHash(seed, frame, uint(l), uint(index), dimension + 1u)) - 1.0f;
        const float r2 = x * x + y * y;
        if (!(r2 < 1.0f) || !(r2 > 0.0f)) continue;
        const float v = versine * r2;
        const float sine = sqrt(v * (2.0f - v));
        const float along = sine / sqrt(r2);
        return normalize((1.0f - v) * d + (along * x) * u + (along * y) * w);
    }
    return d;
}

// Photon `index` (cell index % N, index / N of the N×N grid) of directional light l: a jittered
// ray through the rectangle the box projects to on the plane perpendicular to the light. A light
// with a disc (lightDiscVersine > 0) tilts each photon into its own direction of the disc
// (discDirection) through its point of the plane across d at the box's centre, and widens the
// rectangle to cover the box's projection along every direction of the disc; the photons that
// then miss the box never existed. The flux through the plane per
// area is the light's irradiance either way.
GpuPhoton generateDirectionalPhoton(int l, int photonsPerSide, int index, uint seed, uint frame,
                                    float relativeThreshold) {
    const GpuLight light = params.lights[l];
    const vec3 d = normalize(vec3(light.direction));
    vec3 u;
    vec3 w;
    lightPlaneBasis(d, u, w);
    const float versine = lightDiscVersine(light);
    // Start one box diagonal before the box's centre along d: outside the box, whatever d is.
    const vec3 centre = 0.5f * (vec3(params.volumeMin) + vec3(params.volumeMax));
    const float diagonal = length(vec3(params.volumeMax) - vec3(params.volumeMin));
    vec4 rect = lightPlaneBounds(u, w);
    if (versine > 0.0f) {
        // The box lies within halfDepth of the centre's plane along d: a photon tilted by up to
        // the disc's radius α and aimed at a point of that plane meets the box only within
        // halfDepth · tan α of the rectangle.
        float halfDepth = 0.0f;
        for (int c = 0; c < 8; ++c)
            halfDepth = max(halfDepth, abs(dot(volumeCorner(c) - centre, d)));
        const float margin = halfDepth * sqrt(versine * (2.0f - versine)) / (1.0f - versine);
        rect += vec4(-margin, -margin, margin, margin);
    }
    float cellArea;
    const vec2 q = jitteredCellPoint(rect, photonsPerSide, index, l, index, seed, frame, cellArea);
    const vec3 through = (q.x - dot(centre, u)) * u + (q.y - dot(centre, w)) * w;
    vec3 travel = d;
    if (versine > 0.0f) travel = discDirection(d, u, w, versine, l, index, seed, frame);
    // (Without a disc, the sum in the order it always had: the same photons to the bit.)
    const vec3 origin = versine > 0.0f ? centre + through - diagonal * travel
                                       : centre - diagonal * d + (q.x - dot(centre, u)) * u +
                                             (q.y - dot(centre, w)) * w;
    return startPhoton(origin, travel, vec3(light.radiance) * cellArea, relativeThreshold);
}

// ---- Point and spot lights: perspective grids on planes at unit distance from the light. A cell
// of the plane at (s, t) from the axis subtends the solid angle cellArea · cos³θ, cos θ =
// 1/√(1 + s² + t²), so a photon through its jittered point carrying I × that (× the spot falloff
// there) is an unbiased estimate of the power the light sends through the cell. ----

// A perspective grid is used only where every corner of the box lies within this cosine of its
// axis (60°): its rectangle then stays within tan 60° of the axis, so its cells differ in solid
// angle by at most 8× and none degenerates.
EK_CONST float EK_PHOTON_GRID_MIN_COS = 0.5f;

// The axis of perspective grid `grid` (EK_PHOTON_GRID_BOX or _SPOT) of a light.
vec3 perspectiveAxis(GpuLight light, int grid) {
    if (grid == EK_PHOTON_GRID_SPOT) return normalize(vec3(light.direction));
    const vec3 centre = 0.5f * (vec3(params.volumeMin) + vec3(params.volumeMax));
    return normalize(centre - vec3(light.position));
}

// The rectangle of perspective grid `grid` on the plane at unit distance from the light along
// axis a (basis u, w): x, y = min; z, w = max. BOX: the box's projection. SPOT: the square around
// the outer cone's footprint (half-width tan θ_outer), cut to the box's projection where that
// exists. minCos gets the smallest cosine between a and the direction to a box corner: where it is
// ≤ 0 some corner lies beside or behind the light and the box has no projection.
vec4 perspectiveRect(GpuLight light, int grid, vec3 a, vec3 u, vec3 w, EK_OUT(float) minCos) {
    const vec3 p = vec3(light.position);
    vec4 r = vec4(3.0e38f, 3.0e38f, -3.0e38f, -3.0e38f);
    minCos = 1.0f;
    for (int c = 0; c < 8; ++c) {
        const vec3 e = volumeCorner(c) - p;
        const float z = dot(e, a);
        const float len = length(e);
        minCos = min(minCos, len > 0.0f ? z / len : -1.0f);
        if (!(z > 0.0f)) continue;
        const float s = dot(e, u) / z;
        const float t = dot(e, w) / z;
        r = vec4(min(r.x, s), min(r.y, t), max(r.z, s), max(r.w, t));
    }
    if (grid != EK_PHOTON_GRID_SPOT) return r;
    // tan θo from the versine v: sin θ = √(v (2 − v)), cos θ = 1 − v.
    const float v = lightVersineOuter(light);
    const float halfWidth = sqrt(max(v * (2.0f - v), 0.0f)) / (1.0f - v);
    if (!(minCos > 0.0f)) return vec4(-halfWidth, -halfWidth, halfWidth, halfWidth);
    return vec4(max(r.x, -halfWidth), max(r.y, -halfWidth), min(r.z, halfWidth),
                min(r.w, halfWidth));
}

float rectArea(vec4 r) {
    return (r.z - r.x) * (r.w - r.y);
}

// How light l's photons are laid out (EK_PHOTON_GRID_*), decided once on the host and passed to
// the generator: the layout sets the photon count, so both backends must agree on it exactly.
// Point and spot lights take the perspective grid with the smaller rectangle (the fewer photons
// wasted outside the box or the cone) where one is usable, else the six faces of a cube around
// the light (a light inside the box, or close beside it).
int photonGrid(int l) {
    const GpuLight light = params.lights[l];
    const int type = lightType(light);
    if (type == EK_LIGHT_DIRECTIONAL) return EK_PHOTON_GRID_PARALLEL;
    int grid = EK_PHOTON_GRID_CUBE;
    float area = 3.0e38f;
    vec3 u;
    vec3 w;
    float minCos;
    vec3 a = perspectiveAxis(light, EK_PHOTON_GRID_BOX);
    lightPlaneBasis(a, u, w);
    vec4 r = perspectiveRect(light, EK_PHOTON_GRID_BOX, a, u, w, minCos);
    if (minCos >= EK_PHOTON_GRID_MIN_COS) {
        grid = EK_PHOTON_GRID_BOX;
        area = rectArea(r);
    }
    if (type == EK_LIGHT_SPOT && 1.0f - lightVersineOuter(light) >= EK_PHOTON_GRID_MIN_COS) {
        a = perspectiveAxis(light, EK_PHOTON_GRID_SPOT);
        lightPlaneBasis(a, u, w);
        r = perspectiveRect(light, EK_PHOTON_GRID_SPOT, a, u, w, minCos);
        // The cone's square misses the box's projection: no photon could reach the box.
        if (!(r.x < r.z && r.y < r.w)) return EK_PHOTON_GRID_NONE;
        if (rectArea(r) < area) grid = EK_PHOTON_GRID_SPOT;
    }
    return grid;
}

// How many N×N grids layout `grid` has.
int photonGridFaces(int grid) {
    if (grid == EK_PHOTON_GRID_NONE) return 0;
    return grid == EK_PHOTON_GRID_CUBE ? 6 : 1;
}

// The face of layout `grid` that photon cell `cell` lies on: its axis a, basis u, w and rectangle
// (x, y = min; z, w = max) at unit distance; cell becomes the index within that face. Cube faces
// are ±x, ±y, ±z in that order, each the square [−1, 1]², together the whole sphere.
vec4 lightGridFace(GpuLight light, int grid, int cellsPerFace, EK_INOUT(int) cell, EK_OUT(vec3) a,
                   EK_OUT(vec3) u, EK_OUT(vec3) w) {
    if (grid == EK_PHOTON_GRID_CUBE) {
        const int face = cell / cellsPerFace;
        cell -= face * cellsPerFace;
        a = vec3(0.0f);
        a[face / 2] = (face & 1) == 0 ? 1.0f : -1.0f;
        lightPlaneBasis(a, u, w);
        return vec4(-1.0f, -1.0f, 1.0f, 1.0f);
    }
    a = perspectiveAxis(light, grid);
    lightPlaneBasis(a, u, w);
    float minCos;
    return perspectiveRect(light, grid, a, u, w, minCos);
}

// Photon `index` of point or spot light l laid out as `grid` (photonGrid): the ray from the light
// through the jittered point of its cell, carrying I × the cell's solid angle (× the spot
// falloff along the ray), starting where the ray enters the box, or at the light inside it.
GpuPhoton generatePointPhoton(int l, int grid, int photonsPerSide, int index, uint seed, uint frame,
                              float relativeThreshold) {
    const GpuLight light = params.lights[l];
    int cell = index;
    vec3 a;
    vec3 u;
    vec3 w;
    const vec4 rect = lightGridFace(light, grid, photonsPerSide * photonsPerSide, cell, a, u, w);
    float cellArea;
    const vec2 q = jitteredCellPoint(rect, photonsPerSide, cell, l, index, seed, frame, cellArea);
    const vec3 d = normalize(a + q.x * u + q.y * w);
    // 1 + s² + t² from the plane coordinates, not |a + s u + t w|²: exact for the ideal frame.
    const float r2 = 1.0f + q.x * q.x + q.y * q.y;
    float solidAngle = cellArea / (r2 * sqrt(r2));
    if (lightType(light) == EK_LIGHT_SPOT) solidAngle *= spotFalloff(light, d);
    return startPhoton(vec3(light.position), d, vec3(light.radiance) * solidAngle,
                       relativeThreshold);
}

// Photon `index` of light l laid out as `grid` (photonGrid(l)); photon indices run over
// photonGridFaces(grid) · N² per light.
GpuPhoton generatePhoton(int l, int grid, int photonsPerSide, int index, uint seed, uint frame,
                         float relativeThreshold) {
    if (grid == EK_PHOTON_GRID_PARALLEL)
        return generateDirectionalPhoton(l, photonsPerSide, index, seed, frame, relativeThreshold);
    return generatePointPhoton(l, grid, photonsPerSide, index, seed, frame, relativeThreshold);
}

// ∫ e^(−κt) dt over [0, s]: (1 − e^(−κs)) / κ, and its series as κs → 0 where that cancels.
float photonDecayIntegral(float kappa, float s) {
    return kappa * s > 1e-4f ? (1.0f - exp(-kappa * s)) / kappa : s * (1.0f - 0.5f * kappa * s);
}

// photonDecayIntegral for each channel. In C++ (the CPU twins) a grey κ takes one for all three,
// as channelDecay (optics.h) takes one exp.
vec3 photonDecayIntegrals(vec3 kappa, float s) {
#ifdef __cplusplus
    if (kappa.x == kappa.y && kappa.x == kappa.z) return vec3(photonDecayIntegral(kappa.x, s));
#endif
    return vec3(photonDecayIntegral(kappa.x, s), photonDecayIntegral(kappa.y, s),
                photonDecayIntegral(kappa.z, s));
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
            // The mask last: × 1 keeps the bits of a trace without dispersion.
            const vec3 fluxLength =
                flux0 * channelDecay(kappa, t0) * photonDecayIntegrals(kappa, len) * photonChannels;
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

// Spreads flux arriving at world point x on receiver r's front face over the four map texels
// around it with bilinear weights (a tent kernel one texel wide: each texel's sum estimates the
// flux through its area with less noise than a point count, and no flux is lost at the edges).
void depositOnReceiver(int r, vec3 x, vec3 flux) {
    ivec4 index;
    vec4 weight;
    receiverBilinear(r, receiverMapCoord(r, x), index, weight);
    for (int k = 0; k < 4; ++k)
        if (weight[k] > 0.0f) depositReceiverTexel(index[k], flux * weight[k]);
}

// One adaptive step of an active photon (§1 step 5): Δs = clamp(Δs_octree, minStep, Δs_max), with
// Δs_max winning where the two conflict (it is the accuracy the octree asks for there), taken by
// `integrator` (ray_equation.h; EK_RAY_EULER is the paper's x += (Δs/n) v, v += Δs ∇n); the flux
// decays by e^(−κ|Δx|) with κ at the chord's midpoint, and the chord is deposited. A segment that
// leaves the box is cut at the face and the photon escapes. extinguished gets the flux the step
// lost. Returns the photon's new state (EK_PHOTON_*).
int photonStep(EK_INOUT(GpuPhoton) photon, float minStep, int integrator,
               EK_INOUT(vec3) extinguished) {
    const vec3 x = vec3(photon.position);
    const vec3 v = vec3(photon.direction);
    const float speed = length(v);  // |v| = n on the exact path; drifts a little in the march
    const vec4 g0 = rayStepStart(integrator, x, v);
    if (!(speed > 1e-6f) || !(g0.w > 1e-6f)) return EK_PHOTON_DROPPED;
    const vec3 dir = v / speed;
    float maxStep;
    const float leafDistance = octreeLeafDistance(x, dir, maxStep);
    // The leaf distance is in world length; |Δx| = Δs |v| / n converts it to the ray parameter.
    const float ds = min(max(leafDistance * g0.w / speed, minStep), maxStep);
    vec3 next = x;
    vec3 vNext = v;
    if (!rayAdvance(integrator, next, vNext, ds, g0)) return EK_PHOTON_DROPPED;
    const vec3 delta = next - x;
    float s = length(delta);
    if (!(s > 0.0f) || !(s < 3.0e38f)) return EK_PHOTON_DROPPED;
    const vec3 segmentDir = delta / s;
    const float tExit = intersectVolume(x, segmentDir).y;
    const bool leaves = tExit <= s;
    if (leaves) {
        // v at the face, not at the step's end up to a step beyond it: the part of the step's
        // turn that happens inside (the chord's fraction; a whole step's turn is up to |∇n|/n Δs).
        const float inside = max(tExit, 0.0f) / s;
        vNext = v + inside * (vNext - v);
        s = max(tExit, 0.0f);
        next = x + segmentDir * s;
    }
    // A receiver in the way stops the photon on its plane; only its front face gathers flux.
    float tHit;
    bool front;
    const int receiver = receiverCrossing(x, next, tHit, front);
    if (receiver >= 0) {
        next = receiverHitPoint(receiver, x, next, tHit);
        s *= tHit;
    }
    const vec3 flux = vec3(photon.flux);
    const vec3 kappa = extinctionAt(worldToVolumeIndex(0.5f * (x + next)));
    depositSegment(x, next, s, segmentDir, flux, kappa);
    const vec3 fluxNext = flux * channelDecay(kappa, s);
    extinguished += flux - fluxNext;
    photon.position = vec4(next, photon.position.w);
    photon.direction = vec4(vNext, photon.direction.w + 1.0f);
    photon.flux = vec4(fluxNext, photon.flux.w);
    if (receiver >= 0) {
        // Voxel receivers have no map: the photon volumes beside them hold their light.
        if (front && receiverKind(params.receivers[receiver]) == EK_RECEIVER_PLANE)
            depositOnReceiver(receiver, next, fluxNext * photonChannels);
        return EK_PHOTON_RECEIVED;
    }
    if (leaves) return EK_PHOTON_ESCAPED;
    if (any(isnan(vNext)) || any(isinf(vNext))) return EK_PHOTON_DROPPED;  // a degenerate medium
    if (max(fluxNext.x, max(fluxNext.y, fluxNext.z)) < photon.flux.w) return EK_PHOTON_DROPPED;
    return EK_PHOTON_ACTIVE;
}

// Marches an active photon for at most `steps` steps, stopping early if it escapes, lands on a
// receiver or is dropped; the state is written to position.w (still EK_PHOTON_ACTIVE if it took
// all of them). Everything the march needs lives in the photon itself (position, v and the step
// count, flux and its threshold) and in `extinguished`, so a march split into rounds of
// marchPhoton takes exactly the steps of one uninterrupted march
// (render/transport/photons/photon_tracing.h).
void marchPhoton(EK_INOUT(GpuPhoton) photon, float minStep, int integrator, int steps,
                 EK_INOUT(vec3) extinguished) {
    int state = int(photon.position.w);
    for (int i = 0; i < steps && state == EK_PHOTON_ACTIVE; ++i)
        state = photonStep(photon, minStep, integrator, extinguished);
    photon.position.w = float(state);
}

// Marches a photon until it escapes, lands on a receiver, is dropped, or has taken maxSteps steps
// (EK_PHOTON_CUT); the state is written to position.w. extinguished gets the flux lost on the way.
void tracePhoton(EK_INOUT(GpuPhoton) photon, float minStep, int integrator, int maxSteps,
                 EK_INOUT(vec3) extinguished) {
    marchPhoton(photon, minStep, integrator, maxSteps, extinguished);
    if (int(photon.position.w) == EK_PHOTON_ACTIVE) photon.position.w = float(EK_PHOTON_CUT);
}

#endif
