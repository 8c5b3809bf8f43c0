#pragma once
// Resizing a linear HDR image: the viewer's previews (apps/viewer.h) are rendered at a fraction of
// the window's size and shown enlarged until the full picture replaces them.
#include "render/image.h"

namespace eikon {

// `source` resampled to width × height by bilinear interpolation of its pixels (rgb and alpha),
// each image spanning the same rectangle: pixel centres map to pixel centres of the same place,
// and reads beyond the outermost centres take the edge pixel. A linear ramp comes back a linear
// ramp between the outermost centres; the same size comes back bit for bit. Throws eikon::Error
// for an empty source or a size below 1.
Image resizeBilinear(const Image& source, int width, int height);

}  // namespace eikon
