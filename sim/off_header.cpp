#include "sim/off_header.h"

namespace eikon {

OffHeader readOffHeader(const std::string& bytes) {
    OffHeader h;
    const std::size_t newline = bytes.find('\n');
    h.lineEnded = newline != std::string::npos;
    const std::size_t lineEnd = h.lineEnded ? newline : bytes.size();
    h.bodyOffset = h.lineEnded ? newline + 1 : bytes.size();
    std::size_t p = 0;
    const auto next = [&](const char* text) {
        const std::size_t n = std::char_traits<char>::length(text);
        if (p + n > lineEnd || bytes.compare(p, n, text) != 0) return false;
        p += n;
        return true;
    };
    if (next("ST")) h.vertexBytes += 8;  // u, v
    h.colours = next("C");
    if (h.colours) h.vertexBytes += 12;  // three colour values, integers or floats
    h.normals = next("N");
    if (h.normals) h.vertexBytes += 12;
    const bool homogeneous = next("4");  // four coordinates per vertex
    const bool dimension = next("n");    // the dimension written before the counts
    if (!next("OFF")) return h;
    h.readable = !homogeneous && !dimension;
    // One character is skipped after "OFF", whatever it is.
    h.binary = h.readable && p + 1 + 6 <= lineEnd && bytes.compare(p + 1, 6, "BINARY") == 0;
    return h;
}

}  // namespace eikon
