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

// Henyey–Greenstein phase function, normalised over the sphere; cosTheta is the cosine between
// the direction light travels and the direction it scatters into.
float phaseHG(float g, float cosTheta) {
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

vec3 extinctionAt(vec3 indexPos) {
    vec3 kappa = vec3(0.0f);
    for (int m = 0; m < materialCount(params); ++m) {
        const float f = sampleField(materialSlot(params.materials[m]), indexPos);
        kappa += f * (vec3(params.materials[m].absorption) + vec3(params.materials[m].scattering));
    }
    return kappa;
}

// The largest channel of the extinction at the centre of `voxel` (the octree's κ ranges,
// octree.h), by the sum extinctionAt takes.
float voxelExtinctionMax(ivec3 voxel) {
    vec3 kappa = vec3(0.0f);
    for (int m = 0; m < materialCount(params); ++m) {
        const float f = fetchVolume(materialSlot(params.materials[m]), voxel).x;
        kappa += f * (vec3(params.materials[m].absorption) + vec3(params.materials[m].scattering));
    }
    return max(kappa.x, max(kappa.y, kappa.z));
}

// exp(−∫κ) from x toward a light, up to `maxDistance` or the volume's edge.
vec3 transmittanceToward(vec3 x, vec3 toLight, float maxDistance) {
    const float tEnd = min(intersectVolume(x, toLight).y, maxDistance);
    const float h = shadowStep(params);
    const int steps = min(int(ceil(max(tEnd, 0.0f) / h)), EK_MAX_STEPS);
    vec3 tau = vec3(0.0f);
    for (int i = 0; i < steps; ++i) {
        const float t0 = float(i) * h;
        const float t1 = min(t0 + h, tEnd);
        tau += extinctionAt(worldToVolumeIndex(x + toLight * (0.5f * (t0 + t1)))) * (t1 - t0);
        if (min(min(tau.x, tau.y), tau.z) > 30.0f) break;  // e^-30: nothing gets through
    }
    return exp(-tau);
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
