#include "core/printable.h"

namespace eikon {

namespace {

bool isControl(unsigned char c) {
    return c < 0x20 || c == 0x7f;
}

}  // namespace

std::string printable(std::string_view text, std::size_t maxBytes) {
    const bool cut = text.size() > maxBytes;
    if (cut) text = text.substr(0, maxBytes);
    std::string out;
    out.reserve(text.size() + 3);
    for (char ch : text) {
        const unsigned char c = static_cast<unsigned char>(ch);
        if (!isControl(c)) {
            out += ch;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else {
            static const char* const kHex = "0123456789abcdef";
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        }
    }
    if (cut) out += "...";
    return out;
}

bool hasControlCharacter(std::string_view text) {
    for (char ch : text)
        if (isControl(static_cast<unsigned char>(ch))) return true;
    return false;
}

}  // namespace eikon
