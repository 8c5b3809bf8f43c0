#pragma once
// Keys that say what a stage's result was computed from: the raw bytes of its inputs, compared
// with the last key to decide whether the stage reruns (frame_renderer.cpp, mesh_fields.cpp).
#include <cstddef>
#include <vector>

namespace eikon {

inline void appendBytes(std::vector<unsigned char>& key, const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    key.insert(key.end(), bytes, bytes + size);
}

}  // namespace eikon
