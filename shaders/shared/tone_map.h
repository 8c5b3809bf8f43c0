// The tone map from linear HDR radiance to display values, shared by the PNG writer
// (render/image_io.cpp) and the viewer's display shader (shaders/display.frag), so a screenshot
// and a rendered PNG of the same image agree. Exposure first (a scale of 2^stops), then a curve,
// then the sRGB transfer function.

#define EK_TONE_LINEAR 0  // clamp at 1: exact below it, hard clipping above
#define EK_TONE_FILMIC 1  // ACES filmic fit: a toe, a shoulder that rolls highlights off to 1

// The sRGB transfer function (IEC 61966-2-1) of a value in [0, 1]; NaN and negatives go to 0.
float srgbEncode(float linear) {
    if (!(linear > 0.0f)) return 0.0f;
    if (linear >= 1.0f) return 1.0f;
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * pow(linear, 1.0f / 2.4f) - 0.055f;
}

// Narkowicz's 2015 fit of the ACES reference rendering transform: x(2.51x + 0.03) /
// (x(2.43x + 0.59) + 0.14). Monotonic, 0 at 0, 0.80 at 1, and 1 (clipped) only from x ≈ 7.24,
// so caustics up to about seven times the exposure's white keep their structure.
float filmicCurve(float x) {
    if (!(x > 0.0f)) return 0.0f;
    return min((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 1.0f);
}

// Display value in [0, 1] of one linear channel.
float toneMapChannel(float linear, float exposureScale, int curve) {
    const float x = linear * exposureScale;
    return srgbEncode(curve == EK_TONE_FILMIC ? filmicCurve(x) : x);
}
