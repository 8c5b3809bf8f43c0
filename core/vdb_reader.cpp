#include "core/vdb_reader.h"

#include <filesystem>
#include <fstream>

#include <openvdb/io/GridDescriptor.h>

#include "core/error.h"
#include "core/memory_limit.h"
#include "core/printable.h"
#include "core/vdb_grid_check.h"
#include "core/vdb_import.h"

namespace eikon {

// Archive keeps the pieces of the format reader protected; a subclass may call them.
struct VdbReader::Impl : public openvdb::io::Archive {
    std::ifstream stream;
    openvdb::io::StreamMetadata::Ptr streamMeta;
    std::vector<openvdb::io::GridDescriptor> descriptors;  // parallel to entries (registered)
    std::uintmax_t fileSize = 0;

    bool readHeaderOf(std::istream& is) { return readHeader(is); }
    void tagStream(std::istream& is) {
        streamMeta = std::make_shared<openvdb::io::StreamMetadata>();
        streamMeta->setSeekable(true);
        openvdb::io::setStreamMetadataPtr(is, streamMeta, /*transfer=*/false);
        setFormatVersion(is);
        setLibraryVersion(is);
        setDataCompression(is);
    }
    static int32_t gridCount(std::istream& is) { return readGridCount(is); }
    static void readGridData(openvdb::GridBase::Ptr grid, const openvdb::io::GridDescriptor& gd,
                             std::istream& is) {
        openvdb::io::Archive::readGrid(grid, gd, is);
    }
};

namespace {

// A grid as messages name it; the name is the file's and may hold control characters.
std::string gridLabel(const std::string& name) {
    return "grid '" + printable(name) + "'";
}

// Walks grid `gd`'s bytes as Archive::readGrid will read them (compression flags, metadata,
// transform, tree) and throws VdbFormatError on a size or flag OpenVDB would trust. Instances
// have no tree of their own; their parent's is walked when it is read.
void checkGridBytes(std::istream& is, const openvdb::io::GridDescriptor& gd,
                    const VdbReader::Entry& e, const std::string& path) {
    gd.seekToGrid(is);
    if (e.endPos - e.gridPos < 4) throw VdbFormatError("the grid has no compression flags");
    std::uint32_t compression = 0;
    is.read(reinterpret_cast<char*>(&compression), sizeof(compression));
    const std::streampos metaPos = is.tellg();
    checkVdbMetadata(is, e.endPos);
    // Whether values are stored as half floats is what the grid's own metadata says
    // (GridBase::saveFloatAsHalf, read after readMeta), not the descriptor's "_HalfFloat": a file
    // where the two disagree had its tree walked at the wrong value size (found by fuzz_vdb).
    // The metadata's bytes were checked just above, so OpenVDB reads them safely.
    is.seekg(metaPos);
    openvdb::MetaMap meta;
    meta.readMeta(is);
    const openvdb::Metadata::ConstPtr half = meta[openvdb::GridBase::META_SAVE_HALF_FLOAT];
    VdbTreeLayout layout;
    if (!vdbTreeLayoutFor(e.type, half && half->asBool(), layout))
        throw VdbFormatError("grid type " + e.type + " has no known layout");
    // A transform is its map's type name, then a fixed-size record that OpenVDB reads safely;
    // the name's length is checked first (OpenVDB allocates it unread), then one is read to get
    // past it.
    const std::streampos transformPos = is.tellg();
    checkVdbString(is, e.endPos, "the transform's map type");
    is.seekg(transformPos);
    openvdb::math::Transform transform;
    transform.read(is);
    if (gd.isInstance()) return;
    VdbTreeNodeCounts counts;
    checkVdbTree(is, e.endPos, layout, compression, &counts);
    // A few megabytes of well-compressed leaves can expand to more than the machine holds.
    checkMemory(path, counts.bytes(layout),
                gridLabel(e.name) + " (" + std::to_string(counts.leaves) + " leaves)",
                "resample it coarser in the tool that wrote it");
}

// `detail` is OpenVDB's message, which may quote the file's bytes: escaped here.
std::string truncatedOrCorrupt(const std::string& what, const std::string& detail) {
    return what + " could not be read; the file is truncated or corrupt (" +
           printable(detail, 200) + ")";
}

}  // namespace

VdbReader::VdbReader(const std::string& path) : path_(path), impl_(std::make_unique<Impl>()) {
    ensureOpenVdbInitialized();
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw Error(path, "no such file");
    if (!std::filesystem::is_regular_file(path, ec)) throw Error(path, "is not a regular file");
    impl_->fileSize = std::filesystem::file_size(path, ec);
    std::ifstream& is = impl_->stream;
    is.open(path, std::ios::in | std::ios::binary);
    if (!is) throw Error(path, "cannot be opened for reading");
    is.exceptions(std::ios::failbit | std::ios::badbit);

    try {
        impl_->readHeaderOf(is);
    } catch (const std::exception& e) {
        throw Error(path,
                    std::string("not a readable VDB file (") + printable(e.what(), 200) + ")");
    }
    fileVersion_ = impl_->version();
    try {
        impl_->tagStream(is);
        meta_ = std::make_shared<openvdb::MetaMap>();
        {
            const std::streampos metaPos = is.tellg();
            try {
                checkVdbMetadata(is, std::int64_t(impl_->fileSize));
            } catch (const VdbFormatError& err) {
                throw Error(path, truncatedOrCorrupt("the file metadata", err.what()));
            }
            is.seekg(metaPos);
        }
        meta_->readMeta(is);
        const int32_t count = Impl::gridCount(is);
        if (count < 0 || count > 1000000)
            throw std::runtime_error("implausible grid count " + std::to_string(count));
        for (int32_t i = 0; i < count; ++i) {
            openvdb::io::GridDescriptor gd;
            Entry e;
            {
                const std::streampos descriptorPos = is.tellg();
                checkVdbGridDescriptor(is, std::int64_t(impl_->fileSize),
                                       openvdb::io::getFormatVersion(is) >=
                                           openvdb::OPENVDB_FILE_VERSION_GRID_INSTANCING);
                is.seekg(descriptorPos);
            }
            try {
                gd.read(is);
            } catch (const openvdb::LookupError&) {
                // The type is not registered; the descriptor's offsets follow (GridDescriptor.cc).
                e.registered = false;
                is.read(reinterpret_cast<char*>(&e.gridPos), sizeof(int64_t));
                is.read(reinterpret_cast<char*>(&e.blockPos), sizeof(int64_t));
                is.read(reinterpret_cast<char*>(&e.endPos), sizeof(int64_t));
            }
            e.name = gd.gridName();
            e.type = gd.gridType();
            e.savedAsHalf = gd.saveFloatAsHalf();
            e.instanceParent = gd.instanceParentName();
            if (e.registered) {
                e.gridPos = gd.getGridPos();
                e.blockPos = gd.getBlockPos();
                e.endPos = gd.getEndPos();
            }
            if (e.gridPos < 0 || e.gridPos > e.endPos || std::uintmax_t(e.endPos) > impl_->fileSize)
                throw Error(path, gridLabel(e.name) + " should end at byte " +
                                      std::to_string(e.endPos) + " but the file has " +
                                      std::to_string(impl_->fileSize) +
                                      " bytes: the file is truncated or corrupt");
            entries_.push_back(e);
            impl_->descriptors.push_back(gd);
            is.seekg(e.endPos, std::ios::beg);
        }
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(path, truncatedOrCorrupt("the grid directory", e.what()));
    }
}

VdbReader::~VdbReader() = default;

std::string VdbReader::creator() const {
    if (auto c = (*meta_)["creator"]) return c->str();
    return "";
}

openvdb::GridBase::Ptr VdbReader::readGrid(size_t index) {
    const Entry& e = entries_.at(index);
    const std::string what = gridLabel(e.name);
    if (!e.registered)
        throw UnsupportedGridError(
            path_, what + " has type " + printable(e.type) + ", which is not registered here");
    // OpenVDB reads what the walk below does not know without checking its sizes: a point grid's
    // Blosc block asked for 10^17 bytes (found by fuzz_vdb). Such grids are not read at all.
    VdbTreeLayout layout;
    if (!vdbTreeLayoutFor(e.type, false, layout))
        throw UnsupportedGridError(path_, what + " has type " + printable(e.type) +
                                              ", whose bytes this reader cannot check (it reads "
                                              "float, double, integer, vector, bool and mask "
                                              "grids)");
    const std::uint32_t format = openvdb::io::getFormatVersion(impl_->stream);
    if (format < openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION)
        throw UnsupportedGridError(
            path_, what + " is stored in VDB file format " + std::to_string(format) +
                       ", older than the " +
                       std::to_string(openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION) +
                       " this reader can check");
    try {
        const openvdb::io::GridDescriptor& gd = impl_->descriptors[index];
        openvdb::GridBase::Ptr grid = openvdb::GridBase::createGrid(e.type);
        grid->setSaveFloatAsHalf(e.savedAsHalf);
        impl_->stream.clear();
        checkGridBytes(impl_->stream, gd, e, path_);
        impl_->stream.clear();
        gd.seekToGrid(impl_->stream);
        Impl::readGridData(grid, gd, impl_->stream);
        if (gd.isInstance()) {
            for (size_t p = 0; p < entries_.size(); ++p)
                if (p != index && impl_->descriptors[p].uniqueName() == gd.instanceParentName()) {
                    // OpenVDB writes an instance of the grid that holds the tree, never of
                    // another instance; following one here could recurse without end (two
                    // grids naming each other overflowed the stack).
                    if (impl_->descriptors[p].isInstance())
                        throw std::runtime_error("its instance parent " +
                                                 gridLabel(entries_[p].name) +
                                                 " is an instance itself");
                    grid->setTree(readGrid(p)->baseTreePtr());
                    return grid;
                }
            throw std::runtime_error("its instance parent is missing");
        }
        return grid;
    } catch (const Error&) {
        throw;
    } catch (const openvdb::LookupError& ex) {
        throw UnsupportedGridError(
            path_, what + " cannot be decoded here (" + printable(ex.what(), 200) + ")");
    } catch (const openvdb::KeyError& ex) {
        throw UnsupportedGridError(
            path_, what + " cannot be decoded here (" + printable(ex.what(), 200) + ")");
    } catch (const std::exception& ex) {
        throw Error(path_, truncatedOrCorrupt(what, ex.what()));
    }
}

}  // namespace eikon
