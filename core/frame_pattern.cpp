#include "core/frame_pattern.h"

#include <cctype>
#include <cstdio>

#include "core/error.h"

namespace eikon {
namespace {

bool isDigit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// The width a token at `name[i]` stands for and its length in `name`; 0 length when none starts
// there. A '#' run is its own width.
struct Token {
    size_t length = 0;
    int width = 0;
};

Token tokenAt(const std::string& name, size_t i, const std::string& where) {
    Token t;
    if (name[i] == '#') {
        while (i + t.length < name.size() && name[i + t.length] == '#') ++t.length;
        t.width = int(t.length);
        return t;
    }
    if (name[i] == '%' && i + 1 < name.size()) {
        size_t j = i + 1;
        const bool zero = name[j] == '0';
        if (zero) ++j;
        size_t digits = j;
        while (digits < name.size() && isDigit(name[digits])) ++digits;
        if (digits < name.size() && name[digits] == 'd') {
            if (digits == j && zero) throw Error(where, "'%0d' has no width; write %04d or ####");
            if (digits > j && !zero)
                throw Error(where, "'" + name.substr(i, digits + 1 - i) +
                                       "' pads with spaces, which a file name cannot hold; write "
                                       "%0" +
                                       name.substr(j, digits - j) + "d");
            // At most two digits are read: a longer width is out of range anyway, and stoi
            // would throw on one past int.
            t.width = digits == j ? 1 : digits - j > 2 ? 99 : std::stoi(name.substr(j, digits - j));
            t.length = digits + 1 - i;
            if (t.width < 1 || t.width > 9)
                throw Error(where, "frame width " + std::to_string(t.width) +
                                       " is outside 1 to 9 in '" + name + "'");
        }
        return t;
    }
    // Houdini: $F, $F4 ($FF is its float frame, $FPS and $FSTART other variables: not tokens).
    if (name[i] == '$' && i + 1 < name.size() && name[i + 1] == 'F') {
        size_t j = i + 2;
        if (j < name.size() && std::isalpha(static_cast<unsigned char>(name[j]))) return t;
        if (j < name.size() && isDigit(name[j])) {
            t.width = name[j] - '0';
            ++j;
            if (j < name.size() && isDigit(name[j]))
                throw Error(where, "frame width over 9 in '" + name + "'");
            if (t.width < 1) throw Error(where, "'$F0' has no width; write $F4 or ####");
        } else {
            t.width = 1;
        }
        t.length = j - i;
    }
    return t;
}

}  // namespace

std::string toHashPattern(const std::string& name, const std::string& where) {
    std::string out;
    int tokens = 0;
    for (size_t i = 0; i < name.size();) {
        const Token t = tokenAt(name, i, where);
        if (t.length == 0) {
            out += name[i++];
            continue;
        }
        if (++tokens > 1)
            throw Error(where, "'" + name +
                                   "' holds two frame-number tokens; a name has one (####, %04d "
                                   "or $F4)");
        out.append(size_t(t.width), '#');
        i += t.length;
    }
    return out;
}

bool hasHashRun(const std::string& name) {
    return name.find('#') != std::string::npos;
}

std::string expandHashPattern(const std::string& pattern, int frame) {
    const size_t start = pattern.find('#');
    if (start == std::string::npos) return pattern;
    size_t end = start;
    while (end < pattern.size() && pattern[end] == '#') ++end;
    char number[32];
    std::snprintf(number, sizeof(number), "%0*d", int(end - start), frame);
    return pattern.substr(0, start) + number + pattern.substr(end);
}

}  // namespace eikon
