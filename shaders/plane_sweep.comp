#version 430 core
// The plane sweep (shaders/shared/plane_sweep.h) on the GPU, one dispatch per pass and plane
// (render/transport/plane_sweep/plane_sweep_gpu.cpp), in the CPU twin's order:
//   EK_SWEEP_PASS_CLEAR    zeroes the output volumes (one dispatch per slice along z; GL 4.3 has
//                          no glClearTexImage);
//   EK_SWEEP_PASS_TRACE    every texel of the new plane traces back to the previous one;
//   EK_SWEEP_PASS_ADVANCE  every texel takes its light and direction from there;
//   EK_SWEEP_PASS_STOP     (scenes with receivers) light whose step crossed a receiver is taken
//                          off the new plane and gathered on the receiver's map in fixed point;
//   EK_SWEEP_PASS_DEPOSIT  on a voxel-centre plane, every texel adds its light to its voxel of the
//                          fluence volumes (one texel per voxel: no two invocations share one, and
//                          lights are added one after the other, in the twin's order).
// The host swaps the light and direction images between planes; an image barrier separates
// dispatches.
layout(local_size_x = 8, local_size_y = 8) in;

// With EK_EXACT_MATH: the CPU twin's float arithmetic (exact_math.glsl).
#ifdef EK_EXACT_MATH
#include "exact_math.glsl"
#endif

#include "volume_bindings.glsl"
#include "fixed_point.glsl"

// The colour channels the sources send (plane_sweep.h): (1, 1, 1), or under dispersion one
// channel's 1 per pass, the pass bending through that channel's ∇n volume.
uniform vec3 sweepChannels;

// The hooks plane_sweep.h calls, declared before it and defined after.
vec4 fetchSweepLight(ivec2 texel);
vec4 fetchSweepDirection(ivec2 texel);
vec4 fetchSweepTrace(ivec2 texel);
void depositSweepReceiver(int mapTexel, vec3 power);

#include "shared/plane_sweep.h"

#define EK_SWEEP_PASS_CLEAR 0
#define EK_SWEEP_PASS_TRACE 1
#define EK_SWEEP_PASS_ADVANCE 2
#define EK_SWEEP_PASS_DEPOSIT 3
#define EK_SWEEP_PASS_STOP 4

uniform int sweepPass;
// The step's GpuPlaneSweep (planeSweepStep on the host), member by member.
uniform ivec4 sweepAxes;
uniform ivec4 sweepPlane;
uniform vec4 sweepPlace;
uniform vec4 sweepLimit;
uniform int depositSlice;  // EK_SWEEP_PASS_DEPOSIT: the volume slice along the sweep axis
// The interleaved view (plane_sweep_view_gpu.cpp): the fluence images are its window of slices,
// texel (u, w) of the plane at layer depositSlice (the slice modulo the slices held), which
// EK_SWEEP_PASS_CLEAR zeroes alone.
uniform int depositWindow;
// The CPU twin's scale of the receivers' sums (planeSweepReceiverScale), in double so that
// value · scale rounds the same way.
uniform double receiverScale;

// The previous plane (the new one, for the deposit), its back-traced points, the new plane.
layout(rgba32f, binding = EK_IMAGE_SWEEP_LIGHT_IN) uniform readonly image2D lightIn;
layout(rgba32f, binding = EK_IMAGE_SWEEP_DIRECTION_IN) uniform readonly image2D directionIn;
layout(rgba32f, binding = EK_IMAGE_SWEEP_TRACE) uniform image2D traces;
layout(rgba32f, binding = EK_IMAGE_SWEEP_LIGHT_OUT) uniform image2D lightOut;
layout(rgba32f, binding = EK_IMAGE_SWEEP_DIRECTION_OUT) uniform writeonly image2D directionOut;
// The output contract's volumes (render/light_transport.h).
layout(rgba32f, binding = EK_IMAGE_SWEEP_FLUENCE) uniform image3D fluenceOut;
layout(rgba32f, binding = EK_IMAGE_SWEEP_FLUENCE_DIRECTION) uniform image3D fluenceDirectionOut;
// Texels whose light was lost (their trace's z is 0), summed over the run.
layout(std430, binding = EK_SSBO_SWEEP_COUNTERS) buffer SweepCounters { uint texelsLost; };
// Per receiver map texel 3 int64 sums (r, g, b) as (low, high) word pairs (fixed_point.glsl).
layout(std430, binding = EK_SSBO_SWEEP_RECEIVER_SUMS) buffer SweepReceiverSums {
    uint receiverSums[];
};

vec4 fetchSweepLight(ivec2 texel) { return imageLoad(lightIn, texel); }
vec4 fetchSweepDirection(ivec2 texel) { return imageLoad(directionIn, texel); }
vec4 fetchSweepTrace(ivec2 texel) { return imageLoad(traces, texel); }
void depositSweepReceiver(int mapTexel, vec3 power) {
    for (int c = 0; c < 3; ++c) {
        const uvec2 f = toFixed(power[c], receiverScale);
        EK_ADD_FIXED(receiverSums, mapTexel * 6 + 2 * c, f);
    }
}

void main() {
    const ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (sweepPass == EK_SWEEP_PASS_CLEAR) {
        const ivec3 v = depositWindow != 0 ? ivec3(t, depositSlice)
                                           : ivec3(t, int(gl_GlobalInvocationID.z));
        if (any(greaterThanEqual(v, depositWindow != 0 ? imageSize(fluenceOut)
                                                       : volumeResolution())))
            return;
        imageStore(fluenceOut, v, vec4(0.0f));
        imageStore(fluenceDirectionOut, v, vec4(0.0f));
        return;
    }
    const GpuPlaneSweep s = GpuPlaneSweep(sweepAxes, sweepPlane, sweepPlace, sweepLimit);
    if (t.x >= s.plane.z || t.y >= s.plane.w) return;
    if (sweepPass == EK_SWEEP_PASS_TRACE) {
        const vec4 traced = sweepBackTrace(s, t);
        imageStore(traces, t, traced);
        if (!(traced.z > 0.0f)) atomicAdd(texelsLost, 1u);
    } else if (sweepPass == EK_SWEEP_PASS_ADVANCE) {
        vec4 light, direction;
        sweepAdvance(s, t, light, direction);
        imageStore(lightOut, t, light);
        imageStore(directionOut, t, direction);
    } else if (sweepPass == EK_SWEEP_PASS_STOP) {
        vec4 light = imageLoad(lightOut, t);
        sweepStopOnReceivers(s, t, light);
        imageStore(lightOut, t, light);
    } else {
        vec3 fluence, weighted;
        if (!sweepDepositTexel(s, imageLoad(lightIn, t), imageLoad(directionIn, t), fluence,
                               weighted))
            return;
        ivec3 v;
        v[s.axes.x] = depositSlice;
        v[s.axes.y] = t.x;
        v[s.axes.z] = t.y;
        if (depositWindow != 0) v = ivec3(t, depositSlice);
        imageStore(fluenceOut, v, imageLoad(fluenceOut, v) + vec4(fluence, 0.0f));
        imageStore(fluenceDirectionOut, v, imageLoad(fluenceDirectionOut, v) + vec4(weighted, 0.0f));
    }
}
