// The Gaussian blur of refractive-index coverage (Sun et al. 2008 §4.1: a 9×9×9 window with
// σ = 1.5 voxels, so that ∇n is smooth enough to act as a surface normal), separable: one pass
// per axis, the same on the GPU and in the CPU twin (render/voxelize.h). Functions only; needs
// platform.h and from the includer `float fetchUnblurred(ivec3 voxel)`.
//
// At the volume's faces the missing neighbours are left out and the weights renormalized, as in
// smoothing.h, so a constant stays constant.

float gaussianBlurWeight(int d, float sigma) {
    return exp(-float(d * d) / (2.0f * sigma * sigma));
}

// gaussianBlurWeight(d, sigma). In the CPU twin (EK_BLUR_WEIGHT_TABLE) the includer's
// `blurWeights[d]`, which holds those floats (d in [−radius, radius]: it points at the middle one),
// taken once a blur: with it alone, the twin's blur at 128³ went from 194-213 to 54-74 ms
// (BENCHMARKS.md, "The mesh blur 14×").
float blurTapWeight(int d, float sigma) {
#ifdef EK_BLUR_WEIGHT_TABLE
    static_cast<void>(sigma);  // the table's weights were taken with it
    return blurWeights[d];
#else
    return gaussianBlurWeight(d, sigma);
#endif
}

float gaussianBlurAlongAxis(ivec3 v, ivec3 res, int axis, float sigma, int radius) {
    float sum = 0.0f;
    float weightSum = 0.0f;
    for (int d = -radius; d <= radius; ++d) {
        ivec3 n = v;
        n[axis] += d;
        if (n[axis] < 0 || n[axis] >= res[axis]) continue;
        const float w = blurTapWeight(d, sigma);
        sum += w * fetchUnblurred(n);
        weightSum += w;
    }
    return sum / weightSum;
}
