#pragma once
// The memory a scene will take, checked where the scene is read (core/memory_limit.h), so that a
// voxel_size or resolution typo is one message naming its JSON pointer instead of an allocation
// that ends the process. Internal to core (scene.cpp).
#include "core/json_reader.h"

namespace eikon {
struct Scene;
}

namespace eikon::scene_detail {

// Estimates each part known from the file alone (procedural fields, smoke domains, the image,
// a render volume of fixed resolution) and throws at the part's pointer when it, or all of them
// together, exceed the memory limit. An "auto" render volume is checked once its resolution is
// known (chooseRenderVolume).
void checkSceneMemory(const Scene& scene, const json::Value& root);

}  // namespace eikon::scene_detail
