#pragma once
// Moving a method's results between host and GPU: reading back a whole RGBA32F volume and
// uploading a vec4 array into a storage buffer (photon_radiance_gpu.cpp, plane_sweep_gpu.cpp).
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace eikon {

// The whole RGBA32F 3D texture of resolution res, x fastest.
std::vector<glm::vec4> downloadRgbaVolume(unsigned texture, glm::ivec3 res);

// `data` into the storage buffer `buffer` (generated when 0), one zero texel for an empty array:
// GL refuses empty buffers, and a shader that reads none of it still needs one bound.
void uploadVec4Buffer(unsigned& buffer, const std::vector<glm::vec4>& data);

}  // namespace eikon
