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

// Walks grid `gd`'s bytes as Archive::readGrid will read them (compression flags, metadata,
// transform, tree) and throws VdbFormatError on a size or flag OpenVDB would trust. Grid types
// the walk does not know, instances (no tree of their own) and files older than format 222 are
// left to OpenVDB as before.
void checkGridBytes(std::istream& is, const openvdb::io::GridDescriptor& gd,
                    const VdbReader::Entry& e, const std::string& path) {
    if (openvdb::io::getFormatVersion(is) < openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION)
        return;
    gd.seekToGrid(is);
    if (e.endPos - e.gridPos < 4) throw VdbFormatError("the grid has no compression flags");
    std::uint32_t compression = 0;
    is.read(reinterpret_cast<char*>(&compression), sizeof(compression));
    checkVdbMetadata(is, e.endPos);
    // Transforms are fixed-size records that OpenVDB reads safely; read one to get past it.
    openvdb::math::Transform transform;
    transform.read(is);
    VdbTreeLayout layout;
    if (gd.isInstance() || !vdbTreeLayoutFor(e.type, e.savedAsHalf, layout)) return;
    VdbTreeNodeCounts counts;
    checkVdbTree(is, e.endPos, layout, compression, &counts);
    // A few megabytes of well-compressed leaves can expand to more than the machine holds.
    checkMemory(path, counts.bytes(layout),
                "grid '" + printable(e.name) + "' (" + std::to_string(counts.leaves) + " leaves)",
                "resample it coarser in the tool that wrote it");
}

std::string truncatedOrCorrupt(const std::string& what, const std::string& detail) {
    return what + " could not be read; the file is truncated or corrupt (" + detail + ")";
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
        throw Error(path, std::string("not a readable VDB file (") + e.what() + ")");
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
                throw Error(path, "grid '" + e.name + "' should end at byte " +
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
    const std::string what = "grid '" + e.name + "'";
    if (!e.registered)
        throw UnsupportedGridError(path_,
                                   what + " has type " + e.type + ", which is not registered here");
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
                    grid->setTree(readGrid(p)->baseTreePtr());
                    return grid;
                }
            throw std::runtime_error("its instance parent is missing");
        }
        return grid;
    } catch (const Error&) {
        throw;
    } catch (const openvdb::LookupError& ex) {
        throw UnsupportedGridError(path_, what + " cannot be decoded here (" + ex.what() + ")");
    } catch (const openvdb::KeyError& ex) {
        throw UnsupportedGridError(path_, what + " cannot be decoded here (" + ex.what() + ")");
    } catch (const std::exception& ex) {
        throw Error(path_, truncatedOrCorrupt(what, ex.what()));
    }
}

}  // namespace eikon
