#pragma once
// Dispersion: a refractive index per colour channel (Ihrke et al. 2007 §5: "dispersion effects
// can be simulated if the input data contain a separate refractive index field for each RGB
// channel"). Eikon's three channels stand for the Fraunhofer lines C (656.3 nm, red), d
// (587.6 nm, green) and F (486.1 nm, blue), the lines on which glass catalogues define the Abbe
// number V_d = (n_d − 1)/(n_F − n_C): a material's `ior` is its n_d, the green channel's index,
// and `abbe` says how far red and blue part from it. Between the lines n follows the two-term
// Cauchy law n(λ) = A + B/λ², which a scene may give instead (`cauchy`: [A, B], λ in µm); the two
// forms are the same law, so a Cauchy pair is kept as its n_d and V_d without loss.
#include <glm/vec3.hpp>

namespace eikon {

// The wavelengths the red, green and blue channels stand for, in micrometres: C, d and F.
inline constexpr double kChannelWavelengthUm[3] = {0.6562725, 0.5875618, 0.4861327};

// n in the red, green and blue channels of a material with n_d = ior and Abbe number abbe (0: no
// dispersion, ior in every channel).
glm::vec3 channelIndices(float ior, float abbe);

// n_d and V_d of the Cauchy law n(λ) = a + b/λ² (λ in µm); abbe 0 where b = 0.
struct IndexAndAbbe {
    double ior = 1.0;
    double abbe = 0.0;
};
IndexAndAbbe fromCauchy(double a, double b);

}  // namespace eikon
