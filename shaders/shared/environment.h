// What a view ray sees once it leaves the volume: the radiance arriving from infinitely far along
// its direction (environmentType(params) picks EK_ENVIRONMENT_*). Up is +y. Needs from the
// includer: the global `params`, EK_PI (optics.h) and `vec4 fetchEnvironment(ivec2 texel)`
// returning a texel of the environment image (texel (0, 0) is the top-left, row 0 looks straight
// up).
//
// Equirectangular mapping of a unit direction d (after the rotation below):
//   u = 0.5 + atan2(d.x, −d.z) / 2π  (0.5: looking along −z, 0.75: +x, 0.25: −x, 0 and 1: +z)
//   v = acos(d.y) / π                (0: straight up, 0.5: the horizon, 1: straight down)
// Texel (i, j) covers u ∈ [i, i+1)/width, v ∈ [j, j+1)/height; lookups filter bilinearly between
// texel centres, wrapping around in u and holding the edge rows in v.

// sin(elevation) below the horizon over which the horizon colour fades into the ground colour:
// a soft edge about 1.1 degrees wide instead of a hard line.
EK_CONST float EK_ENVIRONMENT_GROUND_BLEND = 0.02f;

// a·(1 − t) + b·t written out: exactly a at t = 0 and exactly b at t = 1 on both sides (a driver
// may evaluate mix() as a + t·(b − a), which is not).
vec3 environmentBlend(vec3 a, vec3 b, float t) {
    return a * (1.0f - t) + b * t;
}

// atan2(y, x) in (−π, π] by Cephes' atanf (range reduction to |a| ≤ tan(π/8), then an odd
// polynomial; about 2e-7 relative error): the same few operations on both sides, where the
// GPU's built-in atan and libm's part by 1e-6 radians, which the image's texel gradients magnify
// past 1e-5 of the radiance. 0 at the origin.
float environmentAtan2(float y, float x) {
    const float ax = abs(x);
    const float ay = abs(y);
    const float hi = max(ax, ay);
    if (hi == 0.0f) return 0.0f;
    float a = min(ax, ay) / hi;  // in [0, 1]
    float base = 0.0f;
    if (a > 0.41421356f) {  // tan(π/8): atan(a) = π/4 + atan((a − 1) / (a + 1))
        a = (a - 1.0f) / (a + 1.0f);
        base = 0.25f * EK_PI;
    }
    const float z = a * a;
    float r = base + ((((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z -
                       3.33329491539e-1f) *
                          z * a +
                      a);
    if (ay > ax) r = 0.5f * EK_PI - r;
    if (x < 0.0f) r = EK_PI - r;
    return y < 0.0f ? -r : r;
}

// The gradient sky: horizon to zenith by sqrt(sin(elevation)) (the sky stays bright low down and
// deepens toward the zenith), the ground colour below a short blend under the horizon.
vec3 environmentGradient(vec3 dir) {
    const vec3 horizon = vec3(params.environmentHorizon);
    if (dir.y >= 0.0f) return environmentBlend(horizon, vec3(params.environmentSky), sqrt(dir.y));
    return environmentBlend(horizon, vec3(params.environmentGround),
                            smoothstep(0.0f, EK_ENVIRONMENT_GROUND_BLEND, -dir.y));
}

// The equirectangular image, turned by rotation_deg about +y (its cosine and sine in
// environmentRotationCos/Sin): the image's content moves counter-clockwise seen from above, so the
// lookup turns the view direction the other way.
vec3 environmentImage(vec3 dir) {
    const float c = environmentRotationCos(params);
    const float s = environmentRotationSin(params);
    const vec3 d = vec3(c * dir.x - s * dir.z, dir.y, s * dir.x + c * dir.z);
    // atan2(0, 0) is undefined in GLSL; straight up or down every column meets at the pole.
    const bool pole = d.x == 0.0f && d.z == 0.0f;
    const float u = pole ? 0.5f : 0.5f + environmentAtan2(d.x, -d.z) / (2.0f * EK_PI);
    // acos(d.y), but well conditioned near the poles, where acos turns the last bit of d.y into
    // 3e-4 radians and the GPU and the CPU twin, whose d differ in that bit, would part.
    const float v = environmentAtan2(sqrt(d.x * d.x + d.z * d.z), d.y) / EK_PI;
    const int width = environmentWidth(params);
    const int height = environmentHeight(params);
    const float tx = u * float(width) - 0.5f;
    const float ty = v * float(height) - 0.5f;
    const float bx = floor(tx);
    const float by = floor(ty);
    const float fx = tx - bx;
    const float fy = ty - by;
    // Wrap in u by float arithmetic: GLSL leaves % of a negative int undefined.
    const int x0 = int(bx - float(width) * floor(bx / float(width)));
    const int x1 = x0 + 1 < width ? x0 + 1 : 0;
    const int y0 = clamp(int(by), 0, height - 1);
    const int y1 = clamp(int(by) + 1, 0, height - 1);
    const vec3 top = environmentBlend(vec3(fetchEnvironment(ivec2(x0, y0))),
                                      vec3(fetchEnvironment(ivec2(x1, y0))), fx);
    const vec3 bottom = environmentBlend(vec3(fetchEnvironment(ivec2(x0, y1))),
                                         vec3(fetchEnvironment(ivec2(x1, y1))), fx);
    return environmentBlend(top, bottom, fy);
}

// Radiance arriving along −dir from outside the volume, for a unit direction `dir`.
vec3 environmentRadiance(vec3 dir) {
    if (environmentType(params) == EK_ENVIRONMENT_GRADIENT) return environmentGradient(dir);
    if (environmentType(params) == EK_ENVIRONMENT_IMAGE)
        return environmentIntensity(params) * environmentImage(dir);
    return vec3(params.background);
}
