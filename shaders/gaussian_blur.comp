#version 430 core
// One axis of the separable Gaussian blur of an R32F volume (shaders/shared/gaussian_blur.h).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "shared/bindings.h"

layout(r32f, binding = EK_IMAGE_BLUR_SOURCE) readonly uniform image3D source;
layout(r32f, binding = EK_IMAGE_BLUR_TARGET) writeonly uniform image3D target;

uniform ivec3 resolution;
uniform int axis;
uniform float sigma;
uniform int radius;

float fetchUnblurred(ivec3 v) { return imageLoad(source, v).x; }

#include "shared/platform.h"
#include "shared/gaussian_blur.h"

void main() {
    const ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, resolution))) return;
    imageStore(target, v, vec4(gaussianBlurAlongAxis(v, resolution, axis, sigma, radius)));
}
