#pragma once
// Linear HDR images (what passes produce) and their output: the tone map to 8-bit sRGB PNG, and
// linear float EXR. Writers go through a temporary file renamed into place, so a failed write
// never replaces an existing image. Output is byte-identical for identical pixels (no time
// stamps in either format).
#include <string>
#include <vector>

#include <glm/vec4.hpp>

namespace eikon {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> pixels;  // row 0 is the top; rgb linear radiance, a = transmittance

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h), glm::vec4(0.0f)) {}
    glm::vec4& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
    const glm::vec4& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

// Exposure (2^stops), then the sRGB transfer curve, clamped to [0, 1] and rounded to 8 bits.
std::vector<unsigned char> toneMapToSrgb8(const Image& image, float exposureStops);

void writePng(const std::string& path, const Image& image, float exposureStops);
void writeExr(const std::string& path, const Image& image);  // RGBA, 32-bit float, ZIP

}  // namespace eikon
