// The viewing pass: emission, absorption and single scattering of every light. A light's light
// reaches the medium through the light-transport method's fluence volumes (lightInFluence; with
// photons, light bent and focused by refraction) or straight, with its transmittance (shadowing)
// taken from the light volume (light_volume.h) or, as reference, marched toward the light from
// every sample (like vdb_render). Rays that leave the volume see environmentRadiance
// (environment.h); rays that reach a receiver (receivers.h) stop there and see its diffuse
// reflection. Curved rays crossing the sharp surface of a refracting material (fresnel.h) keep
// 1 − R of their transmittance and see R of what lies in the mirror direction, and, with
// EK_SPECULAR (the CPU twin always; on the GPU a variant for the scenes that have them, so that
// the others run the code they always ran, to the instruction), the lights' highlights where the
// material has a roughness. Needs optics.h, receivers.h, ray_equation.h,
// environment.h, fresnel.h, specular.h and, from the includer,
// `vec4 fetchReceiverTexel(int index)`: the irradiance (rgb) of a texel of the receiver map;
// `bool viewSampleReady(vec3 p)`: whether a step's sample may be shaded now; and
// `bool receiverDeferred(int r, vec3 x, bool front, vec3 weight)`: whether the includer takes a
// receiver hit to shade later (weight × receiverRadiance, added to the ray's radiance), when its
// irradiance is not complete yet. Both are true and false in the view pass (view.comp and its
// twin); the plane sweep's interleaved view (view_interleaved.comp and its twin) waits and defers.

// Integral of e^(−κ s) over a step of length s: (1 − e^(−κ s)) / κ, and s as κ → 0; `decay` is
// e^(−κ s), the step's transmittance, which the step takes anyway (one exp for both: a C++
// compiler may not merge two calls of exp, which may set errno).
float stepWeight(float kappa, float s, float decay) {
    return kappa * s > 1e-5f ? (1.0f - decay) / kappa : s * (1.0f - 0.5f * kappa * s);
}

// stepWeight for each channel, decay = channelDecay(kappa, s). In C++ (the CPU twins) a grey κ
// takes one for all three, as channelDecay (optics.h) takes one exp.
vec3 stepWeights(vec3 kappa, float s, vec3 decay) {
#ifdef __cplusplus
    if (kappa.x == kappa.y && kappa.x == kappa.z) return vec3(stepWeight(kappa.x, s, decay.x));
#endif
    return vec3(stepWeight(kappa.x, s, decay.x), stepWeight(kappa.y, s, decay.y),
                stepWeight(kappa.z, s, decay.z));
}

// Light scattered toward the camera (along −dir) at volume index position p from the fluence
// volumes (Sun et al. 2008 §5.4): the fluence rate φ = Σ flux·length / voxel volume, and one
// phase function per material around the stored mean direction the light travels. Where the
// directions cancel (light crossing from opposite sides) the mean says nothing: the phase
// function falls back to isotropic, 1/4π.
vec3 fluenceInScattering(vec3 p, vec3 dir, vec3 sigma[EK_MAX_MATERIALS]) {
    const vec3 h = volumeVoxelSize();
    const vec3 fluenceRate = vec3(sampleVolume(EK_FLUENCE_SLOT, p)) / (h.x * h.y * h.z);
    const vec3 weightedDir = vec3(sampleVolume(EK_FLUENCE_DIRECTION_SLOT, p));
    const float len = length(weightedDir);
    const bool directed = len > 1e-20f;
    const float cosTheta = directed ? dot(weightedDir / len, -dir) : 0.0f;
    vec3 scattered = vec3(0.0f);
    for (int m = 0; m < materialCount(params); ++m)
        scattered += sigma[m] * (directed ? phaseHG(materialPhaseG(params.materials[m]), cosTheta)
                                          : 1.0f / (4.0f * EK_PI));
    return scattered * fluenceRate;
}

// Light l's transmittance on its way to x (volume index position p): from its light volume, or
// marched toward it (EK_SHADOWS_MARCHED, the reference).
vec3 lightShadow(int l, vec3 x, vec3 p, vec3 toLight, float lightDistance) {
    if (shadowMode(params) == EK_SHADOWS_MARCHED)
        return lightTransmittance(l, x, toLight, lightDistance);
    return vec3(sampleVolume(EK_MAX_MATERIALS + l, p));
}

// Irradiance on receiver r at x (on its plane) from the lights whose light comes through the
// fluence (lightInFluence). Plane receivers read their map (the flux that crossed the plane, per
// area); voxel receivers read the fluence volumes 1.5 voxels in front of the plane, where they
// are not yet cut by it: fluence rate times the net flux's cosine with the normal,
// |Σ lum·dir| ≤ lum(Σ flux·length) making that factor a cosine in [0, 1].
vec3 receiverFluenceIrradiance(int r, vec3 x) {
    if (receiverKind(params.receivers[r]) == EK_RECEIVER_PLANE) {
        ivec4 index;
        vec4 weight;
        receiverBilinear(r, receiverMapCoord(r, x), index, weight);
        vec3 e = vec3(0.0f);
        for (int k = 0; k < 4; ++k) e += weight[k] * vec3(fetchReceiverTexel(index[k]));
        return e;
    }
    const vec3 normal = receiverNormal(r);
    const vec3 p = worldToVolumeIndex(x) + 1.5f * normal;
    const vec3 h = volumeVoxelSize();
    const vec3 fluxLength = vec3(sampleVolume(EK_FLUENCE_SLOT, p));
    const vec3 weightedDir = vec3(sampleVolume(EK_FLUENCE_DIRECTION_SLOT, p));
    const float lum = dot(fluxLength, vec3(0.2126f, 0.7152f, 0.0722f));
    if (!(lum > 0.0f)) return vec3(0.0f);
    const float cosine = clamp(-dot(weightedDir, normal) / lum, 0.0f, 1.0f);
    return fluxLength / (h.x * h.y * h.z) * cosine;
}

// Radiance the front face of receiver r reflects toward the camera at x: albedo/π × the
// irradiance of every light, through the fluence or, for the other lights, straight with their
// transmittance. Its back face is black.
vec3 receiverRadiance(int r, vec3 x, bool front) {
    if (!front) return vec3(0.0f);
    vec3 irradiance = anyLightInFluence(params) ? receiverFluenceIrradiance(r, x) : vec3(0.0f);
    const vec3 normal = receiverNormal(r);
    const vec3 p = worldToVolumeIndex(x);
    for (int l = 0; l < lightCount(params); ++l) {
        if (lightInFluence(params, l)) continue;  // in receiverFluenceIrradiance
        vec3 toLight;
        float lightDistance;
        const vec3 e = lightIrradiance(l, x, toLight, lightDistance);
        const float cosine = dot(toLight, normal);
        if (!(cosine > 0.0f) || e.x + e.y + e.z <= 0.0f) continue;
        irradiance += e * cosine * lightShadow(l, x, p, toLight, lightDistance);
    }
    return vec3(params.receivers[r].albedo) * (1.0f / EK_PI) * irradiance;
}

// The roughness of the sharp surface a crossing from volume index position pStart to pEnd went
// through: that of the sharp material whose field changed most over it (materialRoughness); 0
// where none of them has highlights.
float crossingRoughness(vec3 pStart, vec3 pEnd) {
    float roughness = 0.0f;
    float largest = 0.0f;
    for (int m = 0; m < materialCount(params); ++m) {
        if (!materialFresnel(params.materials[m])) continue;
        const int slot = materialSlot(params.materials[m]);
        const float change = abs(sampleField(slot, pEnd) - sampleField(slot, pStart));
        if (change > largest) {
            largest = change;
            roughness = materialRoughness(params.materials[m]);
        }
    }
    return roughness;
}

// Whether some material's sharp surfaces show highlights.
bool anyRoughSurfaces() {
    for (int m = 0; m < materialCount(params); ++m)
        if (materialFresnel(params.materials[m]) && materialRoughness(params.materials[m]) > 0.0f)
            return true;
    return false;
}

// The lights' specular highlights (specular.h) seen toward unit v (pointing to the viewer) on a
// sharp surface of the given roughness crossed from index n1 (the viewer's side) to n2, the light
// taken at world point x where the crossing began (on the viewer's side, before the surface
// passes it on): through the fluence, its coherent part (the fluence rate times
// |Σ lum·dir| / Σ lum, from the mean direction, as receivers take it); the other lights straight,
// with their transmittance. normalSum: the ∇n gathered over the crossing (fresnel.h).
vec3 surfaceHighlights(vec3 x, vec3 normalSum, vec3 v, float roughness, float n1, float n2) {
    const float size = length(normalSum);
    if (!(size > 0.0f) || !(roughness > 0.0f)) return vec3(0.0f);
    const vec3 normal = normalSum / size;
    const vec3 p = worldToVolumeIndex(x);
    vec3 highlight = vec3(0.0f);
    if (anyLightInFluence(params) && viewSampleReady(p)) {
        const vec3 h = volumeVoxelSize();
        const vec3 fluxLength = vec3(sampleVolume(EK_FLUENCE_SLOT, p));
        const vec3 weightedDir = vec3(sampleVolume(EK_FLUENCE_DIRECTION_SLOT, p));
        const float lum = dot(fluxLength, vec3(0.2126f, 0.7152f, 0.0722f));
        const float len = length(weightedDir);
        if (lum > 0.0f && len > 0.0f)
            highlight += fluxLength / (h.x * h.y * h.z) * min(len / lum, 1.0f) *
                         ggxSpecular(normal, v, -weightedDir / len, roughness, n1, n2);
    }
    for (int l = 0; l < lightCount(params); ++l) {
        if (lightInFluence(params, l)) continue;  // above
        vec3 toLight;
        float lightDistance;
        const vec3 e = lightIrradiance(l, x, toLight, lightDistance);
        if (e.x + e.y + e.z <= 0.0f) continue;
        const float reflected = ggxSpecular(normal, v, toLight, roughness, n1, n2);
        if (!(reflected > 0.0f)) continue;
        highlight += e * reflected * lightShadow(l, x, p, toLight, lightDistance);
    }
    return highlight;
}

// Radiance reaching the camera along a ray, and the ray's transmittance through the volume.
// Adds one step of length s, with the medium's optics taken at its midpoint x (volume index
// position p) and the ray travelling along unit `dir`. Returns false once the ray is opaque
// (every channel below the scene's cut-off), with transmittance set to 0.
EK_FORCE_INLINE bool accumulateStep(vec3 x, vec3 p, vec3 dir, float s, EK_INOUT(vec3) radiance,
                                    EK_INOUT(vec3) transmittance) {
    vec3 kappa = vec3(0.0f);
    vec3 source = vec3(0.0f);
    // Per-material scattering, kept for the phase function of each light below.
    vec3 sigma[EK_MAX_MATERIALS];
    bool scatters = false;
    // The field a particle colour reads, at the step's two ends: sampled once for all the
    // materials coloured by it (a scan's tissue classes all read the scan).
    int endsSlot = -1;
    float endA = 0.0f;
    float endB = 0.0f;
    for (int m = 0; m < materialCount(params); ++m) {
        const int slot = materialSlot(params.materials[m]);
        const float value = sampleField(slot, p);
        const float field = clippedField(m, p, value);  // clip planes cut it (optics.h)
        sigma[m] = field * vec3(params.materials[m].scattering);
        kappa += field * vec3(params.materials[m].absorption) + sigma[m];
        vec3 emitted = field * vec3(params.materials[m].emission);
        // A particle colour tints what the material scatters and emits, not what it takes away;
        // it reads the field's own value (colorSlot) over the step.
        const int colorSlot = materialColorSlot(params.materials[m]);
        if (colorSlot >= 0) {
            if (colorSlot != endsSlot) {
                const vec3 halfStep = (0.5f * s) * dir / volumeVoxelSize();
                endA = sampleField(colorSlot, p - halfStep);
                endB = sampleField(colorSlot, p + halfStep);
                endsSlot = colorSlot;
            }
            // The midpoint's value where the material's own slot holds it, else the ends' mean.
            const float mid = colorSlot == slot ? value : 0.5f * (endA + endB);
            const vec3 tint = particleColorOverStep(m, endA, mid, endB);
            sigma[m] *= tint;
            emitted *= tint;
        }
        source += emitted;
        scatters = scatters || sigma[m].x + sigma[m].y + sigma[m].z > 0.0f;
    }
    if (scatters && readsFluence(params)) source += fluenceInScattering(p, dir, sigma);
    if (scatters) {
        for (int l = 0; l < lightCount(params); ++l) {
            if (lightInFluence(params, l)) continue;  // in the fluence volumes
            vec3 toLight;
            float lightDistance;
            const vec3 irradiance = lightIrradiance(l, x, toLight, lightDistance);
            if (irradiance.x + irradiance.y + irradiance.z <= 0.0f) continue;
            // Light travels along −toLight and scatters toward the camera, along −dir.
            const float cosTheta = dot(-toLight, -dir);
            vec3 scattered = vec3(0.0f);
            for (int m = 0; m < materialCount(params); ++m)
                scattered += sigma[m] * phaseHG(materialPhaseG(params.materials[m]), cosTheta);
            source += scattered * irradiance * lightShadow(l, x, p, toLight, lightDistance);
        }
    }
    const vec3 decay = channelDecay(kappa, s);
    radiance += transmittance * source * stepWeights(kappa, s, decay);
    transmittance *= decay;
    if (max(max(transmittance.x, transmittance.y), transmittance.z) < minTransmittance(params)) {
        transmittance = vec3(0.0f);  // what is left is below the cut-off the scene set
        return false;
    }
    return true;
}

#ifdef EK_SKIP_EMPTY_SPACE
// Empty space (CPU twin only; render/empty_bricks.h): where the includer's
// `int emptyBrickAt(vec3 indexPos)` finds the brick around a step empty (≥ 0: its index; −1: not
// empty), every field is zero and ∇n is +0 for every sample the step takes; `bool
// anyEmptyBricks()` says whether there is one at all (a fog that fills the volume leaves none, and
// a curved step then spends nothing looking). These two functions give the full step's floats
// without taking those samples.

// accumulateStep over a step where every field is zero: no κ, no source, so the radiance gains
// transmittance × 0 × s = +0 and the transmittance keeps its value (× e^0 = × 1); the cut-off is
// tested as accumulateStep tests it.
bool accumulateEmptyStep(EK_INOUT(vec3) radiance, EK_INOUT(vec3) transmittance) {
    radiance += vec3(0.0f);
    if (max(max(transmittance.x, transmittance.y), transmittance.z) < minTransmittance(params)) {
        transmittance = vec3(0.0f);
        return false;
    }
    return true;
}

// rayAdvance's Störmer–Verlet step of length h from (x, v) where the force n∇n is +0 at its
// midpoint: v gains dτ × 0 = +0, x moves straight. True, with next and vNext set, where the step
// starts and ends in the same empty brick (its midpoint then lies in it too); false otherwise.
bool emptyVerletStep(vec3 x, vec3 v, float h, EK_OUT(vec3) next, EK_OUT(vec3) vNext) {
    next = x;
    vNext = v;
    if (viewIntegrator(params) != EK_RAY_VERLET || !anyEmptyBricks()) return false;
    const int brick = emptyBrickAt(worldToVolumeIndex(x));
    if (brick < 0) return false;
    const float speed = length(v);  // rayStepStart's w for Verlet
    if (!(speed > 1e-6f)) return false;
    const float dtau = h / speed;
    const vec3 xHalf = x + (0.5f * dtau) * v;
    const vec3 vEnd = v + vec3(0.0f);
    const vec3 xEnd = xHalf + (0.5f * dtau) * vEnd;
    if (emptyBrickAt(worldToVolumeIndex(xEnd)) != brick) return false;
    next = xEnd;
    vNext = vEnd;
    return true;
}
#endif

// One step of the ray equation of length h from (x, v) (viewIntegrator, ray_equation.h) into
// (next, vNext); `empty` where it was taken straight through an empty brick (CPU twin,
// EK_SKIP_EMPTY_SPACE). False where the medium is degenerate: nothing more to trace.
bool curvedRayStep(vec3 x, vec3 v, float h, EK_OUT(vec3) next, EK_OUT(vec3) vNext,
                   EK_OUT(bool) empty) {
    next = x;
    vNext = v;
    empty = false;
#ifdef EK_SKIP_EMPTY_SPACE
    empty = emptyVerletStep(x, v, h, next, vNext);
    if (empty) return true;
#endif
    return rayAdvance(viewIntegrator(params), next, vNext, h,
                      rayStepStart(viewIntegrator(params), x, v));
}

// A reflection a view ray hands back to be traced through the volume: from origin (xyz) along
// unit dir (xyz) with momentum dir × n (n in dir.w), seen with weight (rgb; 0: none).
struct KeptReflection {
    vec4 origin;
    vec4 dir;
    vec4 weight;
};

// A curved ray being traced (traceCurvedRayReflecting): where it is, what it has gathered, and
// its walk across sharp surfaces. A state of its own so that a trace can stop between steps and
// go on later (the plane sweep's interleaved viewing, plane_sweep_view.h, advances every pixel's
// ray only as far as the light planes swept so far).
struct CurvedRay {
    vec3 x;  // where it is
    vec3 v;  // n dx/ds
    vec3 exitDir;
    vec3 radiance;
    vec3 transmittance;
    vec4 walk;  // the walk across sharp surfaces (fresnel.h)
    vec4 surfaceNormal;
    vec3 crossingStart;
    float h;             // the step length
    float surfaceSlope;  // per scene unit; 0: no walk
    int kept;
    int keep;
    int steps;  // taken so far, of at most maxSteps
    int maxSteps;
    bool shade;
};

// How curvedRayAdvance stopped.
#define EK_RAY_ENDED 1  // it left the volume, stopped on a receiver or the medium went degenerate
#define EK_RAY_WAITS 2  // its next sample is not ready (viewSampleReady)

// The ray that traceCurvedRayReflecting traces from `entry`, before its first step.
CurvedRay curvedRayStart(vec3 entry, vec3 dir, bool shade, float onSurface, int keep, vec3 radiance,
                         vec3 transmittance) {
    CurvedRay r;
    r.h = viewStep(params);
    r.x = entry;
    const vec4 gEntry = sampleVolume(EK_GRADIENT_SLOT, worldToVolumeIndex(entry));
    r.v = dir * (onSurface > 0.0f ? onSurface : gEntry.w);
    r.exitDir = dir;
    r.radiance = radiance;
    r.transmittance = transmittance;
    r.kept = 0;
    r.keep = keep;
    r.shade = shade;
    // The walk across sharp surfaces (fresnel.h), its slope per scene unit.
    const vec3 voxel = volumeVoxelSize();
    r.surfaceSlope = shade && anySurfaces()
                         ? viewSurfaceSlope(params) / min(voxel.x, min(voxel.y, voxel.z))
                         : 0.0f;
    r.walk = vec4(0.0f);
    if (r.surfaceSlope > 0.0f) {
        const float nSurface = surfaceIndexAt(worldToVolumeIndex(entry));
        r.walk = onSurface > 0.0f ? surfaceWalkStartOnSurface(gEntry.w, nSurface)
                                  : surfaceWalkStart(gEntry.w, nSurface);
    }
    r.surfaceNormal = vec4(0.0f);
    r.crossingStart = entry;
    // A ray trapped by total internal reflection would circle forever: bound the path at 16
    // crossings of the volume.
    const ivec3 res = volumeResolution();
    r.maxSteps = 16 * (res.x + res.y + res.z);
    r.steps = 0;
    return r;
}

// Steps the ray by the ray equation, steps of length h (viewIntegrator, ray_equation.h), the
// last cut at the volume's face or a receiver, with accumulateStep on each segment while the ray
// shades, until it ends (EK_RAY_ENDED) or the next segment's shading sample is not ready
// (viewSampleReady, from the includer: EK_RAY_WAITS). A waiting ray is left as it was before
// that step: advanced again later, it takes the same step, to the bit. One loop with breaks, as
// the trace was written before it could wait: a step function called in a loop, with its early
// returns, took llvmpipe 10 % longer to compile view.comp. The first r.keep reflections at sharp
// surfaces go to first and second (traceCurvedRayReflecting), the others see the environment.
int curvedRayAdvance(EK_INOUT(CurvedRay) r, EK_INOUT(KeptReflection) first,
                     EK_INOUT(KeptReflection) second) {
    int status = EK_RAY_ENDED;
    // Whether a step moved the ray: its exit direction is normalize(v) after its last step, taken
    // once on the way out rather than at every step (the same floats: the same v).
    bool moved = false;
    // The next step, taken ahead (see below) where this one goes on.
    bool ahead = false;
    vec3 aheadNext = r.x;
    vec3 aheadV = r.v;
    bool aheadTaken = false;
    bool aheadEmpty = false;
    for (; r.steps < r.maxSteps; ++r.steps) {
        vec3 next = r.x;
        vec3 vNext = r.v;
        bool empty = false;
        bool taken;
        if (ahead) {
            next = aheadNext;
            vNext = aheadV;
            taken = aheadTaken;
            empty = aheadEmpty;
            ahead = false;
        } else {
            taken = curvedRayStep(r.x, r.v, r.h, next, vNext, empty);
        }
        if (!taken) break;  // a degenerate n; nothing more to trace
        const vec3 delta = next - r.x;
        float s = length(delta);
        if (!(s > 0.0f)) break;  // a degenerate n; nothing more to trace
        const vec3 segmentDir = delta / s;
        const float tExit = intersectVolume(r.x, segmentDir).y;
        const bool leaves = tExit < s;
        if (leaves) {
            // v at the face, not at the step's end beyond it (photons.h, photonStep).
            const float inside = max(tExit, 0.0f) / s;
            vNext = r.v + inside * (vNext - r.v);
            s = max(tExit, 0.0f);
            next = r.x + segmentDir * s;
        }
        float tHit;
        bool front;
        const int receiver = receiverCrossing(r.x, next, tHit, front);
        if (receiver >= 0) {
            next = receiverHitPoint(receiver, r.x, next, tHit);
            s *= tHit;
        }
        // Where the ray goes on from here, its next step depends on nothing the shading below
        // does: taken now, its chain of dependent operations (each step's ∇n sample waits on the
        // step before) runs beside this step's shading instead of after it. The same floats.
        if (!leaves && receiver < 0 && r.steps + 1 < r.maxSteps) {
            aheadTaken = curvedRayStep(next, vNext, r.h, aheadNext, aheadV, aheadEmpty);
            ahead = true;
        }
        if (r.shade) {
            const vec3 mid = 0.5f * (r.x + next);
            const vec3 midIndex = worldToVolumeIndex(mid);
            if (!viewSampleReady(midIndex)) {
                status = EK_RAY_WAITS;
                break;
            }
#ifdef EK_SKIP_EMPTY_SPACE
            if (empty ? !accumulateEmptyStep(r.radiance, r.transmittance)
                      : !accumulateStep(mid, midIndex, segmentDir, s, r.radiance, r.transmittance))
                r.shade = false;  // opaque: keep tracing only for the exit point
#else
            if (!accumulateStep(mid, midIndex, segmentDir, s, r.radiance, r.transmittance))
                r.shade = false;  // opaque: keep tracing only for the exit point
#endif
        }
        if (r.shade && r.surfaceSlope > 0.0f && s > 0.0f) {
            const vec3 q = worldToVolumeIndex(next);
            const float n1 = r.walk.y;  // where a crossing ending here began
            const float transmitted =
                surfaceWalkStep(r.walk, r.surfaceNormal, sampleVolume(EK_GRADIENT_SLOT, q),
                                surfaceIndexAt(q), vNext, r.surfaceSlope * s, r.surfaceSlope);
            if (n1 == 0.0f && r.walk.y != 0.0f) r.crossingStart = r.x;  // a crossing began
            if (transmitted < 1.0f) {
                const vec3 weight = r.transmittance * (1.0f - transmitted);
                const vec3 mirror = surfaceMirrorDirection(vNext, vec3(r.surfaceNormal), n1);
#ifdef EK_SPECULAR
                if (anyRoughSurfaces()) {
                    // The lights' highlights, seen from where the ray came (v: back along its
                    // incident direction, the mirror direction reflected again).
                    const vec3 normal = normalize(vec3(r.surfaceNormal));
                    const vec3 v = 2.0f * dot(mirror, normal) * normal - mirror;
                    const float roughness =
                        crossingRoughness(worldToVolumeIndex(r.crossingStart), q);
                    r.radiance +=
                        r.transmittance * surfaceHighlights(r.crossingStart, vec3(r.surfaceNormal),
                                                            v, roughness, n1, r.walk.z);
                }
#endif
                if (r.kept < r.keep) {
                    KeptReflection k;
                    k.origin = vec4(r.crossingStart, 0.0f);
                    k.dir = vec4(mirror, n1);
                    k.weight = vec4(weight, 0.0f);
                    if (r.kept == 0)
                        first = k;
                    else
                        second = k;
                    ++r.kept;
                } else {
                    r.radiance += weight * environmentRadiance(mirror);
                }
                r.transmittance *= transmitted;
            }
        }
        r.x = next;
        r.v = vNext;
        moved = true;
        if (receiver >= 0) {  // opaque: nothing behind it shows
            if (r.shade && !receiverDeferred(receiver, r.x, front, r.transmittance))
                r.radiance += r.transmittance * receiverRadiance(receiver, r.x, front);
            r.transmittance = vec3(0.0f);
            ++r.steps;
            break;
        }
        if (leaves) {
            ++r.steps;
            break;
        }
    }
    if (moved) r.exitDir = normalize(r.v);
    return status;
}

// Traces a curved ray from `entry` (on or inside the volume) with unit direction `dir`, one step
// of the ray equation of length h per iteration (curvedRayAdvance), until it leaves the volume or
// the medium goes degenerate; the last step is cut at the face. Calls accumulateStep on every
// segment when `shade`. Returns the exit point; exitDir gets the direction the ray leaves with.
//
// With `shade` and viewSurfaceSlope > 0 it reflects at the sharp surfaces it crosses (fresnel.h;
// Ihrke et al. 2007 eqs. 2 and 5): once a crossing ends with transmittance factor t < 1, the
// transmittance keeps t and the reflected part, transmittance × (1 − t), is seen along the mirror
// direction. The first `keep` (0-2) such reflections are handed back in first and second, to be
// traced through the volume from where their crossing began (on the side the ray came from):
// what a glass in fog reflects, outside and inside, is mostly lit fog. Every other reflection sees
// the environment in its direction (the paper's "first reflection" by environment mapping), a
// reflection off the inside of glass its direction inside the glass. `onSurface` > 0: the ray
// starts in a surface's layer (a kept reflection), with momentum dir × onSurface (the n on the
// side it was reflected to: n where it starts, in the layer, would shorten its tangential part,
// which Snell's law keeps), and finds no crossing before it is out of the layer.
vec3 traceCurvedRayReflecting(vec3 entry, vec3 dir, bool shade, float onSurface, int keep,
                              EK_INOUT(vec3) radiance, EK_INOUT(vec3) transmittance,
                              EK_OUT(vec3) exitDir, EK_OUT(KeptReflection) first,
                              EK_OUT(KeptReflection) second) {
    CurvedRay r = curvedRayStart(entry, dir, shade, onSurface, keep, radiance, transmittance);
    first.weight = second.weight = vec4(0.0f);
    first.origin = second.origin = first.dir = second.dir = vec4(0.0f);
    curvedRayAdvance(r, first, second);
    radiance = r.radiance;
    transmittance = r.transmittance;
    exitDir = r.exitDir;
    return r.x;
}

// traceCurvedRayReflecting with every reflection seeing the environment.
vec3 traceCurvedRay(vec3 entry, vec3 dir, bool shade, EK_INOUT(vec3) radiance,
                    EK_INOUT(vec3) transmittance, EK_OUT(vec3) exitDir) {
    KeptReflection unusedFirst, unusedSecond;
    return traceCurvedRayReflecting(entry, dir, shade, 0.0f, 0, radiance, transmittance, exitDir,
                                    unusedFirst, unusedSecond);
}

// A straight ray being integrated (integrateViewRay), in steps of h along t from where it enters
// the volume; like CurvedRay, a state that can stop between steps.
struct StraightRay {
    vec3 origin;
    vec3 dir;
    vec3 radiance;
    vec3 transmittance;
    float tStart;  // where the ray enters the volume
    float tEnd;    // and leaves it
    int step;
    int steps;
};

StraightRay straightRayStart(vec3 origin, vec3 dir, vec2 span) {
    StraightRay r;
    r.origin = origin;
    r.dir = dir;
    r.radiance = vec3(0.0f);
    r.transmittance = vec3(1.0f);
    r.tStart = span.x;
    r.tEnd = span.y;
    r.step = 0;
    r.steps = min(int(ceil((span.y - span.x) / viewStep(params))), EK_MAX_STEPS);
    return r;
}

#ifdef EK_SKIP_EMPTY_SPACE
// The last step of straight ray r, from r.step (an empty step) on, that the ray may skip: its
// sample, and every sample between, lies in the run of empty bricks r.step's sample is in. Each
// such step adds +0 and keeps the transmittance, and skipping them gives the same floats.
//
// The run is found along the ray in volume index space, o + d·t (emptyRunEnd), which differs
// from a step's own sample, worldToVolumeIndex(origin + dir·t), by rounding: a few units in the
// last place of o and d·t, far below the 0.25 voxel kept back from the run's end below while they
// stay under 1e5 voxels. A sample less than half a voxel outside an empty brick still reads only
// the voxels that make it empty (render/empty_bricks.h), so the steps skipped are empty to the
// bit even where rounding put one a little out. Only where no receiver may cut a step and every
// sample may be shaded at once (viewSamplesAllReady: not the interleaved view, whose samples wait
// on the sweep); r.step elsewhere.
int lastStepInEmptyRun(StraightRay r) {
    if (receiverCount(params) > 0 || !viewSamplesAllReady()) return r.step;
    const vec3 o = worldToVolumeIndex(r.origin);
    const vec3 d = r.dir / volumeVoxelSize();
    const float speed = length(d);  // voxels per unit of t
    const float far = max(max(abs(o.x), abs(o.y)), abs(o.z)) + speed * r.tEnd;
    if (!(far < 1e5f) || !(speed > 0.0f)) return r.step;
    const float h = viewStep(params);
    const float t0 = r.tStart + float(r.step) * h;
    const float mid = 0.5f * (t0 + min(t0 + h, r.tEnd));
    const float leave = emptyRunEnd(o, d, mid) - 0.25f / speed;
    // The last step whose midpoint, r.tStart + (k + 1/2) h, comes before `leave`.
    const float last = floor((leave - r.tStart) / h - 0.5f);
    if (!(last > float(r.step))) return r.step;
    return last < float(r.steps - 1) ? int(last) : r.steps - 1;
}
#endif

// Steps a straight ray, each step exactly clipped, until it ends or waits (curvedRayAdvance's
// contract).
int straightRayAdvance(EK_INOUT(StraightRay) r) {
    const float h = viewStep(params);
    int status = EK_RAY_ENDED;
    for (; r.step < r.steps; ++r.step) {
        const float t0 = r.tStart + float(r.step) * h;
        const float tEnd = min(t0 + h, r.tEnd);
        float tHit;
        bool front;
        const int receiver =
            receiverCrossing(r.origin + r.dir * t0, r.origin + r.dir * tEnd, tHit, front);
        const float t1 = receiver >= 0 ? t0 + (tEnd - t0) * tHit : tEnd;
        const vec3 x = r.origin + r.dir * (0.5f * (t0 + t1));
        const vec3 p = worldToVolumeIndex(x);
        if (!viewSampleReady(p)) {
            status = EK_RAY_WAITS;
            break;
        }
#ifdef EK_SKIP_EMPTY_SPACE
        if (receiver < 0 && emptyBrickAt(p) >= 0) {  // the step's one sample is in empty space
            if (!accumulateEmptyStep(r.radiance, r.transmittance)) {
                ++r.step;
                break;
            }
            // The steps after it in the same run of empty bricks change nothing either.
            r.step = lastStepInEmptyRun(r);
            continue;
        }
#endif
        if (!accumulateStep(x, p, r.dir, t1 - t0, r.radiance, r.transmittance)) {
            ++r.step;
            break;
        }
        if (receiver >= 0) {  // opaque: nothing behind it shows
            const vec3 hit =
                receiverHitPoint(receiver, r.origin + r.dir * t0, r.origin + r.dir * tEnd, tHit);
            if (!receiverDeferred(receiver, hit, front, r.transmittance))
                r.radiance += r.transmittance * receiverRadiance(receiver, hit, front);
            r.transmittance = vec3(0.0f);
            ++r.step;
            break;
        }
    }
    return status;
}

// Radiance reaching the camera along a ray, and the ray's transmittance through the volume.
// Straight rays integrate exactly-clipped steps along t; curved rays (curvedRays) follow
// the ray equation inside the volume, where n varies, and leave along their bent direction; up to
// two reflections at sharp surfaces are kept and traced the same way, each seeing the environment
// at its own reflections. The camera's ray and the kept reflections are passes of one loop around
// one call of the trace, the count of passes known only at run time: shader compilers inline
// every call and unroll a loop of known count, and three copies of the trace (each with the light
// marches of accumulateStep) took llvmpipe 47 s to compile view.comp (link and the first
// dispatch, where it generates code), 221 s with EK_HARDWARE_TRILINEAR; one takes 16 s and 69 s
// (BENCHMARKS.md, "Compiling the shaders on llvmpipe").
//
// `curved` is curvedRays(params), passed in so that a CPU twin can compile a copy of the trace for
// each kind of ray with the other kind's code left out (render/view_pass_cpu.cpp): integrateViewRay
// passes it.
vec3 integrateViewRayOf(vec3 origin, vec3 dir, bool curved, EK_OUT(vec3) transmittance) {
    transmittance = vec3(1.0f);
    vec3 radiance = vec3(0.0f);
    const vec2 span = intersectVolume(origin, dir);
    if (!(span.x < span.y)) return environmentRadiance(dir);
    if (curved) {
        KeptReflection first, second;  // the camera ray's pass keeps them
        first.weight = second.weight = vec4(0.0f);
        first.origin = second.origin = first.dir = second.dir = vec4(0.0f);
        int passes = 1;
        for (int pass = 0; pass < passes; ++pass) {
            const KeptReflection r = pass == 1 ? first : second;  // passes 1 and 2
            if (pass > 0 && !(r.weight.x + r.weight.y + r.weight.z > 0.0f)) continue;
            vec3 passRadiance = vec3(0.0f);
            vec3 passTransmittance = vec3(1.0f);
            vec3 exitDir;
            KeptReflection keptFirst, keptSecond;
            traceCurvedRayReflecting(pass == 0 ? origin + dir * span.x : vec3(r.origin),
                                     pass == 0 ? dir : vec3(r.dir), true,
                                     pass == 0 ? 0.0f : r.dir.w, pass == 0 ? 2 : 0, passRadiance,
                                     passTransmittance, exitDir, keptFirst, keptSecond);
            const vec3 seen = passRadiance + passTransmittance * environmentRadiance(exitDir);
            if (pass == 0) {
                radiance = seen;
                transmittance = passTransmittance;
                first = keptFirst;
                second = keptSecond;
                passes = 3;  // a pass whose reflection has no weight is skipped above
            } else {
                radiance += vec3(r.weight) * seen;
            }
        }
        return radiance;
    }
    StraightRay r = straightRayStart(origin, dir, span);
    straightRayAdvance(r);
    transmittance = r.transmittance;
    return r.radiance + r.transmittance * environmentRadiance(dir);
}

vec3 integrateViewRay(vec3 origin, vec3 dir, EK_OUT(vec3) transmittance) {
    return integrateViewRayOf(origin, dir, curvedRays(params), transmittance);
}

// The unit direction of the viewing ray through pixel (px, py)'s centre, row 0 at the top
// (core/camera.h projectToImage is its inverse).
vec3 pixelRayDirection(int px, int py) {
    const float u =
        ((float(px) + 0.5f) / float(params.image.x) * 2.0f - 1.0f) * tanHalfFovX(params);
    const float v = (1.0f - (float(py) + 0.5f) / float(params.image.y) * 2.0f) *
                    tanHalfFovX(params) / imageAspect(params);
    return normalize(vec3(params.cameraForward) + u * vec3(params.cameraRight) +
                     v * vec3(params.cameraUp));
}

// One pixel: a ray through the pixel's centre; rgb radiance, alpha the mean transmittance.
// `curved`: curvedRays(params) (integrateViewRayOf).
vec4 renderPixelOf(int px, int py, bool curved) {
    const vec3 dir = pixelRayDirection(px, py);
    vec3 transmittance;
    const vec3 radiance = integrateViewRayOf(vec3(params.cameraOrigin), dir, curved, transmittance);
    return vec4(radiance, (transmittance.x + transmittance.y + transmittance.z) / 3.0f);
}

vec4 renderPixel(int px, int py) {
    return renderPixelOf(px, py, curvedRays(params));
}

// One channel of a pixel under dispersion (viewChannel(params) = c ≥ 0, params holding channel
// c's refractive indices): the pixel so far (channels before c) with c's radiance and transmittance
// added. Alpha sums the transmittances until the last channel divides: the same operations, in the
// same order, as renderPixel's mean, so equal indices in every channel give renderPixel's bytes.
vec4 renderPixelChannel(int px, int py, vec4 pixel) {
    const int c = viewChannel(params);
    const vec3 dir = pixelRayDirection(px, py);
    vec3 transmittance;
    const vec3 radiance = integrateViewRay(vec3(params.cameraOrigin), dir, transmittance);
    pixel[c] = radiance[c];
    pixel.w = c == 0 ? transmittance[c] : pixel.w + transmittance[c];
    if (c == 2) pixel.w = pixel.w / 3.0f;
    return pixel;
}
