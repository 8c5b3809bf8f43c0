#pragma once
// Level-set files for tests (issue 20), written with OpenVDB's own tools as Houdini's "VDB from
// Polygons" or OpenVDB's sphere.vdb would be: a narrow band of signed distance, class "level set".
#include <string>

#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

namespace eikon::test {

// A sphere of `radius` around `centre`, sampled every `voxel`, three voxels of band each side,
// written alone to `path` under `name` (empty: unnamed, as zeno writes its SDFs).
inline void writeLevelSetSphere(const std::string& path, float radius, openvdb::Vec3f centre,
                                float voxel, const std::string& name = "surface") {
    openvdb::initialize();
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(radius, centre, voxel);
    grid->setName(name);
    openvdb::io::File(path).write({grid});
}

}  // namespace eikon::test
