#include "render/gpu_transfer.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace eikon {

std::vector<glm::vec4> downloadRgbaVolume(unsigned texture, glm::ivec3 res) {
    std::vector<glm::vec4> out(size_t(res.x) * size_t(res.y) * size_t(res.z));
    glBindTexture(GL_TEXTURE_3D, texture);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_FLOAT, out.data());
    glBindTexture(GL_TEXTURE_3D, 0);
    return out;
}

void uploadVec4Buffer(unsigned& buffer, const std::vector<glm::vec4>& data) {
    if (!buffer) glGenBuffers(1, &buffer);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    const glm::vec4 none(0.0f);
    glBufferData(GL_SHADER_STORAGE_BUFFER,
                 GLsizeiptr(std::max<size_t>(data.size(), 1) * sizeof(glm::vec4)),
                 data.empty() ? &none : data.data(), GL_DYNAMIC_DRAW);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

}  // namespace eikon
