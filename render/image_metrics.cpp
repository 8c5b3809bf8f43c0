#include "render/image_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace eikon {
namespace {

void checkSameSize(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw Error("compare", "images differ in size: " + std::to_string(a.width) + "x" +
                                   std::to_string(a.height) + " vs " + std::to_string(b.width) +
                                   "x" + std::to_string(b.height));
}

std::vector<double> luma(const Image& image) {
    std::vector<double> y(image.pixels.size());
    for (size_t i = 0; i < y.size(); ++i) {
        const glm::vec4& p = image.pixels[i];
        y[i] = 0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b;
    }
    return y;
}

// Separable Gaussian filter (σ = 1.5, radius 5: the 11-tap window of the SSIM paper); samples
// outside the image are left out and the weights renormalized, so small images stay valid.
std::vector<double> gaussianFiltered(const std::vector<double>& v, int w, int h) {
    constexpr int kRadius = 5;
    constexpr double kSigma = 1.5;
    double weights[2 * kRadius + 1];
    for (int i = -kRadius; i <= kRadius; ++i)
        weights[i + kRadius] = std::exp(-double(i * i) / (2.0 * kSigma * kSigma));
    std::vector<double> rows(v.size()), out(v.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sum = 0.0, norm = 0.0;
            for (int i = std::max(-kRadius, -x); i <= std::min(kRadius, w - 1 - x); ++i) {
                sum += weights[i + kRadius] * v[size_t(y) * size_t(w) + size_t(x + i)];
                norm += weights[i + kRadius];
            }
            rows[size_t(y) * size_t(w) + size_t(x)] = sum / norm;
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sum = 0.0, norm = 0.0;
            for (int i = std::max(-kRadius, -y); i <= std::min(kRadius, h - 1 - y); ++i) {
                sum += weights[i + kRadius] * rows[size_t(y + i) * size_t(w) + size_t(x)];
                norm += weights[i + kRadius];
            }
            out[size_t(y) * size_t(w) + size_t(x)] = sum / norm;
        }
    return out;
}

}  // namespace

Image displayValues(const Image& image, bool displayEncoded) {
    if (displayEncoded) return image;
    const std::vector<unsigned char> rgb = toneMapToSrgb8(image, 0.0f, ToneCurve::Filmic);
    Image out(image.width, image.height);
    for (size_t i = 0; i < out.pixels.size(); ++i)
        out.pixels[i] =
            glm::vec4(rgb[3 * i] / 255.0f, rgb[3 * i + 1] / 255.0f, rgb[3 * i + 2] / 255.0f, 1.0f);
    return out;
}

double ssim(const Image& test, const Image& reference) {
    checkSameSize(test, reference);
    const int w = test.width, h = test.height;
    if (w == 0 || h == 0) return 1.0;
    const std::vector<double> a = luma(test), b = luma(reference);
    std::vector<double> aa(a.size()), bb(a.size()), ab(a.size());
    for (size_t i = 0; i < a.size(); ++i) {
        aa[i] = a[i] * a[i];
        bb[i] = b[i] * b[i];
        ab[i] = a[i] * b[i];
    }
    const std::vector<double> muA = gaussianFiltered(a, w, h), muB = gaussianFiltered(b, w, h);
    const std::vector<double> eAA = gaussianFiltered(aa, w, h), eBB = gaussianFiltered(bb, w, h),
                              eAB = gaussianFiltered(ab, w, h);
    constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;  // (K L)², dynamic range L = 1
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        const double varA = eAA[i] - muA[i] * muA[i];
        const double varB = eBB[i] - muB[i] * muB[i];
        const double cov = eAB[i] - muA[i] * muB[i];
        sum += ((2.0 * muA[i] * muB[i] + kC1) * (2.0 * cov + kC2)) /
               ((muA[i] * muA[i] + muB[i] * muB[i] + kC1) * (varA + varB + kC2));
    }
    return sum / double(a.size());
}

double psnr(const Image& test, const Image& reference, double peak) {
    checkSameSize(test, reference);
    double sumSq = 0.0;
    for (size_t i = 0; i < test.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = double(test.pixels[i][c]) - double(reference.pixels[i][c]);
            sumSq += d * d;
        }
    const double mse = test.pixels.empty() ? 0.0 : sumSq / (3.0 * double(test.pixels.size()));
    if (!(mse > 0.0)) return mse == 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
    return 10.0 * std::log10(peak * peak / mse);
}

std::vector<unsigned char> differenceHeatMap(const Image& test, const Image& reference,
                                             double& maxDifference) {
    checkSameSize(test, reference);
    std::vector<double> d(test.pixels.size(), 0.0);
    maxDifference = 0.0;
    for (size_t i = 0; i < d.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double diff =
                std::fabs(double(test.pixels[i][c]) - double(reference.pixels[i][c]));
            d[i] = std::max(d[i], std::isnan(diff) ? HUGE_VAL : diff);
        }
        if (std::isfinite(d[i])) maxDifference = std::max(maxDifference, d[i]);
    }
    std::vector<unsigned char> rgb(3 * d.size(), 0);
    for (size_t i = 0; i < d.size(); ++i) {
        // NaN or infinite differences show full white; the rest scale to the largest.
        const double t = !std::isfinite(d[i]) ? 1.0 : maxDifference > 0 ? d[i] / maxDifference : 0;
        const double r = std::clamp(3.0 * t, 0.0, 1.0), g = std::clamp(3.0 * t - 1.0, 0.0, 1.0),
                     b = std::clamp(3.0 * t - 2.0, 0.0, 1.0);
        rgb[3 * i] = static_cast<unsigned char>(std::lround(255.0 * r));
        rgb[3 * i + 1] = static_cast<unsigned char>(std::lround(255.0 * g));
        rgb[3 * i + 2] = static_cast<unsigned char>(std::lround(255.0 * b));
    }
    return rgb;
}

}  // namespace eikon
