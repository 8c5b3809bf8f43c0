#include "render/image_resize.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace eikon {
namespace {

// Where output pixel i's centre falls among the source's n pixels of the axis (out of m), as the
// lower source pixel and the weight of the one after it.
struct Tap {
    int lower = 0;
    float weight = 0.0f;
};

Tap tapOf(int i, int m, int n) {
    const double position =
        std::clamp((double(i) + 0.5) * double(n) / double(m) - 0.5, 0.0, double(n - 1));
    const int lower = std::min(int(std::floor(position)), n - 1);
    return {lower, float(position - double(lower))};
}

// a + (b − a)·w: equal neighbours give their value exactly, whatever the weight.
glm::vec4 blend(const glm::vec4& a, const glm::vec4& b, float w) {
    return a + (b - a) * w;
}

}  // namespace

Image resizeBilinear(const Image& source, int width, int height) {
    if (source.width < 1 || source.height < 1 ||
        source.pixels.size() != size_t(source.width) * size_t(source.height))
        throw Error("resize", "the source image is empty");
    if (width < 1 || height < 1)
        throw Error("resize", "a size of " + std::to_string(width) + "x" + std::to_string(height) +
                                  " has no pixels");
    if (width == source.width && height == source.height) return source;
    Image out(width, height);
    for (int y = 0; y < height; ++y) {
        const Tap ty = tapOf(y, height, source.height);
        const int y1 = std::min(ty.lower + 1, source.height - 1);
        for (int x = 0; x < width; ++x) {
            const Tap tx = tapOf(x, width, source.width);
            const int x1 = std::min(tx.lower + 1, source.width - 1);
            const glm::vec4 top =
                blend(source.at(tx.lower, ty.lower), source.at(x1, ty.lower), tx.weight);
            const glm::vec4 bottom = blend(source.at(tx.lower, y1), source.at(x1, y1), tx.weight);
            out.at(x, y) = blend(top, bottom, ty.weight);
        }
    }
    return out;
}

}  // namespace eikon
