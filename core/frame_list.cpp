#include "core/frame_list.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "core/error.h"

namespace eikon {
namespace {

const char* const kGrammar =
    "expected frames as 7, 1-10, 1-10x2 (every 2nd) or a comma list of those (1,3,5-7)";

[[noreturn]] void fail(const std::string& text, const std::string& why = "") {
    throw Error("--frames",
                std::string(kGrammar) + ", got '" + text + "'" + (why.empty() ? "" : ": " + why));
}

// Reads the digits at text[at...] as a number up to INT_MAX (the scene's frame numbers' range),
// advancing `at`; false where there is none or it is larger.
bool readNumber(const std::string& text, size_t& at, int& value) {
    const size_t start = at;
    long long v = 0;
    while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at]))) {
        v = v * 10 + (text[at] - '0');
        if (v > std::numeric_limits<int>::max()) return false;
        ++at;
    }
    if (at == start) return false;
    value = int(v);
    return true;
}

}  // namespace

std::vector<int> parseFrameList(const std::string& text) {
    std::vector<int> frames;
    size_t at = 0;
    if (text.empty()) fail(text);
    while (true) {
        int first = 0, last = 0, step = 1;
        if (!readNumber(text, at, first)) fail(text);
        last = first;
        if (at < text.size() && text[at] == '-') {
            ++at;
            if (!readNumber(text, at, last)) fail(text);
            if (last < first) fail(text, "the last frame comes before the first");
            if (at < text.size() && text[at] == 'x') {
                ++at;
                if (!readNumber(text, at, step) || step < 1) fail(text, "a step is 1 or more");
            }
        }
        const long long count = (static_cast<long long>(last) - first) / step + 1;
        if (count + static_cast<long long>(frames.size()) > kMaxListedFrames)
            fail(text, "more than " + std::to_string(kMaxListedFrames) + " frames");
        for (long long f = first; f <= last; f += step) frames.push_back(int(f));
        if (at == text.size()) break;
        if (text[at] != ',') fail(text);
        ++at;
    }
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    return frames;
}

bool isContiguous(const std::vector<int>& frames) {
    return !frames.empty() && static_cast<long long>(frames.back()) - frames.front() + 1 ==
                                  static_cast<long long>(frames.size());
}

std::string framePath(const std::string& directory, const std::string& name, int frame,
                      const char* ext) {
    char number[16];
    std::snprintf(number, sizeof(number), "_%04d.", frame);
    return (std::filesystem::path(directory) / (name + number + ext)).string();
}

}  // namespace eikon
