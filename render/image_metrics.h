#pragma once
// What a regression check measures between a new image and its reference, beside the plain
// differences of compareImages (render/image.h): PSNR and SSIM, and a heat map of where they
// differ for a report.
//
// SSIM (Wang, Bovik, Sheikh & Simoncelli 2004) is the perceptual metric: one closed formula with
// standard constants (11×11 Gaussian window, σ = 1.5, K1 = 0.01, K2 = 0.03), which users can
// reproduce with scikit-image's structural_similarity(..., gaussian_weights=True, sigma=1.5,
// use_sample_covariance=False, data_range=1). FLIP would need viewing conditions (pixels per
// degree) that a regression suite does not know. It is computed on what a person sees: the
// luma (Rec. 709 weights) of display values — a PNG's as stored, a linear image's after the PNG
// writer's tone map.
#include "render/image.h"

namespace eikon {

// Display values in [0, 1]: linear radiance through the PNG writer's tone map (exposure 0,
// filmic), or, when `displayEncoded` (a PNG read by readPng), the values as they are.
Image displayValues(const Image& image, bool displayEncoded);

// Mean SSIM of the luma of two display-value images of the same size; 1 for identical images.
double ssim(const Image& test, const Image& reference);

// 10 log10(peak² / MSE) over RGB; +infinity for identical images. `peak` is 1 for display values,
// the reference's largest value for linear ones.
double psnr(const Image& test, const Image& reference, double peak);

// The per-pixel largest RGB difference, mapped black (0) → red → yellow → white (the largest
// difference in the image), as 8-bit sRGB rows for writePngRgb8. `maxDifference` receives that
// largest difference.
std::vector<unsigned char> differenceHeatMap(const Image& test, const Image& reference,
                                             double& maxDifference);

}  // namespace eikon
