#include "core/file_kind.h"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace fs = std::filesystem;

namespace eikon {
namespace {

// The first bytes as text a reader can place: printable ASCII as is, others as \xNN.
std::string shownBytes(const std::string& head) {
    std::string out;
    for (size_t i = 0; i < head.size() && i < 8; ++i) {
        const unsigned char c = static_cast<unsigned char>(head[i]);
        if (std::isprint(c)) {
            out += char(c);
        } else {
            char hex[8];
            std::snprintf(hex, sizeof(hex), "\\x%02x", c);
            out += hex;
        }
    }
    return out;
}

bool startsWith(const std::string& s, const char* prefix, size_t n) {
    return s.size() >= n && std::memcmp(s.data(), prefix, n) == 0;
}

}  // namespace

FileKind sniffFileKind(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error(path, "no such file");
    if (fs::is_directory(path, ec))
        throw Error(path, "is a folder; expected a scene (.json) or a VDB file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path, std::string("cannot open: ") + std::strerror(errno));
    std::string head(256, '\0');
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(size_t(in.gcount()));
    if (head.empty())
        throw Error(path, "the file is empty (0 bytes); expected a scene or a VDB file");
    // OpenVDB writes its magic as a little-endian int32 (io/Archive.cc): bytes 20 42 44 56.
    if (startsWith(head, "\x20\x42\x44\x56", 4)) return FileKind::Vdb;
    if (startsWith(head, "NanoVDB", 7)) return FileKind::NanoVdb;
    size_t i = startsWith(head, "\xEF\xBB\xBF", 3) ? 3 : 0;
    while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
    if (i < head.size() && head[i] == '{') return FileKind::Json;
    if (i == head.size() && !in.eof())
        throw Error(path, "neither a scene (JSON), an OpenVDB nor a NanoVDB file: it starts with " +
                              std::to_string(head.size()) + " bytes of white space");
    if (i == head.size()) throw Error(path, "the file holds only white space; expected a scene");
    throw Error(path, "neither a scene (JSON), an OpenVDB nor a NanoVDB file: it starts with \"" +
                          shownBytes(head.substr(i)) + "\"");
}

bool isNanoVdbFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char head[7] = {};
    in.read(head, sizeof(head));
    return in.gcount() == 7 && std::memcmp(head, "NanoVDB", 7) == 0;
}

}  // namespace eikon
