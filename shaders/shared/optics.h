// Optics of the medium and of the lights, shared by the viewing pass and the light volume passes
// (GPU shaders and CPU twins). Needs sampling.h and, from the includer, `params` and
// `fetchVolume`.
//
// Radiative transfer along a view ray x(t) = o + t·d, per colour channel:
//   L = ∫ T(t) S(x(t)) dt + T(end) · L_background,   T(t) = exp(−∫₀ᵗ κ),
//   S = emission + Σ_lights Σ_materials f_m σ_m p_HG(g_m, cos θ) · E_light · T_light,
// with κ = Σ f_m (σ_m + α_m). Each step takes the optics at its midpoint as constant over the
// step and integrates exactly: ∫ T S over the step = T · S · (1 − e^(−κΔ)) / κ.

EK_CONST float EK_PI = 3.14159265358979f;
EK_CONST int EK_MAX_STEPS = 1 << 20;  // a bound on any march, so no input can hang a pass

// e^(−κs) for each channel. In C++ (the CPU twins) a grey κ, the three channels equal (smoke),
// takes one exp for all three: the same function of the same value, so the same floats, for a
// third of the exps.
vec3 channelDecay(vec3 kappa, float s) {
#ifdef __cplusplus
    if (kappa.x == kappa.y && kappa.x == kappa.z) return vec3(exp(-kappa.x * s));
#endif
    return exp(-kappa * s);
}

// Henyey–Greenstein phase function, normalised over the sphere; cosTheta is the cosine between
// the direction light travels and the direction it scatters into.
float phaseHG(float g, float cosTheta) {
#ifdef __cplusplus
    // C++ (the CPU twins): for g = ±0 and a finite cosine, d below is 1 exactly and the formula
    // gives 1/(4π) as written, the same float, without its root and division. Smoke and fog
    // scatter isotropically, and the view takes this at every step that scatters.
    if (g == 0.0f && std::isfinite(cosTheta)) return 1.0f / (4.0f * EK_PI);
#endif
    const float d = 1.0f + g * g - 2.0f * g * cosTheta;
    return (1.0f - g * g) / (4.0f * EK_PI * d * sqrt(d));
}

// Entry and exit distances of the ray with the volume box; tNear > tFar when it misses.
vec2 intersectVolume(vec3 origin, vec3 dir) {
    vec3 safeDir = dir;
    if (abs(safeDir.x) < 1e-12f) safeDir.x = 1e-12f;
    if (abs(safeDir.y) < 1e-12f) safeDir.y = 1e-12f;
    if (abs(safeDir.z) < 1e-12f) safeDir.z = 1e-12f;
    const vec3 t0 = (vec3(params.volumeMin) - origin) / safeDir;
    const vec3 t1 = (vec3(params.volumeMax) - origin) / safeDir;
    const vec3 tmin = min(t0, t1);
    const vec3 tmax = max(t0, t1);
    return vec2(max(max(tmin.x, tmin.y), max(tmin.z, 0.0f)), min(min(tmax.x, tmax.y), tmax.z));
}

// How much of a clipped material's opacity stays at volume index position `indexPos`: the product,
// over the clip planes set in `mask` (materialClipMask), of each plane's ramp, 1 on the side that
// stays and 0 past the plane, linear across one voxel's extent along the normal (centred on the
// plane: along a ray through it the ramp takes away exactly what a sharp cut would). `reach`
// shifts every ramp by that many of those extents: ±1 bounds the weight anywhere within a voxel of
// `indexPos` along every axis (voxelExtinctionRange). Only opacity reads it: n, ∇n and the
// Fresnel surfaces read the field uncut, so what is cut away still refracts.
float clipWeight(int mask, vec3 indexPos, float reach) {
    float weight = 1.0f;
    for (int k = 0; k < EK_MAX_CLIP_PLANES; ++k) {
        if ((mask & (1 << k)) == 0) continue;
        const vec4 plane = params.clipPlanes[k];
        weight *= clamp(dot(vec3(plane), indexPos) + plane.w + reach, 0.0f, 1.0f);
    }
    return weight;
}

// Material m's field value f at `indexPos` as its opacity sees it: cut by its clip planes.
float clippedField(int m, vec3 indexPos, float f) {
    const int mask = materialClipMask(params.materials[m]);
    return mask == 0 ? f : f * clipWeight(mask, indexPos, 0.0f);
}

// Material m's field at `indexPos` as its opacity sees it: cut by its clip planes.
float opacityField(int m, vec3 indexPos) {
    return clippedField(m, indexPos, sampleField(materialSlot(params.materials[m]), indexPos));
}

// Particle colour (Magnus's thesis: the colour of the light a material's particles scatter and
// emit, apart from the medium colour its absorption gives), read from material m's table
// (core/particle_color.h): linear between its entries, flat beyond either end. Positions t are
// in entries from the first, t = (value − range.x) · range.y.
float particleColorPosition(int m, float value) {
    const vec4 range = params.particleColorRanges[m];
    return (value - range.x) * range.y;
}

// The colour at table position t (NaN: the first entry).
vec3 particleColorAtPosition(int m, float t) {
    const int base = m * EK_PARTICLE_COLOR_TABLE;
    const float last = float(EK_PARTICLE_COLOR_TABLE - 1);
    const float clamped = t > 0.0f ? min(t, last) : 0.0f;
    const int i = min(int(clamped), EK_PARTICLE_COLOR_TABLE - 2);
    return mix(vec3(params.particleColors[base + i]), vec3(params.particleColors[base + i + 1]),
               clamped - float(i));
}

// ∫₀ᵗ colour dt' over table positions: the pre-integration table's entry plus the exact integral
// of the linear piece it is in, and the end colours carried on beyond the table.
vec3 particleColorIntegral(int m, float t) {
    const int base = m * EK_PARTICLE_COLOR_TABLE;
    const int lastEntry = EK_PARTICLE_COLOR_TABLE - 1;
    if (!(t > 0.0f)) return (t > -3.0e38f ? t : 0.0f) * vec3(params.particleColors[base]);
    if (t >= float(lastEntry))
        return vec3(params.particleColorIntegrals[base + lastEntry]) +
               (t - float(lastEntry)) * vec3(params.particleColors[base + lastEntry]);
    const int i = min(int(t), lastEntry - 1);
    const float w = t - float(i);
    const vec3 c0 = vec3(params.particleColors[base + i]);
    const vec3 c1 = vec3(params.particleColors[base + i + 1]);
    return vec3(params.particleColorIntegrals[base + i]) + w * (c0 + (0.5f * w) * (c1 - c0));
}

// Below this span of table positions a step's mean colour is its midpoint's: the same for a
// linear piece, and the difference of two integrals would lose digits (they reach 255 × colour).
EK_CONST float EK_PREINTEGRATION_MIN_SPAN = 0.0625f;

// Material m's particle colour over a view step along which the value it reads runs from `a` to
// `b` through `mid` (pre-integrated: the mean of the colour over [a, b], so a colour band thinner
// than the step is weighed by its width, not hit or missed by the midpoint; `mid` only where the
// span is too short for that).
vec3 particleColorOverStep(int m, float a, float mid, float b) {
    const float ta = particleColorPosition(m, a);
    const float tb = particleColorPosition(m, b);
    if (!(abs(tb - ta) >= EK_PREINTEGRATION_MIN_SPAN))
        return particleColorAtPosition(m, particleColorPosition(m, mid));
    return (particleColorIntegral(m, tb) - particleColorIntegral(m, ta)) / (tb - ta);
}

vec3 extinctionAt(vec3 indexPos) {
    vec3 kappa = vec3(0.0f);
    for (int m = 0; m < materialCount(params); ++m) {
        const float f = opacityField(m, indexPos);
        kappa += f * (vec3(params.materials[m].absorption) + vec3(params.materials[m].scattering));
    }
    return kappa;
}

// The largest channel of the extinction at the centre of `voxel` (the octree's κ ranges,
// octree.h), by the sum extinctionAt takes: x with each clipped material's weight at its lowest
// within a voxel of the centre, y at its highest. Without clip planes both are the value at the
// centre. With them, κ between voxel centres is no longer the trilinear blend of κ at the centres
// (the weight is a function of position, not of the field), so the range over a voxel's
// neighbours would miss the κ a sample between them sees; the two bounds do not: a sample's
// trilinear corners all lie within a voxel of it.
vec2 voxelExtinctionRange(ivec3 voxel) {
    vec3 lo = vec3(0.0f);
    vec3 hi = vec3(0.0f);
    const vec3 centre = vec3(voxel) + vec3(0.5f);
    for (int m = 0; m < materialCount(params); ++m) {
        const float f = fetchVolume(materialSlot(params.materials[m]), voxel).x;
        const vec3 c = vec3(params.materials[m].absorption) + vec3(params.materials[m].scattering);
        const int mask = materialClipMask(params.materials[m]);
        if (mask == 0) {
            lo += f * c;
            hi += f * c;
        } else {
            lo += (f * clipWeight(mask, centre, -1.0f)) * c;
            hi += (f * clipWeight(mask, centre, 1.0f)) * c;
        }
    }
    return vec2(max(lo.x, max(lo.y, lo.z)), max(hi.x, max(hi.y, hi.z)));
}

// How far a shadow step's Simpson and trapezoid sums of κ may differ (optical depth) before the
// step is halved: a sharp extinction edge inside a step makes them differ by a third of its
// jump × the step, a smooth medium by far less. Steps halve down to EK_SHADOW_MIN_STEP_VOXELS.
// 0.01: a sharp slab (τ 2-8) within 0.94% of Beer–Lambert; 0.002 gave 0.26% for 2-6× the light
// stage's time on smoke caches (blender_smoke_sequence 35 → 90 ms per frame at 0.01, CPU twin).
EK_CONST float EK_SHADOW_TAU_TOLERANCE = 0.01f;
EK_CONST float EK_SHADOW_MIN_STEP_VOXELS = 0.125f;

vec3 extinctionAlong(vec3 x, vec3 dir, float t) {
    return extinctionAt(worldToVolumeIndex(x + dir * t));
}

// exp(−∫κ) from x toward a light, up to `maxDistance` or the volume's edge. Simpson's rule over
// steps of shadowStep(params), refined where κ bends: a step whose Simpson and trapezoid sums
// differ by more than EK_SHADOW_TAU_TOLERANCE is halved (its midpoint becomes the new end, so
// nothing is sampled twice), and steps grow back ×2 where the two agree to a quarter of that. A
// sharp slab (τ 8) was 32-78% off at a fixed 3-voxel midpoint step; smooth media keep the
// nominal step.
vec3 transmittanceToward(vec3 x, vec3 toLight, float maxDistance) {
    const float tEnd = min(intersectVolume(x, toLight).y, maxDistance);
    const float hMax = shadowStep(params);
    const vec3 voxel = volumeVoxelSize();
    const float hMin = min(hMax, EK_SHADOW_MIN_STEP_VOXELS * min(voxel.x, min(voxel.y, voxel.z)));
    vec3 tau = vec3(0.0f);
    float t = 0.0f;
    float h = hMax;
    vec3 k0 = extinctionAlong(x, toLight, 0.0f);
    vec3 kEnd = vec3(0.0f);
    bool endKnown = false;  // kEnd holds κ at t + h: the midpoint of a step just halved
    for (int i = 0; i < EK_MAX_STEPS && t < tEnd; ++i) {
        const float s = min(h, tEnd - t);
        const vec3 km = extinctionAlong(x, toLight, t + 0.5f * s);
        const vec3 k1 = endKnown && s == h ? kEnd : extinctionAlong(x, toLight, t + s);
        const vec3 simpson = (s / 6.0f) * (k0 + 4.0f * km + k1);
        const vec3 gap = abs(simpson - 0.5f * s * (k0 + k1));
        const float err = max(gap.x, max(gap.y, gap.z));
        if (err > EK_SHADOW_TAU_TOLERANCE && s > hMin) {
            h = 0.5f * s;
            kEnd = km;
            endKnown = true;
            continue;
        }
        tau += simpson;
        t += s;
        k0 = k1;
        endKnown = false;
        if (err < 0.25f * EK_SHADOW_TAU_TOLERANCE) h = min(2.0f * h, hMax);
        if (min(min(tau.x, tau.y), tau.z) > 30.0f) break;  // e^-30: nothing gets through
    }
    return exp(-tau);
}

// A unit basis (u, w) of the plane perpendicular to unit d. For an axis-aligned d both are exact
// axes, so the photons' light-space grid tiles an axis-aligned box face cell for cell.
void lightPlaneBasis(vec3 d, EK_OUT(vec3) u, EK_OUT(vec3) w) {
    const vec3 helper = abs(d.y) < 0.999f ? vec3(0.0f, 1.0f, 0.0f) : vec3(1.0f, 0.0f, 0.0f);
    u = normalize(cross(helper, d));
    w = cross(d, u);
}

// A directional light's disc for the passes that march toward the light (light volumes, the
// view's marched shadows): its transmittance is the mean over 16 directions of the disc, four
// rings of equal area (radius √((j + ½)/4) of the disc's, j = 0..3), each with four points a
// quarter turn apart, the rings turned by π/8 from one another starting at π/16. The quarter-turn
// symmetry makes the points' mean the disc's centre and their spread the same along every
// direction, the disc's (the variance of its projection on any line, R²/4), so the penumbra
// behind an edge has the disc's width at every depth, in 16 steps. (Vogel's spiral of 16 points
// was tried first: 8 % narrower along one axis than along the other, and off centre by 3 %.)
// No trigonometric built-in, whose rounding differs between drivers: the turns are rotations by
// constants.
EK_CONST int EK_DISC_RINGS = 4;
EK_CONST float EK_DISC_FIRST_COS = 0.9807852804f;  // cos(π/16)
EK_CONST float EK_DISC_FIRST_SIN = 0.1950903220f;  // sin(π/16)
EK_CONST float EK_DISC_TURN_COS = 0.9238795325f;   // cos(π/8)
EK_CONST float EK_DISC_TURN_SIN = 0.3826834324f;   // sin(π/8)

// exp(−∫κ) from x toward light l (unit direction toLight, at lightDistance): one march, or for a
// directional light with a disc the mean of 16 marches over it. One loop with one march in it,
// its count read from the light: a count the compiler knows (a loop per ring, or four calls)
// is unrolled into sixteen copies of the march, and llvmpipe took minutes to compile the light
// volume and view shaders (a cold shader cache: 6 min against 1.9 min for fog_sphere_spot.json).
vec3 lightTransmittance(int l, vec3 x, vec3 toLight, float lightDistance) {
    const GpuLight light = params.lights[l];
    const float versine = lightType(light) == EK_LIGHT_DIRECTIONAL ? lightDiscVersine(light) : 0.0f;
    const bool disc = versine > 0.0f;
    vec3 u = vec3(0.0f);
    vec3 w = vec3(0.0f);
    if (disc) lightPlaneBasis(toLight, u, w);
    const int marches = disc ? 4 * EK_DISC_RINGS : 1;
    vec3 sum = vec3(0.0f);
    float c = EK_DISC_FIRST_COS;  // the ring's first point's angle
    float s = EK_DISC_FIRST_SIN;
    vec3 a = vec3(0.0f);  // the point's offset from the centre, and a quarter turn on
    vec3 b = vec3(0.0f);
    vec3 centre = toLight;
    for (int i = 0; i < marches; ++i) {
        if (disc && i % 4 == 0) {  // a new ring
            // 1 − cos θ at radius fraction ρ is versine·ρ² (even over the cap's area).
            const float v = versine * ((float(i / 4) + 0.5f) / float(EK_DISC_RINGS));
            const float sine = sqrt(v * (2.0f - v));
            a = (sine * c) * u + (sine * s) * w;
            b = (sine * c) * w - (sine * s) * u;
            centre = (1.0f - v) * toLight;
            const float turned = c * EK_DISC_TURN_COS - s * EK_DISC_TURN_SIN;
            s = s * EK_DISC_TURN_COS + c * EK_DISC_TURN_SIN;
            c = turned;
        }
        sum += transmittanceToward(x, disc ? normalize(centre + a) : toLight, lightDistance);
        const vec3 next = b;  // a, b, −a, −b: a quarter turn each
        b = -a;
        a = next;
    }
    return disc ? sum * (1.0f / float(4 * EK_DISC_RINGS)) : sum;
}

// Unshadowed irradiance from light l at x; also the unit direction toward it and its distance.
// A spot light's falloff along unit direction d (travelling away from the light): 1 inside the
// inner cone, 0 outside the outer, smoothstep between, in the versine v = 1 − cos θ =
// |d − axis|² / 2 (exact for small angles, where 1 − dot(d, axis) loses every digit).
// smoothstep(cos θo, cos θi, cos θ) = 1 − smoothstep(vi, vo, v): the same falloff, and its solid
// angle ∫ falloff dΩ = 2π ∫ falloff dv = π (vo + vi).
float spotFalloff(GpuLight light, vec3 d) {
    const vec3 off = d - vec3(light.direction);
    const float v = 0.5f * dot(off, off);
    return 1.0f - smoothstep(lightVersineInner(light), lightVersineOuter(light), v);
}

vec3 lightIrradiance(int l, vec3 x, EK_OUT(vec3) toLight, EK_OUT(float) lightDistance) {
    const GpuLight light = params.lights[l];
    const int type = lightType(light);
    const vec3 radiance = vec3(light.radiance);
    if (type == EK_LIGHT_DIRECTIONAL) {
        toLight = -vec3(light.direction);
        lightDistance = 3.0e38f;
        return radiance;
    }
    const vec3 d = vec3(light.position) - x;
    lightDistance = max(length(d), 1e-6f);
    toLight = d / lightDistance;
    float falloff = 1.0f / (lightDistance * lightDistance);
    if (type == EK_LIGHT_SPOT) falloff *= spotFalloff(light, -toLight);
    return radiance * falloff;
}
