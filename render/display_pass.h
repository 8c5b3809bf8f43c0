#pragma once
// Shows an Image in the current window's default framebuffer (the interactive viewer), with the
// same tone map as the PNG writer, and reads the window back for screenshots.
#include <memory>
#include <vector>

#include "render/image.h"

namespace eikon {

class ShaderProgram;

class DisplayPass {
public:
    DisplayPass();
    ~DisplayPass();
    DisplayPass(const DisplayPass&) = delete;
    DisplayPass& operator=(const DisplayPass&) = delete;

    // Draws `image` scaled to the viewport (width x height pixels).
    void draw(const Image& image, float exposureStops, ToneCurve curve, int width, int height);
    // The window's pixels, 8-bit RGB, row 0 at the top.
    std::vector<unsigned char> readPixels(int width, int height) const;

private:
    std::unique_ptr<ShaderProgram> program_;
    unsigned texture_ = 0;
    unsigned vertexArray_ = 0;
    int textureWidth_ = 0, textureHeight_ = 0;
};

}  // namespace eikon
