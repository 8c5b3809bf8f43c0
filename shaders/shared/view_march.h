// The straight-ray viewing pass: emission, absorption and single scattering of every light with
// its transmittance (shadowing) taken from the light volume (light_volume.h) or, as reference,
// marched toward the light from every sample (like vdb_render). Needs optics.h.

// Integral of e^(−κ s) over a step of length s: (1 − e^(−κ s)) / κ, and s as κ → 0.
float stepWeight(float kappa, float s) {
    return kappa * s > 1e-5f ? (1.0f - exp(-kappa * s)) / kappa : s * (1.0f - 0.5f * kappa * s);
}

// Radiance reaching the camera along a ray, and the ray's transmittance through the volume.
vec3 integrateViewRay(vec3 origin, vec3 dir, EK_OUT(vec3) transmittance) {
    transmittance = vec3(1.0f);
    vec3 radiance = vec3(0.0f);
    const vec2 span = intersectVolume(origin, dir);
    const float h = params.volumeMin.w;
    const int steps = span.x < span.y ? min(int(ceil((span.y - span.x) / h)), EK_MAX_STEPS) : 0;
    for (int i = 0; i < steps; ++i) {
        const float t0 = span.x + float(i) * h;
        const float t1 = min(t0 + h, span.y);
        const float s = t1 - t0;
        const vec3 x = origin + dir * (0.5f * (t0 + t1));
        const vec3 p = worldToVolumeIndex(x);

        vec3 kappa = vec3(0.0f);
        vec3 source = vec3(0.0f);
        // Per-material scattering, kept for the phase function of each light below.
        vec3 sigma[EK_MAX_MATERIALS];
        float field[EK_MAX_MATERIALS];
        bool scatters = false;
        for (int m = 0; m < params.resolution.w; ++m) {
            field[m] = sampleField(params.materials[m].slot.x, p);
            sigma[m] = field[m] * vec3(params.materials[m].scattering);
            kappa += field[m] * vec3(params.materials[m].absorption) + sigma[m];
            source += field[m] * vec3(params.materials[m].emission);
            scatters = scatters || field[m] * (params.materials[m].scattering.x +
                                               params.materials[m].scattering.y +
                                               params.materials[m].scattering.z) > 0.0f;
        }
        if (scatters) {
            for (int l = 0; l < params.image.z; ++l) {
                vec3 toLight;
                float lightDistance;
                const vec3 irradiance = lightIrradiance(l, x, toLight, lightDistance);
                if (irradiance.x + irradiance.y + irradiance.z <= 0.0f) continue;
                // Light travels along −toLight and scatters toward the camera, along −dir.
                const float cosTheta = dot(-toLight, -dir);
                vec3 scattered = vec3(0.0f);
                for (int m = 0; m < params.resolution.w; ++m)
                    scattered += sigma[m] * phaseHG(params.materials[m].absorption.w, cosTheta);
                vec3 shadow;
                if (params.image.w == EK_SHADOWS_MARCHED)
                    shadow = transmittanceToward(x, toLight, lightDistance);
                else
                    shadow = vec3(sampleVolume(EK_MAX_MATERIALS + l, p));
                source += scattered * irradiance * shadow;
            }
        }
        radiance += transmittance * source *
                    vec3(stepWeight(kappa.x, s), stepWeight(kappa.y, s), stepWeight(kappa.z, s));
        transmittance *= exp(-kappa * s);
        if (max(max(transmittance.x, transmittance.y), transmittance.z) < params.background.w) {
            transmittance = vec3(0.0f);  // what is left is below the cut-off the scene set
            break;
        }
    }
    return radiance + transmittance * vec3(params.background);
}

// One pixel: a ray through the pixel's centre; rgb radiance, alpha the mean transmittance.
vec4 renderPixel(int px, int py) {
    const float u = ((float(px) + 0.5f) / float(params.image.x) * 2.0f - 1.0f) *
                    params.cameraOrigin.w;
    const float v = (1.0f - (float(py) + 0.5f) / float(params.image.y) * 2.0f) *
                    params.cameraOrigin.w / params.cameraRight.w;
    const vec3 dir = normalize(vec3(params.cameraForward) + u * vec3(params.cameraRight) +
                               v * vec3(params.cameraUp));
    vec3 transmittance;
    const vec3 radiance = integrateViewRay(vec3(params.cameraOrigin), dir, transmittance);
    return vec4(radiance, (transmittance.x + transmittance.y + transmittance.z) / 3.0f);
}
