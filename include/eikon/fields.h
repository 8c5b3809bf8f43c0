#pragma once
// Fields as OpenVDB grids, for a Session (eikon/eikon.h) and for files: what a simulation made,
// what a scene loaded, and VDB files read through Eikon's checked reader (a truncated or corrupt
// file is an eikon::Error, not grids of zeros) and written as `eikon simulate` writes its caches.
// Needs OpenVDB's headers and library (find_package(Eikon) brings them).
#include <string>
#include <vector>

#include <openvdb/openvdb.h>

#include "eikon/eikon.h"

namespace eikon {

// The names of the fields the session holds now: those its live simulations made up to the
// frame last stepped to or rendered, and, once a frame was rendered, those its sources loaded
// ("density", "temperature", "velocity", ...).
std::vector<std::string> fieldNames(Session& session);
// A field as a grid: shared with the session, so copy it (grid->deepCopyGrid()) to change it.
// Throws eikon::Error naming the fields there are when there is none of that name.
openvdb::GridBase::ConstPtr fieldGrid(Session& session, const std::string& name);

// Every grid of a VDB file that OpenVDB here can decode.
openvdb::GridPtrVec readFields(const std::string& path);
// Writes float and vec3 grids by their names, atomically (a failure leaves no half file).
void writeFields(const std::string& path, const openvdb::GridCPtrVec& grids);

}  // namespace eikon
