#include "core/dispersion.h"

namespace eikon {

namespace {

double inverseSquare(double micrometres) {
    return 1.0 / (micrometres * micrometres);
}

}  // namespace

glm::vec3 channelIndices(float ior, float abbe) {
    if (abbe == 0.0f) return glm::vec3(ior);
    // B from V_d = (n_d − 1)/(n_F − n_C) with n_F − n_C = B (1/λF² − 1/λC²); each channel is n_d
    // moved along the law by B (1/λ² − 1/λd²).
    const double spread = (double(ior) - 1.0) / double(abbe);
    const double b =
        spread / (inverseSquare(kChannelWavelengthUm[2]) - inverseSquare(kChannelWavelengthUm[0]));
    glm::vec3 n;
    for (int c = 0; c < 3; ++c)
        n[c] = float(double(ior) + b * (inverseSquare(kChannelWavelengthUm[c]) -
                                        inverseSquare(kChannelWavelengthUm[1])));
    return n;
}

IndexAndAbbe fromCauchy(double a, double b) {
    IndexAndAbbe out;
    out.ior = a + b * inverseSquare(kChannelWavelengthUm[1]);
    if (b == 0.0) return out;
    const double spread =
        b * (inverseSquare(kChannelWavelengthUm[2]) - inverseSquare(kChannelWavelengthUm[0]));
    out.abbe = (out.ior - 1.0) / spread;
    return out;
}

}  // namespace eikon
