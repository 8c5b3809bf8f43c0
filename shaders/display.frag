#version 430 core
// Shows a linear HDR image through the tone map the PNG writer uses (shaders/shared/tone_map.h).
#include "shared/bindings.h"
#include "shared/platform.h"
#include "shared/tone_map.h"

in vec2 uv;
out vec4 color;

layout(binding = EK_UNIT_DISPLAY_IMAGE) uniform sampler2D image;
uniform float exposureScale;
uniform int toneCurve;  // EK_TONE_*

void main() {
    const vec3 c = texture(image, uv).rgb;
    color = vec4(toneMapChannel(c.r, exposureScale, toneCurve),
                 toneMapChannel(c.g, exposureScale, toneCurve),
                 toneMapChannel(c.b, exposureScale, toneCurve), 1.0f);
}
