#pragma once
// A prism's index gradient for the dispersion tests of the light-transport methods: the box
// [-1, 1]³ filled with a medium whose field is 1 + kPrismRise·y (no surface), so each channel's
// index is n_c(y) = n_c + kPrismRise·(n_c − 1)·y, lit along +x by a slightly red-heavy
// directional light (a channel's result cannot pass for another's). The light goes through the
// fluence, as the methods' configure() sets it.
#include <algorithm>
#include <cmath>
#include <vector>

#include "render/refraction_volume.h"
#include "support/photon_scene.h"

namespace eikon::test {

constexpr float kPrismIor = 1.5f;    // n_d
constexpr float kPrismAbbe = 20.0f;  // a dense flint's dispersion, strong on purpose
constexpr float kPrismRise = 0.3f;

struct DispersivePrism {
    PhotonScene s;
    ChannelGradientsCpu channels;  // red and blue ∇n volumes

    // abbe 0: no dispersion, one index `ior`.
    explicit DispersivePrism(float abbe, float ior = kPrismIor)
        : s(
              32, ior, glm::vec3(0.2f, 0.3f, 0.5f), glm::vec3(1.0f, 0.0f, 0.0f),
              [](glm::vec3 p) { return 1.0f + kPrismRise * p.y; }, glm::vec3(1.0f, 0.8f, 0.6f)) {
        s.scene.materials[0].abbe = abbe;
        s.markGraded();
        shared::setLightInFluence(s.setup.params, 0);
        channels = computeChannelGradientsCpu(s.setup, {&s.field});
    }
};

// The largest |difference| between the rgb of two volumes (`three`, the dispersed passes', and
// `one`, one pass's) relative to the largest |value| of `one`: the mean-direction volumes of
// three channel passes sum each channel's luminance share on its own and so round three times
// where one pass rounds once.
inline double relativeVolumeDifference(const std::vector<glm::vec4>& three,
                                       const std::vector<glm::vec4>& one) {
    double worst = 0.0, largest = 0.0;
    for (size_t i = 0; i < one.size() && i < three.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            worst = std::max(worst, double(std::abs(three[i][k] - one[i][k])));
            largest = std::max(largest, double(std::abs(one[i][k])));
        }
    return largest > 0.0 ? worst / largest : worst;
}

}  // namespace eikon::test
