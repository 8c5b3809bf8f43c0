// compareImages and readImage of include/eikon/eikon.h, on the metrics of eikon regress
// (render/image_metrics.h), so a Python or C++ regression test judges images as the suite does.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "api/rendered_image.h"
#include "eikon/eikon.h"
#include "render/image.h"
#include "render/image_metrics.h"

namespace fs = std::filesystem;

namespace eikon {
namespace {

// The image as the metrics take it: linear rgb, or display values from srgb8 when `display`.
Image asImage(const RenderedImage& r, bool display) {
    Image image(r.width, r.height);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c)
            image.pixels[i][c] =
                display ? r.srgb8[3 * i + size_t(c)] / 255.0f : r.rgb[3 * i + size_t(c)];
        image.pixels[i].a = 1.0f;
    }
    return image;
}

}  // namespace

ImageMetrics compareImages(const RenderedImage& test, const RenderedImage& reference) {
    // A size mismatch throws in eikon::compareImages(Image, Image) below.
    const bool linear = test.linear && reference.linear;
    const Image a = asImage(test, !linear), b = asImage(reference, !linear);
    const ImageDifference d = eikon::compareImages(a, b);
    ImageMetrics m;
    m.rmse = d.rmse;
    m.maxAbs = d.maxAbs;
    m.meanRelative = d.meanRelative;
    m.psnr = psnr(a, b, linear ? std::max(d.referenceMax, 1e-30) : 1.0);
    m.ssim = ssim(asImage(test, true), asImage(reference, true));
    return m;
}

RenderedImage readImage(const std::string& path) {
    const bool exr = fs::path(path).extension() == ".exr";
    const Image image = exr ? readExr(path) : readPng(path);
    RenderedImage out = linearPartsOf(image);
    out.linear = exr;
    out.srgb8 = exr ? toneMapToSrgb8(image, 0.0f, ToneCurve::Filmic)
                    : std::vector<std::uint8_t>(out.rgb.size());
    if (!exr)
        for (size_t i = 0; i < out.rgb.size(); ++i)
            out.srgb8[i] = static_cast<std::uint8_t>(std::lround(out.rgb[i] * 255.0f));
    return out;
}

}  // namespace eikon
