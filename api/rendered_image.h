// The public RenderedImage from the renderer's Image: linear rgb and transmittance copied out
// (the 8-bit picture is the caller's, since it depends on where the image came from).
#pragma once

#include "eikon/eikon.h"
#include "render/image.h"

namespace eikon {

inline RenderedImage linearPartsOf(const Image& image) {
    RenderedImage out;
    out.width = image.width;
    out.height = image.height;
    out.rgb.resize(image.pixels.size() * 3);
    out.transmittance.resize(image.pixels.size());
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) out.rgb[3 * i + size_t(c)] = image.pixels[i][c];
        out.transmittance[i] = image.pixels[i].a;
    }
    return out;
}

}  // namespace eikon
