#pragma once
// Reading a material's dispersion, `abbe` or `cauchy` (core/dispersion.h), for the materials and
// the meshes of a scene. Internal to core.
#include "core/json_reader.h"
#include "core/scene.h"

namespace eikon::scene_detail {

// Reads "abbe" (with the "ior" already read; iorGiven: the scene gave it) or "cauchy" [A, B],
// which sets ior too, into material; one-line errors for both at once, either without a glass
// (no ior above 1, or Gladstone–Dale air), B < 0, and any channel's n below 1.
void readDispersion(json::Object& object, MaterialSpec& material, bool iorGiven);

}  // namespace eikon::scene_detail
