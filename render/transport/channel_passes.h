#pragma once
// Dispersion for the methods that carry light through the volume once per colour channel (photons,
// plane sweep): under a dispersive material (dispersesView) each pass bends its light through one
// channel's ∇n volume and keeps that channel alone (a mask of 1 in it, 0 elsewhere, applied where
// the method's shared code says), so that channel c of the result is, bit for bit, what a glass
// without dispersion of index n_c gives. Without dispersion: one pass, mask (1, 1, 1).
#include <vector>

#include <glm/vec3.hpp>

#include "render/refraction_volume.h"
#include "render/view_params.h"

namespace eikon {

// 3 under dispersion, else 1.
int channelPassCount(bool dispersion);
// The channels pass `pass` of `passes` keeps: (1, 1, 1) alone, else red, green, blue in turn.
glm::vec3 channelPassMask(int pass, int passes);

// The ∇n volume of each pass, red, green, blue (`gradient` is the green one's): one pass unless
// channelGradients is given and setup disperses. Throws eikon::Error (at `where`) for channel
// volumes that do not match `gradient`.
std::vector<const RefractionVolumeCpu*> channelPassGradientsCpu(
    const ViewSetup& setup, const RefractionVolumeCpu& gradient,
    const ChannelGradientsCpu* channelGradients, const char* where);

// The GPU's: the ∇n texture of each pass. Throws eikon::Error (at `where`) under dispersion
// where the red and blue volumes were not computed.
std::vector<unsigned> channelPassGradientsGpu(const RefractionVolumesGpu& refraction,
                                              bool dispersion, const char* where);

}  // namespace eikon
