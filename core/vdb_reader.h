#pragma once
// A VDB reader that notices truncated and corrupt files. OpenVDB's io::File reads through a
// stream whose short reads fail silently, so a file cut in half loads as grids full of zeros.
// This reader walks the same format (header, file metadata, grid descriptors) on a stream that
// throws on any short read, checks every grid's byte range against the file size, and can skip a
// grid whose type is not registered while still reading the others.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <openvdb/openvdb.h>

#include "core/error.h"

namespace eikon {

// A grid OpenVDB here cannot decode (unregistered grid type, unregistered point attribute
// codec), or one whose bytes this reader cannot check before OpenVDB trusts them (point grids,
// files older than format 222): callers skip it by name and go on with the rest of the file.
class UnsupportedGridError : public Error {
public:
    using Error::Error;
};

class VdbReader {
public:
    struct Entry {
        std::string name;
        std::string type;  // as stored, without the half-float suffix
        bool savedAsHalf = false;
        bool registered = true;  // false: OpenVDB here cannot create this grid type
        std::string instanceParent;
        std::int64_t gridPos = 0, blockPos = 0, endPos = 0;
    };

    // Opens `path` and reads everything but the grids' data. Throws eikon::Error(path, reason)
    // when the file is missing, not a VDB file, or truncated.
    explicit VdbReader(const std::string& path);
    ~VdbReader();

    const std::string& path() const { return path_; }
    const std::vector<Entry>& entries() const { return entries_; }
    const openvdb::MetaMap& fileMetadata() const { return *meta_; }
    std::string creator() const;
    std::string fileVersion() const { return fileVersion_; }

    // Reads grid `index` completely. Throws eikon::Error(path, "grid 'x' could not be read; the
    // file is truncated or corrupt (...)") on bad bytes, UnsupportedGridError when the type or
    // one of its codecs is not registered here, or its bytes cannot be checked.
    openvdb::GridBase::Ptr readGrid(size_t index);

private:
    struct Impl;
    std::string path_;
    std::string fileVersion_;
    std::unique_ptr<Impl> impl_;
    openvdb::MetaMap::Ptr meta_;
    std::vector<Entry> entries_;
};

}  // namespace eikon
