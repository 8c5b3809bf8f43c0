#pragma once
// Reading a material's "transfer" function (core/transfer_function.h) and "particle_color"
// (core/particle_color.h). Internal to core.
#include "core/json_reader.h"
#include "core/scene.h"

namespace eikon::scene_detail {

// Reads "transfer": [[value, amount], ...] into material.transfer, with the errors of
// transferFunctionProblem (core/transfer_function.h); not with Gladstone–Dale air.
void readTransfer(json::Object& object, MaterialSpec& material);

// Reads "particle_color" (core/particle_color.h) into material.particleColor: a colour map's name
// (over values 0 to 1), {"map": name, "range": [low, high]}, or [[value, r, g, b], ...]; with the
// errors of particleColorProblem.
void readParticleColor(json::Object& object, MaterialSpec& material);

}  // namespace eikon::scene_detail
