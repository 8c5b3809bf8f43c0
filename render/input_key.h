#pragma once
// Keys that say what a stage's result was computed from: the raw bytes of its inputs, compared
// with the last key to decide whether the stage reruns (frame_renderer.cpp, mesh_fields.cpp).
#include <cstddef>
#include <cstring>
#include <vector>

namespace eikon {

// resize + memcpy rather than insert: GCC 12 warns (-Wstringop-overflow, a false positive) on
// insert into an empty vector once the code is inlined, as the position-independent build does.
inline void appendBytes(std::vector<unsigned char>& key, const void* data, std::size_t size) {
    if (size == 0) return;
    const std::size_t at = key.size();
    key.resize(at + size);
    std::memcpy(key.data() + at, data, size);
}

}  // namespace eikon
