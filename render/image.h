#pragma once
// Linear HDR images (what passes produce) and their output: the tone map to 8-bit sRGB PNG, and
// linear float EXR. Writers go through a temporary file renamed into place, so a failed write
// never replaces an existing image. Output is byte-identical for identical pixels (no time
// stamps in either format).
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "core/scene.h"

namespace eikon {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<glm::vec4> pixels;  // row 0 is the top; rgb linear radiance, a = transmittance

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h), glm::vec4(0.0f)) {}
    glm::vec4& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
    const glm::vec4& at(int x, int y) const {
        return pixels[size_t(y) * size_t(width) + size_t(x)];
    }
};

// Exposure (2^stops), the curve, then the sRGB transfer function, rounded to 8 bits
// (shaders/shared/tone_map.h, which the viewer's display shader shares).
std::vector<unsigned char> toneMapToSrgb8(const Image& image, float exposureStops,
                                          ToneCurve curve = ToneCurve::Filmic);

void writePng(const std::string& path, const Image& image, float exposureStops,
              ToneCurve curve = ToneCurve::Filmic);
// 8-bit sRGB RGB rows, row 0 at the top (what toneMapToSrgb8 returns, or a window's pixels).
void writePngRgb8(const std::string& path, int width, int height,
                  const std::vector<unsigned char>& rgb);
void writeExr(const std::string& path, const Image& image);  // RGBA, 32-bit float, ZIP
// Reads an RGBA (or RGB, alpha 1) EXR; throws eikon::Error naming the file.
Image readExr(const std::string& path);

// Reads any PNG as 8-bit RGB, each channel as its display value / 255 (not linear), alpha 1.
// Throws eikon::Error naming the file.
Image readPng(const std::string& path);

// How far `test` is from `reference` (same size), over the RGB channels of all pixels.
struct ImageDifference {
    double rmse = 0.0;          // root mean square difference
    double maxAbs = 0.0;        // largest absolute difference
    double referenceMax = 0.0;  // largest reference value, to read the others relatively
    double meanRelative = 0.0;  // mean |difference| / mean |reference|
};
ImageDifference compareImages(const Image& test, const Image& reference);

}  // namespace eikon
