#pragma once
// Parser of the scene's "receivers" array (docs/scene-format.md#receivers). Internal to core:
// scene.cpp calls it; users read Scene::receivers.
#include <vector>

#include "core/json_reader.h"
#include "core/scene.h"
#include "shaders/shared/gpu_types.h"

namespace eikon {

// At most as many receivers as the GPU parameter block has room for.
constexpr std::size_t kMaxReceivers = EK_MAX_RECEIVERS;

std::vector<ReceiverSpec> readReceivers(const json::Value& value);

}  // namespace eikon
