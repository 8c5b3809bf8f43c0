#pragma once
// Parser of the scene's "receivers" array (docs/scene-format.md#receivers). Internal to core:
// scene.cpp calls it; users read Scene::receivers.
#include <vector>

#include "core/json_reader.h"
#include "core/scene.h"

namespace eikon {

// At most this many receivers (the GPU parameter block has room for EK_MAX_RECEIVERS).
constexpr std::size_t kMaxReceivers = 4;

std::vector<ReceiverSpec> readReceivers(const json::Value& value);

}  // namespace eikon
