#include "sim/obj_face_lines.h"

#include <cctype>
#include <cstddef>
#include <vector>

#include "core/error.h"
#include "core/printable.h"

namespace eikon {

namespace {

bool isSpace(char c) {
    return std::isspace(static_cast<unsigned char>(c)) != 0;
}

// The words of [begin, end) separated by white space, as `>>` reads them.
std::vector<std::string> words(const std::string& bytes, std::size_t begin, std::size_t end) {
    std::vector<std::string> out;
    std::size_t i = begin;
    while (i < end) {
        while (i < end && isSpace(bytes[i])) ++i;
        const std::size_t start = i;
        while (i < end && !isSpace(bytes[i])) ++i;
        if (i > start) out.push_back(bytes.substr(start, i - start));
    }
    return out;
}

// An OBJ index: an optional sign, then one to nine digits.
bool isIndex(const std::string& part) {
    const std::size_t digits = part.size() - (!part.empty() && (part[0] == '-' || part[0] == '+'));
    if (digits == 0 || digits > 9) return false;
    for (std::size_t k = part.size() - digits; k < part.size(); ++k)
        if (!std::isdigit(static_cast<unsigned char>(part[k]))) return false;
    return true;
}

// v, v/vt, v//vn or v/vt/vn: the vertex index always, the others optional.
bool isCorner(const std::string& corner) {
    std::vector<std::string> parts(1);
    for (char c : corner) {
        if (c == '/')
            parts.emplace_back();
        else
            parts.back() += c;
    }
    if (parts.size() > 3 || !isIndex(parts[0])) return false;
    for (std::size_t k = 1; k < parts.size(); ++k)
        if (!parts[k].empty() && !isIndex(parts[k])) return false;
    return true;
}

}  // namespace

void checkObjFaceLines(const std::string& path, const std::string& bytes) {
    std::size_t lineNumber = 0;
    for (std::size_t start = 0; start < bytes.size();) {
        std::size_t end = bytes.find('\n', start);
        if (end == std::string::npos) end = bytes.size();
        ++lineNumber;
        const std::vector<std::string> w = words(bytes, start, end);
        if (!w.empty() && w[0] == "f") {
            for (std::size_t k = 1; k < w.size(); ++k)
                if (!isCorner(w[k]))
                    throw Error(path + ":" + std::to_string(lineNumber),
                                "face corner " + std::to_string(k) + " ('" + printable(w[k]) +
                                    "') is not v, v/vt, v//vn or v/vt/vn with whole-number "
                                    "indices");
        }
        start = end + 1;
    }
}

}  // namespace eikon
