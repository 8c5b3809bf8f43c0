#include "core/vdb_file_id.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <vector>

#include "core/error.h"

namespace eikon {
namespace {

// io::Archive::writeHeader: int64 magic 0x56444220 (" BDV"), uint32 file version, uint32 library
// major and minor versions, char "has grid offsets", then the UUID as 36 ASCII characters.
constexpr size_t kUuidOffset = 8 + 4 + 4 + 4 + 1;
constexpr size_t kUuidLength = 36;
constexpr unsigned char kMagic[8] = {0x20, 0x42, 0x44, 0x56, 0, 0, 0, 0};
constexpr uint32_t kFirstVersionWithUuid = 222;  // OPENVDB_FILE_VERSION_BOOST_UUID

bool looksLikeUuid(const std::vector<unsigned char>& bytes) {
    for (size_t i = 0; i < kUuidLength; ++i) {
        const char c = char(bytes[kUuidOffset + i]);
        const bool dash = i == 8 || i == 13 || i == 18 || i == 23;
        const bool hex = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
        if (dash ? c != '-' : !hex) return false;
    }
    return true;
}

// FNV-1a over every byte outside the UUID, from a given offset basis.
uint64_t hashOutsideUuid(const std::vector<unsigned char>& bytes, uint64_t basis) {
    uint64_t h = basis;
    for (size_t i = 0; i < bytes.size(); ++i) {
        if (i >= kUuidOffset && i < kUuidOffset + kUuidLength) continue;
        h ^= bytes[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

}  // namespace

void makeVdbFileIdDeterministic(const std::string& path) {
    std::vector<unsigned char> bytes;
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) throw Error(path, "cannot reopen the written VDB file");
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const bool magic = bytes.size() >= kUuidOffset + kUuidLength &&
                       std::equal(std::begin(kMagic), std::end(kMagic), bytes.begin());
    const uint32_t version = magic ? uint32_t(bytes[8]) | uint32_t(bytes[9]) << 8 |
                                         uint32_t(bytes[10]) << 16 | uint32_t(bytes[11]) << 24
                                   : 0;
    if (!magic || version < kFirstVersionWithUuid || !looksLikeUuid(bytes))
        throw Error(path, "the VDB header is not the layout this build knows (file version " +
                              std::to_string(version) + "); cannot make its identifier repeatable");

    const uint64_t a = hashOutsideUuid(bytes, 0xcbf29ce484222325ull);
    const uint64_t b = hashOutsideUuid(bytes, 0x84222325cbf29ce4ull);
    static const char* const kHex = "0123456789abcdef";
    std::string uuid;
    for (int i = 0; i < 32; ++i) {
        const uint64_t word = i < 16 ? a : b;
        uuid += kHex[(word >> (60 - 4 * (i % 16))) & 0xf];
        if (i == 7 || i == 11 || i == 15 || i == 19) uuid += '-';
    }
    std::fstream out(path, std::ios::binary | std::ios::in | std::ios::out);
    out.seekp(std::streamoff(kUuidOffset));
    out.write(uuid.data(), std::streamsize(uuid.size()));
    out.close();
    if (!out) throw Error(path, "cannot rewrite the VDB file's identifier");
}

}  // namespace eikon
