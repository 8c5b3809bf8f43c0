#version 430 core
// Shows a linear HDR image: exposure, then the sRGB curve (the same tone map as the PNG writer,
// render/image_io.cpp).
in vec2 uv;
out vec4 color;

layout(binding = 0) uniform sampler2D image;
uniform float exposureScale;

float srgbEncode(float linear) {
    if (!(linear > 0.0f)) return 0.0f;
    if (linear >= 1.0f) return 1.0f;
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * pow(linear, 1.0f / 2.4f) - 0.055f;
}

void main() {
    const vec3 c = texture(image, uv).rgb * exposureScale;
    color = vec4(srgbEncode(c.r), srgbEncode(c.g), srgbEncode(c.b), 1.0f);
}
