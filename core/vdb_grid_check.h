#pragma once
// Walks a grid's bytes the way OpenVDB will read them and rejects what OpenVDB would trust
// blindly. OpenVDB's readers take the sizes written in the file at their word: a compressed
// block's byte count is handed to `new[]` and to Blosc, an uncompressed block is read into a
// leaf before its size is compared, Blosc decompresses by the sizes in its own header, and bool
// bytes are loaded as bool. A corrupt file then overflows the heap instead of failing. The walk
// below reads only sizes, masks and headers (never decompresses), so it is cheap, and it throws
// VdbFormatError ("<what> at byte <offset>") before OpenVDB sees a bad size.
//
// No OpenVDB headers here: the format facts the walk needs are passed in as plain numbers.
#include <cstdint>
#include <istream>
#include <stdexcept>
#include <string>

namespace eikon {

class VdbFormatError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// What a tree's nodes hold, as far as the byte layout goes. Only the standard 5-4-3 trees are
// described; other grid types (points, custom node sizes) are not walked.
struct VdbTreeLayout {
    enum class Leaf { Values, Bool, Mask };
    Leaf leaf = Leaf::Values;
    std::uint32_t valueBytes = 0;   // sizeof(ValueType) in memory and in root tiles
    std::uint32_t storedBytes = 0;  // bytes per value in node buffers (half when saved as half)
    bool boolValues = false;        // root background, tiles and inactive values are bool bytes
};

// The layout of grid type `type` (e.g. "Tree_float_5_4_3"); false when the walk does not know it.
bool vdbTreeLayoutFor(const std::string& type, bool savedAsHalf, VdbTreeLayout& out);

// Checks a metadata map (MetaMap::readMeta's format) starting at the stream's position and
// ending no later than byte `end`; returns the offset just past it. Leaves the stream there.
std::int64_t checkVdbMetadata(std::istream& is, std::int64_t end);

// Checks a string as OpenVDB stores names (readString: a 32-bit length, then that many bytes),
// starting at the stream's position and ending no later than byte `end`. readString allocates the
// stated length before reading: a corrupt one asked for up to 4 GB. Returns the offset past it.
std::int64_t checkVdbString(std::istream& is, std::int64_t end, const char* what);

// Checks a grid descriptor (GridDescriptor::read's format: the grid's unique name, its type and,
// when `hasInstanceParent` (file format >= 216), its instance parent's name, each a 32-bit length
// and that many bytes; then three 64-bit offsets) starting at the stream's position and ending no
// later than byte `end`. GridDescriptor::read allocates each string at its stated length before
// reading it: a corrupt length asked for gigabytes. Returns the offset just past the descriptor.
std::int64_t checkVdbGridDescriptor(std::istream& is, std::int64_t end, bool hasInstanceParent);

// The nodes a tree's topology declares, counted by the walk before OpenVDB allocates them.
struct VdbTreeNodeCounts {
    std::uint64_t leaves = 0;
    std::uint64_t internal[2] = {0, 0};  // 16^3 and 32^3 internal nodes
    // What OpenVDB will allocate for them (an upper bound; core/memory_limit.h).
    double bytes(const VdbTreeLayout& layout) const;
};

// Checks a tree's topology and buffers (Tree::readTopology then Tree::readBuffers, file format
// >= 222) starting at the stream's position; `compression` is the grid's io::COMPRESS_* flags.
// Returns the offset just past the last buffer, which is at most `end`; `counts`, when given,
// receives the nodes the topology declares.
std::int64_t checkVdbTree(std::istream& is, std::int64_t end, const VdbTreeLayout& layout,
                          std::uint32_t compression, VdbTreeNodeCounts* counts = nullptr);

}  // namespace eikon
