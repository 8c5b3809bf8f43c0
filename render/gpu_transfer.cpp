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

void resizeStorageBuffer(unsigned& buffer, size_t bytes) {
    if (buffer) glDeleteBuffers(1, &buffer);
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(std::max<size_t>(bytes, 16)), nullptr,
                 GL_DYNAMIC_COPY);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

void clearStorageBuffer(unsigned buffer) {
    const GLuint zero = 0;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

void readStorageBuffer(unsigned buffer, size_t offset, size_t bytes, void* out) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, GLintptr(offset), GLsizeiptr(bytes), out);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

std::vector<unsigned> readStorageWords(unsigned buffer, size_t first, size_t count) {
    std::vector<unsigned> words(count);
    if (count)
        readStorageBuffer(buffer, first * sizeof(unsigned), count * sizeof(unsigned), words.data());
    return words;
}

}  // namespace eikon
