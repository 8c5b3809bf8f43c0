#pragma once
// Reading a material's "transfer" function (core/transfer_function.h). Internal to core.
#include "core/json_reader.h"
#include "core/scene.h"

namespace eikon::scene_detail {

// Reads "transfer": [[value, amount], ...] into material.transfer, with the errors of
// transferFunctionProblem (core/transfer_function.h); not with Gladstone–Dale air.
void readTransfer(json::Object& object, MaterialSpec& material);

}  // namespace eikon::scene_detail
