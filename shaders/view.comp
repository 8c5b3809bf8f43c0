#version 430 core
// The viewing pass (render/view_pass_gpu.cpp): one invocation per pixel, its ray straight or, when
// curvedRays(params), bent through the ∇n volume (shaders/shared/view_march.h).
layout(local_size_x = 8, local_size_y = 8) in;

#include "volume_bindings.glsl"

// The receiver map (render/receiver_map.h): rgb irradiance per texel of every plane receiver.
layout(std430, binding = EK_SSBO_RECEIVER_MAP) readonly buffer ReceiverMapBlock {
    vec4 receiverTexels[];
};
vec4 fetchReceiverTexel(int index) { return receiverTexels[index]; }

// Every sample is ready: the volumes are whole (the plane sweep's interleaved view, whose are not,
// is view_interleaved.comp).
bool viewSampleReady(vec3 p) { return true; }
// Receivers are shaded where the rays meet them: their maps are complete.
bool receiverDeferred(int r, vec3 x, bool front, vec3 weight) { return false; }

#include "shared/environment.h"
#include "shared/material_index.h"
#include "shared/fresnel.h"
#include "shared/specular.h"
#include "shared/view_march.h"

#ifndef EK_VIEW_PER_CHANNEL
layout(rgba32f, binding = EK_IMAGE_VIEW_OUTPUT) writeonly uniform image2D outImage;

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= params.image.x || p.y >= params.image.y) return;
    imageStore(outImage, p, renderPixel(p.x, p.y));
}
#else
// Dispersion: one dispatch per colour channel (viewChannel(params)), each adding its channel to
// the pixel the one before wrote (renderPixelChannel). A variant of its own, so that the pass
// without dispersion compiles to the code it always had.
layout(rgba32f, binding = EK_IMAGE_VIEW_OUTPUT) uniform image2D outImage;

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= params.image.x || p.y >= params.image.y) return;
    const vec4 before = viewChannel(params) == 0 ? vec4(0.0f) : imageLoad(outImage, p);
    imageStore(outImage, p, renderPixelChannel(p.x, p.y, before));
}
#endif
