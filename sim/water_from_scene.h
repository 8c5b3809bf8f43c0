#pragma once
// The water surface a scene's water mesh describes (core/scene.h WaterSpec), on the scene's clock.
#include "core/scene.h"
#include "sim/water_surface.h"

namespace eikon::sim {

WaterSettings waterSettingsFor(const WaterSpec& spec, double fps);

}  // namespace eikon::sim
