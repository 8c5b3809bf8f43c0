#pragma once
// Moving a method's results between host and GPU: reading back a whole RGBA32F volume and
// uploading a vec4 array into a storage buffer (photon_radiance_gpu.cpp, plane_sweep_gpu.cpp), and
// the storage buffers of the particle traces (photons, wavefront): made, zeroed, read back.
#include <cstddef>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace eikon {

// The whole RGBA32F 3D texture of resolution res, x fastest.
std::vector<glm::vec4> downloadRgbaVolume(unsigned texture, glm::ivec3 res);

// `data` into the storage buffer `buffer` (generated when 0), one zero texel for an empty array:
// GL refuses empty buffers, and a shader that reads none of it still needs one bound.
void uploadVec4Buffer(unsigned& buffer, const std::vector<glm::vec4>& data);

// A new storage buffer of `bytes` (at least 16), its contents undefined, in place of `buffer`.
void resizeStorageBuffer(unsigned& buffer, size_t bytes);
// Zeroes the whole storage buffer.
void clearStorageBuffer(unsigned buffer);
// `bytes` bytes from byte `offset` of the storage buffer into `out`.
void readStorageBuffer(unsigned buffer, size_t offset, size_t bytes, void* out);

// `count` Ts from the start of the storage buffer.
template <typename T>
std::vector<T> readStorageArray(unsigned buffer, size_t count) {
    std::vector<T> out(count);
    if (count) readStorageBuffer(buffer, 0, count * sizeof(T), out.data());
    return out;
}

// `count` uint words from word `first` of the storage buffer.
std::vector<unsigned> readStorageWords(unsigned buffer, size_t first, size_t count);

}  // namespace eikon
