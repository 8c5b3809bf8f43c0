#include "render/params_buffer.h"

#include <epoxy/gl.h>

#include "shaders/shared/bindings.h"

namespace eikon {

ParamsBuffer::ParamsBuffer() {
    glGenBuffers(1, &buffer_);
}

ParamsBuffer::~ParamsBuffer() {
    if (buffer_) glDeleteBuffers(1, &buffer_);
}

void ParamsBuffer::upload(const shared::GpuViewParams& params) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer_);
    glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(params), &params, GL_DYNAMIC_DRAW);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_VIEW_PARAMS, buffer_);
}

void ParamsBuffer::bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_VIEW_PARAMS, buffer_);
}

}  // namespace eikon
