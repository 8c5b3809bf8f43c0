#pragma once
// A light none of whose particles (photons, wavefront patches) enters the volume lights nothing
// there: a spot light facing away, a cone that misses the box. The render goes on (the picture
// is what such a scene looks like: dark where only that light would shine), but the user is told
// which light, once per trace, since that is rarely what was meant.
#include <cstddef>
#include <functional>
#include <vector>

#include "render/transport/photons/photon_tracing.h"

namespace eikon {

// Logs one warning per light in `lights` none of whose particles `entered` (by the particle's
// index in the plan's numbering), naming the light by its index in the scene's lights. A black
// light (colour × intensity 0) is meant to light nothing and is not named. Returns how many
// lights were named.
int warnLightsMissingVolume(const ViewSetup& setup, const std::vector<PhotonLightPlan>& lights,
                            const std::function<bool(size_t)>& entered);

}  // namespace eikon
