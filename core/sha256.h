#pragma once
// SHA-256 (FIPS 180-4), for the identities a render farm compares: a frame file's hash in a run's
// manifest (apps/render_manifest.h), the hash of a scene and of the eikon binary that rendered
// it. The hex digests are the ones `sha256sum` prints, so users check them with standard tools.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace eikon {

class Sha256 {
public:
    Sha256();
    void update(const void* data, std::size_t size);
    void update(const std::string& bytes) { update(bytes.data(), bytes.size()); }
    // The digest as 64 lowercase hex digits; the object is spent afterwards.
    std::string hexDigest();

private:
    void compress(const unsigned char* block);
    std::array<std::uint32_t, 8> state_;
    std::array<unsigned char, 64> buffer_{};
    std::size_t buffered_ = 0;
    std::uint64_t length_ = 0;  // bytes hashed
};

std::string sha256Hex(const std::string& bytes);
// Of a file's bytes, read in blocks. Throws eikon::Error(path, reason) when it cannot be read.
std::string sha256OfFile(const std::string& path);

}  // namespace eikon
