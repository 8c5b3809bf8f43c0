#include "render/display_pass.h"

#include <algorithm>
#include <cmath>

#include <epoxy/gl.h>

#include "render/shader_program.h"
#include "shaders/shared/bindings.h"

namespace eikon {

DisplayPass::DisplayPass()
    : program_(std::make_unique<ShaderProgram>(
          ShaderProgram::graphics("display.vert", "display.frag"))) {
    // Core profile needs a bound vertex array even when the vertices come from gl_VertexID.
    glGenVertexArrays(1, &vertexArray_);
}

DisplayPass::~DisplayPass() {
    if (texture_) glDeleteTextures(1, &texture_);
    if (vertexArray_) glDeleteVertexArrays(1, &vertexArray_);
}

void DisplayPass::draw(const Image& image, float exposureStops, ToneCurve curve, int width,
                       int height) {
    if (!texture_ || image.width != textureWidth_ || image.height != textureHeight_) {
        if (texture_) glDeleteTextures(1, &texture_);
        glGenTextures(1, &texture_);
        glBindTexture(GL_TEXTURE_2D, texture_);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, image.width, image.height);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        textureWidth_ = image.width;
        textureHeight_ = image.height;
    }
    glActiveTexture(GL_TEXTURE0 + EK_UNIT_DISPLAY_IMAGE);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT,
                    image.pixels.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    program_->use();
    program_->setFloat("exposureScale", std::exp2(exposureStops));
    program_->setInt("toneCurve", curve == ToneCurve::Filmic ? 1 : 0);  // EK_TONE_*
    glBindVertexArray(vertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

std::vector<unsigned char> DisplayPass::readPixels(int width, int height) const {
    std::vector<unsigned char> rgb(size_t(width) * size_t(height) * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    // GL's row 0 is the bottom.
    std::vector<unsigned char> flipped(rgb.size());
    const size_t row = size_t(width) * 3;
    for (int y = 0; y < height; ++y)
        std::copy_n(rgb.begin() + std::ptrdiff_t(size_t(height - 1 - y) * row), row,
                    flipped.begin() + std::ptrdiff_t(size_t(y) * row));
    return flipped;
}

}  // namespace eikon
