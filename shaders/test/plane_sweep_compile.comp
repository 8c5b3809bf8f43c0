#version 430 core
// Compiles shaders/shared/plane_sweep.h as GLSL (tests/render/test_plane_sweep.cpp): the CPU twin
// runs it as C++, and the GPU port must find it valid GLSL 4.30.
layout(local_size_x = 8, local_size_y = 8) in;

#include "../volume_bindings.glsl"

// The hooks plane_sweep.h calls, declared before it and defined after.
vec4 fetchSweepLight(ivec2 texel);
vec4 fetchSweepDirection(ivec2 texel);
vec4 fetchSweepTrace(ivec2 texel);

#include "../shared/plane_sweep.h"

layout(std430, binding = 0) buffer Sweep { GpuPlaneSweep sweep; };
layout(rgba32f, binding = 0) uniform readonly image2D previousLight;
layout(rgba32f, binding = 1) uniform readonly image2D previousDirection;
layout(rgba32f, binding = 2) uniform image2D traces;
layout(rgba32f, binding = 3) uniform writeonly image2D nextLight;
layout(rgba32f, binding = 4) uniform writeonly image2D nextDirection;

vec4 fetchSweepLight(ivec2 texel) { return imageLoad(previousLight, texel); }
vec4 fetchSweepDirection(ivec2 texel) { return imageLoad(previousDirection, texel); }
vec4 fetchSweepTrace(ivec2 texel) { return imageLoad(traces, texel); }

void main() {
    const ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    // Both passes of a plane, as two dispatches would run them.
    imageStore(traces, t, sweepBackTrace(sweep, t));
    vec4 light, direction;
    sweepAdvance(sweep, t, light, direction);
    imageStore(nextLight, t, light);
    imageStore(nextDirection, t, direction);
}
