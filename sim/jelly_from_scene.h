#pragma once
// The jelly a scene mesh's deformer describes (core/scene.h JellySpec), on the scene's clock.
#include "core/scene.h"
#include "sim/jelly.h"

namespace eikon::sim {

JellySettings jellySettingsFor(const JellySpec& spec, double fps);

}  // namespace eikon::sim
