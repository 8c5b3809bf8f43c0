#version 430 core
// Turns the photon pass's fixed-point deposits into float volumes (render/transport/photons/photon_radiance_gpu.cpp)
// the way the CPU twin does: value = float(double(q) / scale), q the int64 sum. double(q) is
// built from its (low, high) words as high·2^32 + low: both terms are exact doubles, so their sum
// rounds once, like the CPU's int64 → double conversion.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "shared/bindings.h"

// Per voxel (x fastest) 6 int64 sums as (low, high) word pairs: r, g, b, then the weighted
// direction x, y, z (shaders/photon_trace.comp).
layout(std430, binding = EK_SSBO_PHOTON_DEPOSITS) readonly buffer DepositBlock { uint deposits[]; };
layout(rgba32f, binding = EK_IMAGE_PHOTON_RADIANCE_RAW) writeonly uniform image3D radianceOut;
layout(rgba32f, binding = EK_IMAGE_PHOTON_DIRECTION_RAW) writeonly uniform image3D directionOut;
uniform ivec3 resolution;
uniform dvec4 depositScale;  // rgb: flux·length channels; w: weighted direction (0: no photons)

float fromFixed(int at, double scale) {
    if (scale <= 0.0LF) return 0.0f;
    const double q = double(int(deposits[at + 1])) * 4294967296.0LF + double(deposits[at]);
    return float(q / scale);
}

void main() {
    const ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, resolution))) return;
    const int base = ((v.z * resolution.y + v.y) * resolution.x + v.x) * 12;
    vec4 radiance = vec4(0.0f);
    vec4 direction = vec4(0.0f);
    for (int c = 0; c < 3; ++c) {
        radiance[c] = fromFixed(base + 2 * c, depositScale[c]);
        direction[c] = fromFixed(base + 6 + 2 * c, depositScale.w);
    }
    imageStore(radianceOut, v, radiance);
    imageStore(directionOut, v, direction);
}
