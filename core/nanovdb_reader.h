#pragma once
// NanoVDB files (.nvdb) read as OpenVDB grids, so that they go through the same importer as .vdb
// files: the same aliases, checks and errors. NanoVDB's own reader trusts the file (a size in a
// header becomes an allocation, an offset in a grid a pointer), so every size is checked against
// the file first, and every grid against NanoVDB's validator (its checksum, where the writer
// stored one) before it is converted.
#include <string>
#include <vector>

#include <openvdb/openvdb.h>

namespace eikon {

struct NanoVdbGrid {
    std::string name;
    std::string type;             // NanoVDB's name: float, Float16, Vec3f, int32, ...
    openvdb::GridBase::Ptr grid;  // float, double, vec3s (from half-like fp4/8/16/N: float);
                                  // null for a type that is not a field (say why in `skipped`)
    std::string skipped;
};

// Throws eikon::Error(path, reason) for a missing, truncated, compressed (ZIP, Blosc: not built
// into Debian's NanoVDB) or corrupt file, or one of another NanoVDB major version.
std::vector<NanoVdbGrid> readNanoVdb(const std::string& path);

}  // namespace eikon
