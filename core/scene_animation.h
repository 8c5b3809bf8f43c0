#pragma once
// Parser of the scene's "animation" array (docs/scene-format.md#animation). Internal to core:
// scene.cpp calls it once the rest of the scene is read, since targets point into it.
#include <vector>

#include "core/json_reader.h"
#include "core/scene.h"

namespace eikon {

std::vector<AnimationTrack> readAnimation(const json::Value& value, const Scene& scene);

}  // namespace eikon
