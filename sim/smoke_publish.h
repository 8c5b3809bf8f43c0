#pragma once
// Hands the smoke state to the rest of Eikon as OpenVDB fields: `density` and `temperature`
// (float grids, one voxel per cell) and `velocity` (a vec3 grid of class staggered holding the
// MAC faces in OpenVDB's convention: voxel (i, j, k) keeps the x component of its -x face, the y
// component of its -y face and the z component of its -z face). The transform matches core's
// (core/procedural.cpp): voxel (i, j, k)'s centre is at origin + (i+½, j+½, k+½)·h, so that
// core/resample.cpp and the VDB export read them like any imported cache.
//
// OpenVDB is included only by the .cpp, so that the solver's users compile quickly.
#include <string>

#include "sim/mac_grid.h"

namespace eikon {
class FieldRegistry;
}

namespace eikon::sim {

// Stores the three fields in `registry` (replacing earlier versions). Cells whose value equals
// the grid's background (0) stay inactive; `origin` says where they came from in messages. With
// a `label` (a smoke domain's, core/simulation_spec.h) the fields and their grids are named
// "density.<label>" and so on, so that several domains' fields stand side by side; a cache file
// is written unlabelled, with the names other tools read.
void publishSmoke(const MacGrid& grid, FieldRegistry& registry, const std::string& origin,
                  const std::string& label = "");

}  // namespace eikon::sim
