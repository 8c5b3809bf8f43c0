#include "sim/off_ascii.h"

#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "core/error.h"
#include "core/printable.h"

namespace eikon {

namespace {

bool wholeNumber(const std::string& word, std::uint64_t& value) {
    if (word.empty() || word.size() > 10 ||
        word.find_first_not_of("0123456789") != std::string::npos)
        return false;
    value = std::stoull(word);
    return value <= 0xffffffffull;
}

bool countWord(const std::string& word) {
    std::uint64_t ignored = 0;
    return wholeNumber(word, ignored);
}

// A word `>>` reads completely into a float: decimal (its reader stops at the x of a hexadecimal
// one), and a number a float holds.
bool floatNumber(const std::string& word) {
    if (word.find_first_not_of("0123456789+-.eE") != std::string::npos) return false;
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(word.c_str(), &end);
    return end == word.c_str() + word.size() && errno == 0 && std::fabs(value) <= double(FLT_MAX);
}

// A word `>>` reads completely into an unsigned index (a minus wraps it; checkFaces in
// sim/mesh_io.cpp rejects the vertex it names).
bool integer(const std::string& word) {
    const std::size_t sign = !word.empty() && (word[0] == '-' || word[0] == '+');
    return word.size() > sign && word.size() - sign <= 10 &&
           word.find_first_not_of("0123456789", sign) == std::string::npos;
}

// Reads the body as OpenMesh does: words separated by white space, and the rest of a line.
class Walker {
public:
    Walker(const std::string& path, const std::string& bytes, std::size_t at)
        : path_(path), bytes_(bytes), at_(at) {}

    std::size_t at() const { return at_; }

    // The next word, or "" at the end of the file.
    std::string word() {
        while (at_ < bytes_.size() && std::isspace((unsigned char)bytes_[at_])) ++at_;
        const std::size_t start = at_;
        while (at_ < bytes_.size() && !std::isspace((unsigned char)bytes_[at_])) ++at_;
        return bytes_.substr(start, at_ - start);
    }

    void restOfLine() {
        at_ = bytes_.find('\n', at_);
        at_ = at_ == std::string::npos ? bytes_.size() : at_ + 1;
    }

    // The next word, which `valid` must accept; `what` names it in the error.
    std::string value(bool (*valid)(const std::string&), const std::string& what,
                      const char* expected) {
        const std::string w = word();
        if (w.empty()) throw Error(path_, "truncated: the file ends before " + what);
        if (!valid(w)) throw Error(path_, what + " is '" + printable(w) + "', not " + expected);
        return w;
    }

private:
    const std::string& path_;
    const std::string& bytes_;
    std::size_t at_;
};

}  // namespace

void checkAsciiOff(const std::string& path, const std::string& bytes, const OffHeader& header) {
    Walker walk(path, bytes, header.bodyOffset);
    std::string counts[3];
    for (std::string& c : counts) c = walk.word();
    std::uint64_t vertices = 0, faces = 0, edges = 0;
    if (!wholeNumber(counts[0], vertices) || !wholeNumber(counts[1], faces) ||
        !wholeNumber(counts[2], edges)) {
        std::string got;
        for (const std::string& c : counts)
            if (!c.empty()) got += (got.empty() ? "" : " ") + c;
        std::string line = bytes.substr(0, header.bodyOffset - header.lineEnded);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        throw Error(path, "expected the vertex, face and edge counts after '" + printable(line) +
                              "', got '" + printable(got) + "'");
    }
    // At least a digit and a separator per coordinate and per face count: counts of 4e9 fail
    // here at once, with the sizes in the message.
    const std::uint64_t available = bytes.size() - walk.at();
    const std::uint64_t needed = vertices * 3 * 2 + faces * 2;
    if (needed > available + 1)
        throw Error(path, "the OFF header declares " + std::to_string(vertices) + " vertices and " +
                              std::to_string(faces) + " faces, which need at least " +
                              std::to_string(needed) + " bytes, but " + std::to_string(available) +
                              " follow the counts: truncated or corrupt");
    const int coordinates = header.normals ? 6 : 3;
    for (std::uint64_t v = 0; v < vertices; ++v) {
        for (int k = 0; k < coordinates; ++k)
            walk.value(floatNumber,
                       "value " + std::to_string(k + 1) + " of vertex " + std::to_string(v + 1),
                       "a number a float holds");
        walk.restOfLine();
    }
    for (std::uint64_t f = 0; f < faces; ++f) {
        const std::string face = "face " + std::to_string(f + 1) + " of " + std::to_string(faces);
        std::uint64_t corners = 0;
        wholeNumber(walk.value(countWord, "the vertex count of " + face, "a whole number"),
                    corners);
        for (std::uint64_t k = 0; k < corners; ++k)
            walk.value(integer, "index " + std::to_string(k + 1) + " of " + face, "an integer");
        if (header.colours) walk.restOfLine();
    }
}

}  // namespace eikon
