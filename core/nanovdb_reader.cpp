#include "core/nanovdb_reader.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <type_traits>

#include <nanovdb/NanoVDB.h>
#include <nanovdb/util/GridChecksum.h>
#include <nanovdb/util/GridHandle.h>
#include <nanovdb/util/GridValidator.h>
#include <nanovdb/util/HostBuffer.h>
#include <nanovdb/util/IO.h>
#include <nanovdb/util/NanoToOpenVDB.h>

#include "core/error.h"
#include "core/printable.h"

namespace eikon {
namespace {

// Grid names longer than this are not names: a corrupt size.
constexpr uint32_t kMaxNameBytes = 4096;

// True when every node the converter and the validator reach lies inside the grid's `size`
// bytes: the root and its table, each upper, lower and leaf node by the pointers that lead to
// it (a leaf of variable bit width by its own size), and the linear runs NanoVDB's node manager
// assumes (first node of a level, times its count). NanoVDB trusts these offsets; a corrupt one
// would be read as memory.
template <typename BuildT>
bool nodesInside(const nanovdb::NanoGrid<BuildT>& grid, uint64_t size) {
    using TreeT = typename nanovdb::NanoGrid<BuildT>::TreeType;
    using RootT = typename TreeT::RootType;
    using UpperT = typename RootT::ChildNodeType;
    using LowerT = typename UpperT::ChildNodeType;
    using LeafT = typename LowerT::ChildNodeType;
    const char* begin = reinterpret_cast<const char*>(&grid);
    const char* end = begin + size;
    auto inside = [&](const void* p, uint64_t bytes) {
        const char* c = static_cast<const char*>(p);
        return c >= begin && c < end && bytes <= uint64_t(end - c) &&
               reinterpret_cast<uintptr_t>(c) % NANOVDB_DATA_ALIGNMENT == 0;
    };
    const TreeT& tree = grid.tree();
    if (!inside(&tree, sizeof(TreeT))) return false;
    const RootT* root = tree.data()->template getRoot<RootT>();
    if (!inside(root, sizeof(RootT)) || !inside(root, root->memUsage())) return false;
    // The checksum's head: grid, tree and root, read as one run from the grid's start.
    if (grid.memUsage() + tree.memUsage() + root->memUsage() > size) return false;
    uint64_t counts[3] = {0, 0, 0};
    const auto* rootData = root->data();
    for (uint32_t t = 0; t < rootData->mTableSize; ++t) {
        const auto* tile = rootData->tile(t);
        if (!tile->isChild()) continue;
        const UpperT* upper = rootData->getChild(tile);
        if (!inside(upper, sizeof(UpperT))) return false;
        ++counts[2];
        for (auto u = upper->data()->mChildMask.beginOn(); u; ++u) {
            const LowerT* lower = upper->data()->getChild(*u);
            if (!inside(lower, sizeof(LowerT))) return false;
            ++counts[1];
            for (auto l = lower->data()->mChildMask.beginOn(); l; ++l) {
                const LeafT* leaf = lower->data()->getChild(*l);
                if (!inside(leaf, sizeof(LeafT)) || !inside(leaf, leaf->data()->memUsage()))
                    return false;
                ++counts[0];
            }
        }
    }
    // The node manager's runs: the counts the tree states, from the offsets it states.
    const uint64_t nodeSize[3] = {sizeof(LeafT), sizeof(LowerT), sizeof(UpperT)};
    for (int level = 0; level < 3; ++level) {
        if (tree.nodeCount(level) != counts[level]) return false;
        if (counts[level] == 0) continue;
        const char* first =
            reinterpret_cast<const char*>(tree.data()) + tree.data()->mNodeOffset[level];
        // A leaf of variable bit width (FpN) has no fixed stride; its nodes were walked above.
        const uint64_t stride = std::is_same<BuildT, nanovdb::FpN>::value && level == 0
                                    ? sizeof(LeafT)
                                    : nodeSize[level];
        if (!inside(first, stride) || counts[level] > uint64_t(end - first) / stride) return false;
    }
    return true;
}

// The grid as OpenVDB's, once its nodes are inside the file's bytes and NanoVDB's validator
// accepts it; null when its type is not a field.
template <typename BuildT>
openvdb::GridBase::Ptr convertChecked(const nanovdb::GridHandle<nanovdb::HostBuffer>& handle,
                                      const std::string& path, const std::string& name) {
    const nanovdb::NanoGrid<BuildT>* grid = handle.grid<BuildT>();
    if (!grid) return nullptr;
    if (grid->checksum() == nanovdb::GridChecksum::EMPTY)
        throw Error(path, "grid '" + name +
                              "' was written without a checksum, which eikon needs to trust a "
                              "NanoVDB file; write it with one (NanoVDB's default)");
    // Blind data (point attributes, a name over 256 characters) is reached by offsets this reader
    // does not bound; a field grid has none.
    if (grid->blindDataCount() != 0)
        throw Error(path, "grid '" + name +
                              "' carries blind data (points, or a name over 256 characters), "
                              "which eikon does not read");
    if (grid->gridSize() != handle.size() || !nodesInside(*grid, handle.size()))
        throw Error(path,
                    "grid '" + name + "' has node offsets outside its bytes: the file is corrupt");
    if (!nanovdb::isValid(*grid, /*detailed=*/true))
        throw Error(path, "grid '" + name +
                              "' fails NanoVDB's validation (checksum or structure): the file is "
                              "corrupt");
    return nanovdb::nanoToOpenVDB(*grid);
}

}  // namespace

std::vector<NanoVdbGrid> readNanoVdb(const std::string& path) {
    std::error_code ec;
    const std::uintmax_t fileSize = std::filesystem::file_size(path, ec);
    if (ec) throw Error(path, "cannot read: " + ec.message());
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path, "cannot open");
    auto truncated = [&](const std::string& what) {
        return Error(path, "truncated NanoVDB file: " + what + " ends past the file's " +
                               std::to_string(fileSize) + " bytes");
    };
    std::vector<NanoVdbGrid> grids;
    std::uintmax_t at = 0;
    // One or more segments, each a header and its grids' metadata, names and data.
    while (at < fileSize) {
        nanovdb::io::Header header;
        if (fileSize - at < sizeof(header)) throw truncated("a segment header");
        in.read(reinterpret_cast<char*>(&header), sizeof(header));
        at += sizeof(header);
        if (header.magic != NANOVDB_MAGIC_NUMBER)
            throw Error(path, "not a NanoVDB segment at byte " + std::to_string(at - 16) +
                                  " (bad magic number)");
        if (header.version.getMajor() != NANOVDB_MAJOR_VERSION_NUMBER)
            throw Error(path, "written by NanoVDB " + std::to_string(header.version.getMajor()) +
                                  "." + std::to_string(header.version.getMinor()) +
                                  "; this build reads major version " +
                                  std::to_string(NANOVDB_MAJOR_VERSION_NUMBER));
        if (header.codec != nanovdb::io::Codec::NONE)
            throw Error(path, std::string("compressed with ") + nanovdb::io::toStr(header.codec) +
                                  ", which this NanoVDB build does not decode; write it "
                                  "uncompressed (Codec::NONE)");
        if (header.gridCount == 0) throw Error(path, "a NanoVDB segment with no grids");
        std::vector<nanovdb::io::MetaData> metas(header.gridCount);
        std::vector<std::string> names(header.gridCount);
        for (size_t g = 0; g < metas.size(); ++g) {
            if (fileSize - at < sizeof(nanovdb::io::MetaData)) throw truncated("grid metadata");
            in.read(reinterpret_cast<char*>(&metas[g]), sizeof(nanovdb::io::MetaData));
            at += sizeof(nanovdb::io::MetaData);
            const uint32_t nameSize = metas[g].nameSize;
            if (nameSize == 0 || nameSize > kMaxNameBytes)
                throw Error(path, "corrupt NanoVDB metadata: a grid name of " +
                                      std::to_string(nameSize) + " bytes");
            if (fileSize - at < nameSize) throw truncated("a grid name");
            std::string name(nameSize, '\0');
            in.read(name.data(), nameSize);
            at += nameSize;
            names[g] = name.c_str();  // stored with its '\0'
        }
        for (size_t g = 0; g < metas.size(); ++g) {
            const nanovdb::io::MetaData& m = metas[g];
            const std::string shown = names[g].empty() ? "(unnamed)" : printable(names[g]);
            // Uncompressed: the bytes on disk are the grid in memory.
            if (m.fileSize != m.gridSize || m.gridSize < sizeof(nanovdb::GridData))
                throw Error(path, "corrupt NanoVDB metadata for grid '" + shown + "' (size " +
                                      std::to_string(m.gridSize) + ", on disk " +
                                      std::to_string(m.fileSize) + ")");
            if (fileSize - at < m.fileSize) throw truncated("grid '" + shown + "'");
            nanovdb::HostBuffer buffer = nanovdb::HostBuffer::create(m.gridSize);
            in.read(reinterpret_cast<char*>(buffer.data()), std::streamsize(m.gridSize));
            at += m.fileSize;
            if (!in) throw truncated("grid '" + shown + "'");
            nanovdb::GridHandle<nanovdb::HostBuffer> handle(std::move(buffer));
            NanoVdbGrid out;
            out.name = names[g];
            out.type = nanovdb::toStr(m.gridType);
            if (!handle.gridMetaData() || handle.gridMetaData()->gridType() != m.gridType)
                throw Error(path, "grid '" + shown + "' does not match its metadata: corrupt");
            // Half-like encodings convert to float grids; vectors to vec3s.
            if (!(out.grid = convertChecked<float>(handle, path, shown)) &&
                !(out.grid = convertChecked<double>(handle, path, shown)) &&
                !(out.grid = convertChecked<nanovdb::Fp16>(handle, path, shown)) &&
                !(out.grid = convertChecked<nanovdb::Fp8>(handle, path, shown)) &&
                !(out.grid = convertChecked<nanovdb::Fp4>(handle, path, shown)) &&
                !(out.grid = convertChecked<nanovdb::FpN>(handle, path, shown)) &&
                !(out.grid = convertChecked<nanovdb::Vec3f>(handle, path, shown)))
                out.skipped =
                    out.type + " grid, not a field type (float, fp16/8/4/N, double, vec3f)";
            if (out.grid) {
                out.grid->setName(out.name);
                if (m.gridClass == nanovdb::GridClass::FogVolume)
                    out.grid->setGridClass(openvdb::GRID_FOG_VOLUME);
                else if (m.gridClass == nanovdb::GridClass::LevelSet)
                    out.grid->setGridClass(openvdb::GRID_LEVEL_SET);
                else if (m.gridClass == nanovdb::GridClass::Staggered)
                    out.grid->setGridClass(openvdb::GRID_STAGGERED);
            }
            grids.push_back(std::move(out));
        }
    }
    if (grids.empty()) throw Error(path, "a NanoVDB file with no grids");
    return grids;
}

}  // namespace eikon
