#version 430 core
// The plane sweep's interleaved view on the GPU (render/transport/plane_sweep/plane_sweep_view.h,
// plane_sweep_view_gpu.cpp): the CPU twin's renderInterleavedCpu, one dispatch per pass over the
// pixels, every pixel's view ray kept in a buffer between dispatches. Passes:
//   EK_INTERLEAVED_START    every ray starts where it enters the volume (or misses it);
//   EK_INTERLEAVED_ADVANCE  every ray not ended takes the steps whose samples the slices held
//                           complete (view_march.h, curvedRayAdvance / straightRayAdvance);
//   EK_INTERLEAVED_SHADE    the receiver hits whose light is complete are shaded (all of them
//                           with interleavedAll, after the last plane);
//   EK_INTERLEAVED_COMPOSE  every pixel gets what its ray sees where it leaves.
// The fluence units hold the window of slices (volume_bindings.glsl, EK_FLUENCE_WINDOW, which
// the host defines); the exact trilinear path reads them (the slices wrap around). Under
// dispersion each pixel has a ray a colour channel, and the host dispatches each channel's rays
// with its channel's params and ∇n (rayChannel).
layout(local_size_x = 8, local_size_y = 8) in;

#include "volume_bindings.glsl"

#define EK_INTERLEAVED_START 0
#define EK_INTERLEAVED_ADVANCE 1
#define EK_INTERLEAVED_SHADE 2
#define EK_INTERLEAVED_COMPOSE 3

uniform int interleavedPass;
uniform int interleavedAll;  // EK_INTERLEAVED_SHADE: every hit, the receivers' maps complete
// Rays a pixel (3 under dispersion, one a colour channel, each dispatch bound to its channel's
// params and ∇n; else 1), and the channel of this dispatch's rays: ray pixel·rayChannels +
// rayChannel. EK_INTERLEAVED_COMPOSE reads them all.
uniform int rayChannels;
uniform int rayChannel;
// The sweep (the CPU twin's FluenceWindow): toward +axis (order 1) or −axis, slices swept so far.
uniform int windowOrder;
uniform int windowSwept;

layout(std430, binding = EK_SSBO_RECEIVER_MAP) readonly buffer ReceiverMapBlock {
    vec4 receiverTexels[];
};
vec4 fetchReceiverTexel(int index) { return receiverTexels[index]; }

// Samples read from slices already dropped, and view ray steps.
layout(std430, binding = EK_SSBO_INTERLEAVED_COUNTERS) buffer InterleavedCounters {
    uint samplesBehind;
    uint viewSteps;
};

// The CPU twin's viewSampleReady (render/volume_kernels_cpu.h): the two slices a lookup at p
// reads must have been swept; a lookup of a slice dropped is counted.
bool viewSampleReady(vec3 p) {
    const int axis = fluenceWindow.x;
    const int last = params.resolution[axis] - 1;
    const int base = int(floor(p[axis] - 0.5f));
    const int k0 = clamp(base, 0, last);
    const int k1 = clamp(base + 1, 0, last);
    const int r0 = windowOrder > 0 ? k0 : last - k0;
    const int r1 = windowOrder > 0 ? k1 : last - k1;
    if (max(r0, r1) >= windowSwept) return false;
    if (min(r0, r1) < windowSwept - fluenceWindow.y) atomicAdd(samplesBehind, 1u);
    return true;
}

// A receiver hit waiting for its light: x (xyz) and the receiver (w); the ray's transmittance
// there (xyz) and its face (w: 1 front, 0 back). w < 0 in the first: none.
struct InterleavedHit {
    vec4 place;
    vec4 weight;
};
layout(std430, binding = EK_SSBO_INTERLEAVED_HITS) buffer InterleavedHits {
    InterleavedHit hits[];
};
int currentRay = 0;  // the ray receiverDeferred is called for
bool receiverDeferred(int r, vec3 x, bool front, vec3 weight) {
    hits[currentRay].place = vec4(x, float(r));
    hits[currentRay].weight = vec4(weight, front ? 1.0f : 0.0f);
    return true;
}

#include "shared/environment.h"
#include "shared/material_index.h"
#include "shared/fresnel.h"
#include "shared/specular.h"
#include "shared/view_march.h"

// Each pixel's ray, curved or straight (curvedRays(params)): the host binds a buffer of the kind
// in use at EK_SSBO_INTERLEAVED_RAYS; the other kind's block is never touched.
#ifdef EK_INTERLEAVED_CURVED
layout(std430, binding = EK_SSBO_INTERLEAVED_RAYS) buffer InterleavedRays {
    CurvedRay rays[];
};
#else
layout(std430, binding = EK_SSBO_INTERLEAVED_RAYS) buffer InterleavedRays {
    StraightRay rays[];
};
#endif
// Per ray: bit 0 it met the volume, bit 1 it ended.
layout(std430, binding = EK_SSBO_INTERLEAVED_FLAGS) buffer InterleavedFlags {
    uint flags[];
};
layout(rgba32f, binding = EK_IMAGE_VIEW_OUTPUT) writeonly uniform image2D outImage;

void main() {
    const ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (px.x >= params.image.x || px.y >= params.image.y) return;
    const int pixel = px.y * params.image.x + px.x;
    const int i = pixel * rayChannels + rayChannel;
    currentRay = i;
    if (interleavedPass == EK_INTERLEAVED_START) {
        const vec3 origin = vec3(params.cameraOrigin);
        const vec3 dir = pixelRayDirection(px.x, px.y);
        const vec2 span = intersectVolume(origin, dir);
        const bool inVolume = span.x < span.y;
        flags[i] = inVolume ? 1u : 2u;
        hits[i].place = vec4(0.0f, 0.0f, 0.0f, -1.0f);
        if (!inVolume) return;
#ifdef EK_INTERLEAVED_CURVED
        rays[i] = curvedRayStart(origin + dir * span.x, dir, true, 0.0f, 0, vec3(0.0f),
                                 vec3(1.0f));
#else
        rays[i] = straightRayStart(origin, dir, span);
#endif
    } else if (interleavedPass == EK_INTERLEAVED_ADVANCE) {
        if ((flags[i] & 2u) != 0u) return;
#ifdef EK_INTERLEAVED_CURVED
        CurvedRay r = rays[i];
        const int before = r.steps;
        // Reflections at sharp surfaces see the environment: none is kept.
        KeptReflection none, unused;
        none.origin = none.dir = none.weight = vec4(0.0f);
        unused = none;
        const int state = curvedRayAdvance(r, none, unused);
        const int taken = r.steps - before;
#else
        StraightRay r = rays[i];
        const int before = r.step;
        const int state = straightRayAdvance(r);
        const int taken = r.step - before;
#endif
        rays[i] = r;
        if (state == EK_RAY_ENDED) flags[i] |= 2u;
        if (taken > 0) atomicAdd(viewSteps, uint(taken));
    } else if (interleavedPass == EK_INTERLEAVED_SHADE) {
        const vec4 place = hits[i].place;
        if (place.w < 0.0f) return;
        const int receiver = int(place.w);
        const vec3 x = vec3(place);
        if (interleavedAll == 0) {
            if (receiverKind(params.receivers[receiver]) != EK_RECEIVER_VOXELS) return;
            if (!viewSampleReady(worldToVolumeIndex(x) + 1.5f * receiverNormal(receiver))) return;
        }
        const vec4 weight = hits[i].weight;
        rays[i].radiance += vec3(weight) * receiverRadiance(receiver, x, weight.w > 0.5f);
        hits[i].place.w = -1.0f;
    } else {
        // What each ray sees where it leaves (integrateViewRay's last line), alpha the mean
        // transmittance: renderPixel's, or under dispersion renderPixelChannel's, channel by
        // channel in its order of operations.
        vec4 colour = vec4(0.0f);
        for (int c = 0; c < rayChannels; ++c) {
            const int ray = pixel * rayChannels + c;
            vec3 radiance, transmittance;
            if ((flags[ray] & 1u) == 0u) {
                radiance = environmentRadiance(pixelRayDirection(px.x, px.y));
                transmittance = vec3(1.0f);
            } else {
                transmittance = rays[ray].transmittance;
#ifdef EK_INTERLEAVED_CURVED
                radiance =
                    rays[ray].radiance + transmittance * environmentRadiance(rays[ray].exitDir);
#else
                radiance = rays[ray].radiance + transmittance * environmentRadiance(rays[ray].dir);
#endif
            }
            if (rayChannels == 1) {
                colour = vec4(radiance, (transmittance.x + transmittance.y + transmittance.z) / 3.0f);
            } else {
                colour[c] = radiance[c];
                colour.w = c == 0 ? transmittance[c] : colour.w + transmittance[c];
                if (c == 2) colour.w = colour.w / 3.0f;
            }
        }
        imageStore(outImage, px, colour);
    }
}
