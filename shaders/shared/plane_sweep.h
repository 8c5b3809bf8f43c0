// Plane-by-plane semi-Lagrangian light propagation (Magnus's thesis, ch. 4.2; docs/methods.md
// `plane_sweep`), the same on the GPU and in the CPU twin
// (render/transport/plane_sweep/plane_sweep_cpu.cpp).
//
// Light lives in a 2D buffer that advances plane by plane through the volume. A texel stores the
// light's irradiance on the plane (rgb, power per area of the plane) and its direction
// v = n dx/ds. To advance from plane i−1 to plane i, every texel p of plane i looks *back* along
// the light's direction to the point q where its ray crossed plane i−1 (sweepBackTrace), reads
// light and direction there bilinearly (sweepFetch), and then (sweepAdvance):
//   - attenuates by exp(−σ̄_t Δs) over the part of the step q → p inside the volume, σ̄_t the
//     trapezoid mean of the extinction at its ends (thesis eq. 4.4, its (1 − α)·m, with the
//     medium's own σ_t per channel);
//   - bends: v_i = v(q) + Δs ∇n(midpoint) (eq. 4.5, the ray equation's step);
//   - corrects the intensity by the intensity law (eqs. 4.6-4.8): the power that crossed plane
//     i−1 through the footprint S_{i−1} of the texel's back-traced neighbours now crosses the
//     texel's own area S_i, so the irradiance is multiplied by S_{i−1}/S_i. The thesis took S from
//     fragment derivatives |∂p/∂x|·|∂p/∂y|; here it is the parallelogram |∂q/∂u × ∂q/∂w| of the
//     neighbours' back-traced points (central differences, one-sided at the buffer's edge or next
//     to a texel whose light was lost), which stays right under shear. Without the correction
//     the scheme only moves light around: a converging beam narrows but does not brighten.
//
// The back-trace is a fixed point: start from the direction light had at the texel's (u, w) on
// plane i−1, find q, then take the direction the ray had at q plus half its bend over the segment
// (the midpoint of the step the forward update takes) and find q again: place.w refinements.
//
// Planes are the volume's slices along a sweep axis (the light volumes' sweep, light_volume.h,
// generalized): texel (a, b) of the plane at axis position c (index units) sits at index point
// [axis] = c, [u] = a + 1/2, [w] = b + 1/2. A plane before the first (the volume's face) and
// taps outside the buffer read the light as it arrives unobstructed (lightIrradiance), so light
// entering through a side face is the source's. Light whose direction comes within minCos of
// the planes (|v̂ · axis| ≤ minCos) cannot be carried by a sweep: it is lost, its texel marked.
// Light is held finite past a focus, where the sweep cannot follow it (sweepAdvance).
//
// Receivers (receivers.h) stop light: a texel whose step crosses one has its light taken off the
// buffer there, and a plane receiver's front face gathers it (sweepStopOnReceivers; the includer
// sums the power in fixed point, so the order of the additions does not matter).
//
// Needs sampling.h, optics.h, receivers.h and ray_equation.h, and from the includer:
//   vec4 fetchSweepLight(ivec2 texel)      the previous plane's light (rgb)
//   vec4 fetchSweepDirection(ivec2 texel)  the previous plane's direction (xyz: v; w: 1 if lit)
//   vec4 fetchSweepTrace(ivec2 texel)      this plane's back-traced points (sweepBackTrace)
//   void depositSweepReceiver(int mapTexel, vec3 power)  adds power to a receiver map texel
//                                          (fixed point on both sides: any order, same sums)
//   vec3 sweepChannels                     the colour channels the light sources send (1 each;
//                                          under dispersion one channel's 1 per pass, the pass
//                                          bending through that channel's ∇n volume:
//                                          render/transport/channel_passes.h). Every step after
//                                          the source is channel by channel, so the other
//                                          channels stay 0 and the kept one is, bit for bit,
//                                          the sweep of that channel's n.
//
// The GPU runs it in shaders/plane_sweep.comp, a dispatch per pass and plane
// (render/transport/plane_sweep/plane_sweep_gpu.cpp).

#ifndef EIKON_SHARED_PLANE_SWEEP_TYPES_H
#define EIKON_SHARED_PLANE_SWEEP_TYPES_H

#define EK_SWEEP_CORRECT_INTENSITY 1  // GpuPlaneSweep.plane.y: the intensity law on
#define EK_SWEEP_PREVIOUS_STORED 2    // GpuPlaneSweep.plane.y: the previous plane is a buffer
// A footprint that shrinks more than fourfold between two planes is at a caustic, where the
// intensity law's E → ∞: the step is held at fourfold.
#define EK_SWEEP_MAX_AREA_RATIO 4.0f
// A footprint covers at most this many map texels along an axis: a receiver has at most 8 texels
// per voxel edge (core/scene_receivers.cpp), and a voxel wide footprint straddles one more.
#define EK_SWEEP_MAX_FOOTPRINT_TEXELS 10

// One plane's step of one light's sweep; only ivec4/vec4 members (std430 and C++ agree).
struct GpuPlaneSweep {
    ivec4 axes;   // x: the sweep axis; y, z: the plane's u and w axes; w: +1 sweeping toward +axis
    ivec4 plane;  // x: the light; y: EK_SWEEP_* flags; z: plane size along u; w: along w
    vec4 place;   // x: this plane's axis position (index units); y: the previous plane's;
                  // z: minCos; w: back-trace refinements
    vec4 limit;   // x: the most irradiance a texel may hold (sweepAdvance); y, z: the soft
                  // light's kernel offset along u and w (texels; 0, 0: a single direction);
                  // w: 0
};

#endif

#ifndef EK_PLANE_SWEEP_TYPES_ONLY

// Index-space point of texel t on the plane at axis position c.
vec3 sweepPoint(GpuPlaneSweep s, vec2 t, float c) {
    vec3 p = vec3(0.0f);
    p[s.axes.x] = c;
    p[s.axes.y] = t.x;
    p[s.axes.z] = t.y;
    return p;
}

vec3 indexToWorld(vec3 indexPos) {
    return vec3(params.volumeMin) + indexPos * volumeVoxelSize();
}

// The light as it arrives unobstructed at index point q: irradiance on a plane of the sweep
// (rgb) and direction v (|v| = n there); nothing where it would cross the plane backward.
void sweepSourceLight(GpuPlaneSweep s, vec3 q, EK_OUT(vec3) light, EK_OUT(vec3) v) {
    const vec3 x = indexToWorld(q);
    vec3 toLight;
    float distance;
    const vec3 irradiance = lightIrradiance(s.plane.x, x, toLight, distance);
    const float cosine = -float(s.axes.w) * toLight[s.axes.x];
    v = -toLight * gradientAt(x).w;
    // The mask last: × 1 keeps the bits of a sweep without dispersion.
    light = cosine > 0.0f ? irradiance * cosine * sweepChannels : vec3(0.0f);
}

// One tap of the previous plane: the buffer's texel, or the source's light outside it.
void sweepTap(GpuPlaneSweep s, ivec2 t, EK_OUT(vec3) light, EK_OUT(vec3) v) {
    const bool stored = (s.plane.y & EK_SWEEP_PREVIOUS_STORED) != 0;
    if (stored && t.x >= 0 && t.y >= 0 && t.x < s.plane.z && t.y < s.plane.w) {
        light = vec3(fetchSweepLight(t));
        v = vec3(fetchSweepDirection(t));
        return;
    }
    sweepSourceLight(s, sweepPoint(s, vec2(t) + vec2(0.5f), s.place.y), light, v);
}

// Light and direction on the previous plane at its point (u, w), bilinear between texel centres.
// Directions are interpolated whether or not light comes with them: the field of directions is
// that of the rays, lit or not. (Weighting them by the light they carry was tried: it pulls a
// converging beam's edge toward its brighter middle, and below a ball lens a narrow beam's
// on-axis E came out 40 % low, 18 % low with only dark taps left out; docs/methods.md.)
void sweepFetch(GpuPlaneSweep s, vec2 q, EK_OUT(vec3) light, EK_OUT(vec3) v) {
    const vec2 c = q - vec2(0.5f);
    const vec2 base = floor(c);
    const vec2 f = c - base;
    const ivec2 t = ivec2(base);
    vec3 l00, l10, l01, l11, v00, v10, v01, v11;
    sweepTap(s, t, l00, v00);
    sweepTap(s, t + ivec2(1, 0), l10, v10);
    sweepTap(s, t + ivec2(0, 1), l01, v01);
    sweepTap(s, t + ivec2(1, 1), l11, v11);
    light = mix(mix(l00, l10, f.x), mix(l01, l11, f.x), f.y);
    v = mix(mix(v00, v10, f.x), mix(v01, v11, f.x), f.y);
}

// Where texel t's ray crossed the previous plane: xy its (u, w), z 1 (0: the light was lost,
// travelling within minCos of the plane).
vec4 sweepBackTrace(GpuPlaneSweep s, ivec2 t) {
    const vec3 h = volumeVoxelSize();
    const int axis = s.axes.x;
    const vec3 p = sweepPoint(s, vec2(t) + vec2(0.5f), s.place.x);
    const float stepAxis = (s.place.x - s.place.y) * h[axis];  // signed, world units
    // First guess: the direction light had on the previous plane at the texel's own (u, w).
    vec3 v;
    vec3 light;
    sweepFetch(s, vec2(t) + vec2(0.5f), light, v);
    vec3 q = p;
    const int refinements = int(s.place.w);
    for (int i = 0; i <= refinements; ++i) {
        const float along = v[axis] * sign(stepAxis);
        if (!(along > s.place.z * length(v))) return vec4(0.0f);
        q = p - v * (stepAxis / v[axis]) / h;
        q[axis] = s.place.y;
        if (i == refinements) break;
        vec3 vq;
        sweepFetch(s, vec2(q[s.axes.y], q[s.axes.z]), light, vq);
        const vec3 segment = (p - q) * h;
        v = vq + (0.5f * length(segment)) * vec3(gradientAt(indexToWorld(0.5f * (p + q))));
    }
    return vec4(q[s.axes.y], q[s.axes.z], 1.0f, 0.0f);
}

// The back-traced point of neighbour t + offset, if it is on the plane and lit.
bool sweepNeighbourTrace(GpuPlaneSweep s, ivec2 t, EK_OUT(vec2) q) {
    if (t.x < 0 || t.y < 0 || t.x >= s.plane.z || t.y >= s.plane.w) return false;
    const vec4 traced = fetchSweepTrace(t);
    q = vec2(traced);
    return traced.z > 0.0f;
}

// ∂q/∂(texel) along one plane axis at texel t: central where both neighbours are lit, one-sided
// where one is; false where neither is.
bool sweepFootprintEdge(GpuPlaneSweep s, ivec2 t, ivec2 step, vec2 q, EK_OUT(vec2) edge) {
    vec2 qPlus = vec2(0.0f);
    vec2 qMinus = vec2(0.0f);
    const bool plus = sweepNeighbourTrace(s, t + step, qPlus);
    const bool minus = sweepNeighbourTrace(s, t - step, qMinus);
    if (plus && minus)
        edge = 0.5f * (qPlus - qMinus);
    else if (plus)
        edge = qPlus - q;
    else if (minus)
        edge = q - qMinus;
    return plus || minus;
}

// S_{i−1}/S_i for texel t (S_i is one texel): the area, in texels, of the parallelogram its
// neighbours' back-traced points span on the previous plane; 1 where it cannot be told.
float sweepAreaRatio(GpuPlaneSweep s, ivec2 t, vec2 q) {
    vec2 du = vec2(0.0f);
    vec2 dw = vec2(0.0f);
    if (!sweepFootprintEdge(s, t, ivec2(1, 0), q, du) ||
        !sweepFootprintEdge(s, t, ivec2(0, 1), q, dw))
        return 1.0f;
    return min(abs(du.x * dw.y - du.y * dw.x), EK_SWEEP_MAX_AREA_RATIO);
}

// exp(−∫σ_t) from index point q to p by the trapezoid rule over the part of the segment inside
// the volume's box: light that entered through a side face met no medium before it.
vec3 sweepSegmentTransmittance(vec3 q, vec3 p) {
    const vec3 h = volumeVoxelSize();
    const vec3 from = indexToWorld(q);
    const vec3 segment = (p - q) * h;
    const vec2 range = intersectVolume(from, segment);  // in fractions of the segment
    const float t0 = clamp(range.x, 0.0f, 1.0f);
    const float t1 = clamp(range.y, 0.0f, 1.0f);
    if (!(t1 > t0)) return vec3(1.0f);
    const vec3 a = mix(q, p, t0);
    const vec3 b = mix(q, p, t1);
    return exp(-0.5f * (extinctionAt(a) + extinctionAt(b)) * ((t1 - t0) * length(segment)));
}

// Texel t of the new plane: light (rgb: irradiance on the plane) and direction (xyz: v; w: 1 if
// lit, 0 if lost).
void sweepAdvance(GpuPlaneSweep s, ivec2 t, EK_OUT(vec4) light, EK_OUT(vec4) direction) {
    const vec4 traced = fetchSweepTrace(t);
    if (!(traced.z > 0.0f)) {
        light = vec4(0.0f);
        direction = (s.plane.y & EK_SWEEP_PREVIOUS_STORED) != 0
                        ? vec4(vec3(fetchSweepDirection(t)), 0.0f)
                        : vec4(0.0f);
        return;
    }
    const vec2 q2 = vec2(traced);
    vec3 lightQ, vq;
    sweepFetch(s, q2, lightQ, vq);
    const vec2 soft = vec2(s.limit.y, s.limit.z);
    if (soft.x != 0.0f || soft.y != 0.0f) {
        // A light with a disc: the incremental convolution (thesis §4.2 after Patel et al. 2013),
        // three equal taps along an offset the host turns by the golden angle each plane, so
        // that every shadow and caustic already in the buffer spreads a little more each plane
        // (planeSweepStep sizes the kernel; docs/methods.md#soft-distant-lights). Only the light
        // is spread: the directions stay the rays'.
        vec3 plus, minus, vPlus, vMinus;
        sweepFetch(s, q2 + soft, plus, vPlus);
        sweepFetch(s, q2 - soft, minus, vMinus);
        lightQ = (lightQ + plus + minus) * (1.0f / 3.0f);
    }
    const vec3 h = volumeVoxelSize();
    const vec3 p = sweepPoint(s, vec2(t) + vec2(0.5f), s.place.x);
    const vec3 q = sweepPoint(s, q2, s.place.y);
    const float ds = length((p - q) * h);
    const vec3 bend = ds * vec3(gradientAt(indexToWorld(0.5f * (p + q))));
    const float ratio =
        (s.plane.y & EK_SWEEP_CORRECT_INTENSITY) != 0 ? sweepAreaRatio(s, t, q2) : 1.0f;
    // Past a focus the sweep's rays do not cross (one direction per texel), so the light there
    // would go on concentrating plane after plane: held below limit.x, all the light that can
    // enter the volume in one texel, it stays finite.
    light = vec4(min(lightQ * sweepSegmentTransmittance(q, p) * ratio, vec3(s.limit.x)), 0.0f);
    direction = vec4(vq + bend, 1.0f);
}

// Whether texel t's step from the previous plane crosses a receiver: its index (−1: none), and
// for a plane receiver's front face the map coordinate where the light lands (receivers.h);
// front is false for a back face or a voxel receiver, whose light stops ungathered. beyond is the
// transmittance from the receiver on to the plane, which the texel's light already carries.
int sweepReceiverHit(GpuPlaneSweep s, ivec2 t, EK_OUT(vec2) mapCoord, EK_OUT(bool) front,
                     EK_OUT(vec3) beyond) {
    mapCoord = vec2(0.0f);
    front = false;
    beyond = vec3(1.0f);
    const vec4 traced = fetchSweepTrace(t);
    if (!(traced.z > 0.0f) || receiverCount(params) == 0) return -1;
    const vec3 a = indexToWorld(sweepPoint(s, vec2(traced), s.place.y));
    const vec3 b = indexToWorld(sweepPoint(s, vec2(t) + vec2(0.5f), s.place.x));
    float fraction;
    bool fromFront;
    const int r = receiverCrossing(a, b, fraction, fromFront);
    if (r < 0) return -1;
    front = fromFront && receiverKind(params.receivers[r]) == EK_RECEIVER_PLANE;
    const vec3 hit = receiverHitPoint(r, a, b, fraction);
    mapCoord = receiverMapCoord(r, hit);
    beyond = sweepSegmentTransmittance(worldToVolumeIndex(hit),
                                       sweepPoint(s, vec2(t) + vec2(0.5f), s.place.x));
    return r;
}

// The share of map texel i (covering [i, i + 1)) in a footprint [lo, hi) along one map axis.
float sweepFootprintShare(float lo, float hi, int i) {
    return (min(hi, float(i + 1)) - max(lo, float(i))) / (hi - lo);
}

// Takes texel t's light (the new plane's) off where its step crossed a receiver, and gives what
// reaches a plane receiver's front face to its map: the texel's power (irradiance on the plane ×
// the texel's area). On a receiver across the sweep axis (its map's axes are the plane's) the
// power is spread over the texel's own footprint, a voxel square around where it lands, so
// uniform light gives a uniform map whatever the map's texels per voxel; on one along the sweep
// axis it is splatted bilinearly at the landing point. What falls outside the map falls outside
// the volume's box: it is not gathered.
void sweepStopOnReceivers(GpuPlaneSweep s, ivec2 t, EK_INOUT(vec4) light) {
    vec2 coord;
    bool front;
    vec3 beyond;
    const int r = sweepReceiverHit(s, t, coord, front, beyond);
    if (r < 0) return;
    const vec3 h = volumeVoxelSize();
    // The light as it reached the receiver, not as it would have reached the plane.
    const vec3 power = vec3(light) / max(beyond, vec3(1e-30f)) * (h[s.axes.y] * h[s.axes.z]);
    light = vec4(0.0f);
    if (!front) return;
    const GpuReceiver receiver = params.receivers[r];
    if (receiverAxis(receiver) != s.axes.x) {
        ivec4 index;
        vec4 weight;
        receiverBilinear(r, coord, index, weight);
        for (int c = 0; c < 4; ++c) depositSweepReceiver(index[c], power * weight[c]);
        return;
    }
    const int width = receiverMapWidth(receiver);
    const int height = receiverMapHeight(receiver);
    const int start = receiverMapStart(receiver);
    // Half the texel's extent in map texels along the map's u and w.
    const vec2 halfExtent =
        vec2(0.5f * float(width) / float(s.plane.z), 0.5f * float(height) / float(s.plane.w));
    const vec2 lo = coord - halfExtent;
    const vec2 hi = coord + halfExtent;
    const ivec2 first = ivec2(floor(lo));
    const ivec2 last =
        min(ivec2(ceil(hi)) - ivec2(1), first + ivec2(EK_SWEEP_MAX_FOOTPRINT_TEXELS - 1));
    for (int w = max(first.y, 0); w <= min(last.y, height - 1); ++w)
        for (int u = max(first.x, 0); u <= min(last.x, width - 1); ++u)
            depositSweepReceiver(
                start + w * width + u,
                power * (sweepFootprintShare(lo.x, hi.x, u) * sweepFootprintShare(lo.y, hi.y, w)));
}

// What a texel of a voxel-centre plane adds to that voxel of the output contract's volumes: the
// fluence (rgb: the irradiance on the plane over cos θ, times the voxel volume, the photons'
// Σ flux·length) and its luminance times the light's unit direction. False where the texel holds
// no light direction.
bool sweepDepositTexel(GpuPlaneSweep s, vec4 light, vec4 direction, EK_OUT(vec3) fluence,
                       EK_OUT(vec3) weightedDirection) {
    fluence = vec3(0.0f);
    weightedDirection = vec3(0.0f);
    const vec3 h = volumeVoxelSize();
    const float voxelVolume = h.x * h.y * h.z;
    const vec3 v = vec3(direction);
    const float speed = length(v);
    if (direction.w <= 0.0f || !(speed > 0.0f)) return false;
    const float cosine = abs(v[s.axes.x]) / speed;
    fluence = vec3(light) * (voxelVolume / cosine);
    const float luminance = dot(fluence, vec3(0.2126f, 0.7152f, 0.0722f));
    weightedDirection = luminance * v / speed;
    return true;
}

#endif
