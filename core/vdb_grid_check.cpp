#include "core/vdb_grid_check.h"

#include <algorithm>
#include <array>
#include <bitset>
#include <cstring>
#include <map>
#include <vector>

namespace eikon {
namespace {

// io::COMPRESS_* and io's per-node metadata byte (openvdb/io/Compression.h).
constexpr std::uint32_t kZip = 0x1, kActiveMask = 0x2, kBlosc = 0x4;
constexpr std::int8_t kMaskAndOneInactive = 4, kMaskAndTwoInactive = 5, kNoMaskAndAllVals = 6;
constexpr std::int8_t kNoMaskAndOneInactive = 2, kMaskAndNoInactive = 3;
constexpr std::uint32_t kBloscHeaderBytes = 16;
constexpr std::uint8_t kBloscMemcpyed = 0x2;
constexpr std::uint32_t kBloscPadBytes = 128;

// Reads little-endian fields (the format's byte order on every platform Eikon runs on) within
// [position, end), so that no read ever runs off the grid or the file.
class Cursor {
public:
    Cursor(std::istream& is, std::int64_t end) : is_(is), pos_(is.tellg()), end_(end) {}

    std::int64_t pos() const { return pos_; }
    std::int64_t left() const { return end_ - pos_; }

    [[noreturn]] void fail(const std::string& what, std::int64_t at) const {
        throw VdbFormatError(what + " at byte " + std::to_string(at));
    }
    void need(std::uint64_t n, const char* what) const {
        if (pos_ > end_ || n > std::uint64_t(end_ - pos_))
            fail(std::string(what) + " needs " + std::to_string(n) + " bytes but " +
                     std::to_string(left() < 0 ? 0 : left()) + " remain",
                 pos_);
    }
    void bytes(void* dst, std::uint64_t n, const char* what) {
        need(n, what);
        is_.read(static_cast<char*>(dst), std::streamsize(n));
        pos_ += std::int64_t(n);
    }
    template <typename T>
    T get(const char* what) {
        T v{};
        bytes(&v, sizeof(T), what);
        return v;
    }
    void skip(std::uint64_t n, const char* what) {
        need(n, what);
        pos_ += std::int64_t(n);
        is_.seekg(pos_, std::ios::beg);
    }
    // A byte that OpenVDB loads as a C++ bool: anything but 0 or 1 is undefined behaviour.
    void boolByte(const char* what) {
        const std::int64_t at = pos_;
        const auto b = get<std::uint8_t>(what);
        if (b > 1)
            fail(std::string(what) + " is " + std::to_string(b) + ", not a bool (0 or 1)", at);
    }

private:
    std::istream& is_;
    std::int64_t pos_;
    std::int64_t end_;
};

std::uint32_t le32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
           std::uint32_t(p[3]) << 24;
}

// A Blosc frame of `cbytes` bytes at the cursor that must decompress to `nbytes`. Blosc 1.x
// (blosc_decompress_ctx) is not told the frame's size: it trusts the header's sizes and the
// block offsets after it, so those must agree with the file.
// `padded`: points/StreamCompression pads arrays under 128 bytes to 128 before compressing (the
// delayed-load metadata is written that way), and its reader accepts either size.
void checkBloscFrame(Cursor& c, std::uint64_t cbytes, std::uint64_t nbytes, std::int64_t at,
                     const char* what, bool padded = false) {
    if (cbytes < kBloscHeaderBytes)
        c.fail(std::string(what) + ": a Blosc block of " + std::to_string(cbytes) +
                   " bytes is shorter than its header",
               at);
    std::array<std::uint8_t, kBloscHeaderBytes> h{};
    c.bytes(h.data(), h.size(), what);
    const std::uint8_t flags = h[2];
    const std::uint32_t hn = le32(&h[4]), blocksize = le32(&h[8]), hc = le32(&h[12]);
    if (padded && hn == kBloscPadBytes && nbytes <= kBloscPadBytes) nbytes = hn;
    if (hn != nbytes)
        c.fail(std::string(what) + ": a Blosc block decompresses to " + std::to_string(hn) +
                   " bytes where " + std::to_string(nbytes) + " are expected",
               at);
    if (hc != cbytes)
        c.fail(std::string(what) + ": a Blosc block's header states " + std::to_string(hc) +
                   " compressed bytes where the file stores " + std::to_string(cbytes),
               at);
    std::uint64_t done = kBloscHeaderBytes;
    if (flags & kBloscMemcpyed) {
        if (cbytes != nbytes + kBloscHeaderBytes)
            c.fail(std::string(what) + ": a stored Blosc block of " + std::to_string(cbytes) +
                       " bytes cannot hold " + std::to_string(nbytes),
                   at);
    } else if (nbytes > 0) {
        if (blocksize == 0 || blocksize > nbytes)
            c.fail(std::string(what) + ": a Blosc block has block size " +
                       std::to_string(blocksize) + " for " + std::to_string(nbytes) + " bytes",
                   at);
        const std::uint64_t blocks = (nbytes + blocksize - 1) / blocksize;
        const std::uint64_t first = kBloscHeaderBytes + 4 * blocks;
        if (first > cbytes)
            c.fail(std::string(what) + ": a Blosc block is too short for its block table", at);
        for (std::uint64_t b = 0; b < blocks; ++b) {
            const auto start = c.get<std::uint32_t>(what);
            if (start < first || start >= cbytes)
                c.fail(std::string(what) + ": a Blosc block's sub-block " + std::to_string(b) +
                           " starts at " + std::to_string(start) + ", outside its " +
                           std::to_string(cbytes) + " bytes",
                       at);
        }
        done = first;
    }
    c.skip(cbytes - done, what);
}

// io::readData: an int64 byte count (negative: that many uncompressed bytes follow), then the
// bytes; without compression, the raw values.
void checkDataBlock(Cursor& c, std::uint64_t expected, std::uint32_t compression,
                    const char* what) {
    if (!(compression & (kBlosc | kZip))) {
        c.skip(expected, what);
        return;
    }
    const std::int64_t at = c.pos();
    const auto n = c.get<std::int64_t>(what);
    if (n <= 0) {
        const std::uint64_t raw = std::uint64_t(0) - std::uint64_t(n);
        if (raw != expected)
            c.fail(std::string(what) + ": an uncompressed block states " + std::to_string(raw) +
                       " bytes where " + std::to_string(expected) + " are expected",
                   at);
        c.skip(raw, what);
        return;
    }
    if (std::uint64_t(n) > std::uint64_t(c.left()))
        c.fail(std::string(what) + ": a compressed block states " + std::to_string(n) +
                   " bytes but " + std::to_string(c.left()) + " remain in the grid",
               at);
    if (compression & kBlosc)
        checkBloscFrame(c, std::uint64_t(n), expected, at, what);
    else
        c.skip(std::uint64_t(n), what);  // zlib is told both buffer sizes and stays inside them
}

template <size_t kBits>
std::bitset<kBits> readMask(Cursor& c, const char* what) {
    std::array<std::uint64_t, kBits / 64> words{};
    c.bytes(words.data(), sizeof(words), what);
    std::bitset<kBits> m;
    for (size_t w = 0; w < words.size(); ++w)
        for (size_t b = 0; b < 64; ++b)
            if (words[w] >> b & 1) m.set(w * 64 + b);
    return m;
}

// io::readCompressedValues for a node of kValues values whose value mask is `valueMask`.
template <size_t kValues>
void checkNodeValues(Cursor& c, const std::bitset<kValues>& valueMask, const VdbTreeLayout& L,
                     std::uint32_t compression, const char* what) {
    const std::int64_t at = c.pos();
    const auto meta = c.get<std::int8_t>(what);
    if (meta < 0 || meta > kNoMaskAndAllVals)
        c.fail(std::string(what) + ": node flag " + std::to_string(meta) + " is not one of 0-6",
               at);
    if (meta == kNoMaskAndOneInactive || meta == kMaskAndOneInactive ||
        meta == kMaskAndTwoInactive) {
        const int inactive = meta == kMaskAndTwoInactive ? 2 : 1;
        for (int i = 0; i < inactive; ++i) {
            if (L.boolValues)
                c.boolByte("an inactive bool value");
            else
                c.skip(L.valueBytes, what);
        }
    }
    if (meta == kMaskAndNoInactive || meta == kMaskAndOneInactive || meta == kMaskAndTwoInactive)
        c.skip(kValues / 8, what);  // the selection mask
    std::uint64_t count = kValues;
    if ((compression & kActiveMask) && meta != kNoMaskAndAllVals) count = valueMask.count();
    // HalfReader returns before reading anything when there are no values.
    if (L.storedBytes != L.valueBytes && count == 0) return;
    checkDataBlock(c, count * L.storedBytes, compression, what);
}

// Per child of the root: the active-value count of each leaf in the order readBuffers visits.
using LeafCounts = std::vector<std::uint16_t>;

template <int kLevel>  // 2: 32^3 internal node, 1: 16^3 internal node
void checkInternalTopology(Cursor& c, const VdbTreeLayout& L, std::uint32_t compression,
                           LeafCounts& leaves, VdbTreeNodeCounts& counts) {
    constexpr size_t kValues = kLevel == 2 ? 32768 : 4096;
    ++counts.internal[kLevel - 1];
    const auto childMask = readMask<kValues>(c, "an internal node's child mask");
    const auto valueMask = readMask<kValues>(c, "an internal node's value mask");
    checkNodeValues<kValues>(c, valueMask, L, compression, "an internal node's values");
    for (size_t i = 0; i < kValues; ++i) {
        if (!childMask.test(i)) continue;
        if constexpr (kLevel == 2) {
            checkInternalTopology<1>(c, L, compression, leaves, counts);
        } else {
            // Every leaf kind stores one 512-bit mask as its topology.
            leaves.push_back(std::uint16_t(readMask<512>(c, "a leaf's value mask").count()));
        }
    }
}

void checkLeafBuffers(Cursor& c, std::uint16_t activeCount, const VdbTreeLayout& L,
                      std::uint32_t compression) {
    switch (L.leaf) {
        case VdbTreeLayout::Leaf::Bool:  // mask, origin, value bits
            c.skip(64 + 12 + 64, "a bool leaf");
            return;
        case VdbTreeLayout::Leaf::Mask:  // value bits, origin
            c.skip(64 + 12, "a mask leaf");
            return;
        case VdbTreeLayout::Leaf::Values: {
            // The stream is seekable, so OpenVDB skips this copy of the mask and keeps the one
            // read with the topology: the counts must come from there too.
            c.skip(64, "a leaf's value mask");
            std::bitset<512> mask;
            for (std::uint16_t i = 0; i < activeCount; ++i) mask.set(i);
            checkNodeValues<512>(c, mask, L, compression, "a leaf's values");
            return;
        }
    }
}

std::uint32_t fixedMetadataBytes(const std::string& type) {
    static const std::map<std::string, std::uint32_t> sizes = {
        {"bool", 1},   {"float", 4},  {"double", 8}, {"int32", 4},  {"int64", 8},  {"vec2i", 8},
        {"vec2s", 8},  {"vec2d", 16}, {"vec3i", 12}, {"vec3s", 12}, {"vec3d", 24}, {"vec4i", 16},
        {"vec4s", 16}, {"vec4d", 32}, {"mat4s", 64}, {"mat4d", 128}};
    const auto it = sizes.find(type);
    return it == sizes.end() ? 0 : it->second;
}

std::string readName(Cursor& c, const char* what) {
    const auto n = c.get<std::uint32_t>(what);
    c.need(n, what);  // before allocating: a corrupt length must not become a 4 GB string
    std::string s(n, '\0');
    c.bytes(s.data(), n, what);
    return s;
}

// io::DelayedLoadMetadata::readValue: a count, a per-leaf flag array and an optional per-leaf
// size array, each either raw (byte count 0) or a Blosc frame of the stated byte count.
void checkDelayedLoad(Cursor& c, std::int64_t entryEnd) {
    const char* what = "the delayed-load metadata";
    const auto count = c.get<std::uint32_t>(what);
    for (int part = 0; part < 2; ++part) {
        const std::uint64_t elementBytes = part == 0 ? 1 : 8;
        const std::int64_t at = c.pos();
        const auto bytes = c.get<std::uint32_t>(what);
        if (part == 1 && bytes == 0xffffffffu) break;  // no size array
        if (bytes == 0) {
            c.skip(std::uint64_t(count) * elementBytes, what);
        } else {
            if (std::int64_t(bytes) > entryEnd - c.pos())
                c.fail(std::string(what) + ": a compressed block states " + std::to_string(bytes) +
                           " bytes, past the end of the entry",
                       at);
            checkBloscFrame(c, bytes, std::uint64_t(count) * elementBytes, at, what,
                            /*padded=*/true);
        }
    }
    if (c.pos() > entryEnd) c.fail(std::string(what) + " runs past the end of its entry", entryEnd);
}

}  // namespace

bool vdbTreeLayoutFor(const std::string& type, bool savedAsHalf, VdbTreeLayout& out) {
    struct Known {
        const char* name;
        std::uint32_t bytes, halfBytes;  // halfBytes 0: not a real type, never stored as half
        VdbTreeLayout::Leaf leaf;
    };
    static const Known known[] = {
        {"Tree_float_5_4_3", 4, 2, VdbTreeLayout::Leaf::Values},
        {"Tree_double_5_4_3", 8, 2, VdbTreeLayout::Leaf::Values},
        {"Tree_int32_5_4_3", 4, 0, VdbTreeLayout::Leaf::Values},
        {"Tree_int64_5_4_3", 8, 0, VdbTreeLayout::Leaf::Values},
        {"Tree_vec3s_5_4_3", 12, 6, VdbTreeLayout::Leaf::Values},
        {"Tree_vec3d_5_4_3", 24, 6, VdbTreeLayout::Leaf::Values},
        {"Tree_vec3i_5_4_3", 12, 0, VdbTreeLayout::Leaf::Values},
        {"Tree_bool_5_4_3", 1, 0, VdbTreeLayout::Leaf::Bool},
        {"Tree_mask_5_4_3", 1, 0, VdbTreeLayout::Leaf::Mask},
    };
    for (const Known& k : known) {
        if (type != k.name) continue;
        out.leaf = k.leaf;
        out.valueBytes = k.bytes;
        out.storedBytes = savedAsHalf && k.halfBytes ? k.halfBytes : k.bytes;
        out.boolValues = k.leaf != VdbTreeLayout::Leaf::Values;
        return true;
    }
    return false;
}

std::int64_t checkVdbMetadata(std::istream& is, std::int64_t end) {
    Cursor c(is, end);
    const auto count = c.get<std::uint32_t>("the metadata count");
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::int64_t at = c.pos();
        const std::string name = readName(c, "a metadata name");
        const std::string type = readName(c, "a metadata type");
        const auto bytes = c.get<std::uint32_t>("a metadata size");
        c.need(bytes, "a metadata value");
        const std::int64_t valueEnd = c.pos() + bytes;
        if (type == "__delayedload") {
            if (bytes > 0) checkDelayedLoad(c, valueEnd);
        } else if (const std::uint32_t fixed = fixedMetadataBytes(type)) {
            if (bytes != fixed)
                c.fail("metadata of type " + type + " states " + std::to_string(bytes) +
                           " bytes where the type holds " + std::to_string(fixed),
                       at);
            if (type == "bool") c.boolByte("a bool metadata value");
        }
        c.skip(std::uint64_t(valueEnd - c.pos()), "a metadata value");
    }
    return c.pos();
}

std::int64_t checkVdbString(std::istream& is, std::int64_t end, const char* what) {
    Cursor c(is, end);
    readName(c, what);
    return c.pos();
}

std::int64_t checkVdbGridDescriptor(std::istream& is, std::int64_t end, bool hasInstanceParent) {
    Cursor c(is, end);
    readName(c, "a grid name");
    readName(c, "a grid type");
    if (hasInstanceParent) readName(c, "a grid's instance parent name");
    c.skip(3 * sizeof(std::int64_t), "a grid's offsets");
    return c.pos();
}

double VdbTreeNodeCounts::bytes(const VdbTreeLayout& L) const {
    // OpenVDB's nodes: a leaf's 512 values (or bits) and masks; an internal node's table of
    // 4096 or 32768 child-or-tile unions (8 bytes, or the value when it is larger) and masks.
    const double leafBytes =
        L.leaf == VdbTreeLayout::Leaf::Values ? 512.0 * L.valueBytes + 96.0 : 192.0;
    const double slot = std::max(8.0, double(L.valueBytes));
    // The grid, its transform, metadata and root node: a few KiB, and a map entry per child.
    constexpr double kGridBytes = 4096.0;
    return kGridBytes + double(leaves) * leafBytes +
           double(internal[0]) * (4096.0 * slot + 1024.0) +
           double(internal[1]) * (32768.0 * slot + 8192.0 + 128.0);
}

std::int64_t checkVdbTree(std::istream& is, std::int64_t end, const VdbTreeLayout& L,
                          std::uint32_t compression, VdbTreeNodeCounts* countsOut) {
    VdbTreeNodeCounts counts;
    Cursor c(is, end);
    const std::int64_t countAt = c.pos();
    const auto bufferCount = c.get<std::int32_t>("the tree's buffer count");
    if (bufferCount != 1)
        c.fail("the tree states " + std::to_string(bufferCount) + " buffers where 1 is expected",
               countAt);
    // RootNode::readTopology: background, tiles (origin, value, active byte), then children.
    if (L.boolValues)
        c.boolByte("the bool background");
    else
        c.skip(L.valueBytes, "the background value");
    const auto tiles = c.get<std::uint32_t>("the root tile count");
    const auto children = c.get<std::uint32_t>("the root child count");
    std::map<std::array<std::int32_t, 3>, LeafCounts> roots;  // RootNode's map order
    for (std::uint32_t t = 0; t < tiles; ++t) {
        c.skip(12, "a root tile's origin");
        if (L.boolValues)
            c.boolByte("a root tile's bool value");
        else
            c.skip(L.valueBytes, "a root tile's value");
        c.boolByte("a root tile's active flag");
    }
    for (std::uint32_t n = 0; n < children; ++n) {
        std::array<std::int32_t, 3> origin{};
        c.bytes(origin.data(), sizeof(origin), "a root child's origin");
        LeafCounts leaves;
        checkInternalTopology<2>(c, L, compression, leaves, counts);
        counts.leaves += leaves.size();
        roots[origin] = std::move(leaves);  // a repeated origin replaces the earlier child
    }
    if (countsOut) *countsOut = counts;
    // Tree::readBuffers visits the root's children in map order, leaves depth first.
    for (const auto& [origin, leaves] : roots)
        for (const std::uint16_t active : leaves) checkLeafBuffers(c, active, L, compression);
    return c.pos();
}

}  // namespace eikon
