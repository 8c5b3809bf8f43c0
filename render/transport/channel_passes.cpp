#include "render/transport/channel_passes.h"

#include "core/error.h"

namespace eikon {

int channelPassCount(bool dispersion) {
    return dispersion ? 3 : 1;
}

glm::vec3 channelPassMask(int pass, int passes) {
    if (passes == 1) return glm::vec3(1.0f);
    glm::vec3 mask(0.0f);
    mask[pass] = 1.0f;
    return mask;
}

std::vector<const RefractionVolumeCpu*> channelPassGradientsCpu(
    const ViewSetup& setup, const RefractionVolumeCpu& gradient,
    const ChannelGradientsCpu* channelGradients, const char* where) {
    if (!channelGradients || !dispersesView(setup)) return {&gradient};
    if (channelGradients->red.size() != gradient.size() ||
        channelGradients->blue.size() != gradient.size())
        throw Error(where, "dispersion needs the red and blue channels' gradient volumes");
    return {&channelGradients->red, &gradient, &channelGradients->blue};
}

std::vector<unsigned> channelPassGradientsGpu(const RefractionVolumesGpu& refraction,
                                              bool dispersion, const char* where) {
    if (!dispersion) return {refraction.gradientTexture()};
    std::vector<unsigned> textures;
    for (int c = 0; c < 3; ++c) textures.push_back(refraction.channelGradientTexture(c));
    if (!textures[0] || !textures[2])
        throw Error(where, "dispersion needs the red and blue channels' gradient volumes");
    return textures;
}

}  // namespace eikon
