#pragma once
// The benchmark's peer for advection alone: OpenVDB's tools::VolumeAdvection driven through the
// same problems (advection_problems.h) as advectField(), so that `eikon bench advection --peer`
// reports both on the same grid, the same steps and the same error metric.
//
// The density becomes a sparse FloatGrid (voxel (i, j, k) = cell (i, j, k), voxel size h, only
// non-zero cells active) and the face velocities a staggered Vec3fGrid (OpenVDB's staggered
// voxel (i, j, k) holds each component on its lower face, which is exactly face (i, j, k) of
// each MacGrid lattice). Each step calls VolumeAdvection::advect with a mask of the box, so that
// the active region, which OpenVDB dilates by the distance the flow can carry values, never
// grows outside the box we advect in. Only that call is timed; building the velocity grid and
// the VolumeAdvection object on it each step is not (the problems change the velocity, and our
// side does not time setting it either).
//
// OpenVDB's headers are heavy: they stay in openvdb_advection_peer.cpp.
#include <memory>

#include "sim/advection_problems.h"

namespace eikon::sim {

// OpenVDB's names: SEMI is forward-Euler semi-Lagrangian, MID a midpoint (RK2) back-trace like
// ours; MAC and BFECC back-trace with Euler and apply the limiter after.
enum class VdbIntegrator { Semi, Mid, MacCormack, Bfecc };
enum class VdbLimiter { None, Clamp, Revert };

const char* vdbIntegratorName(VdbIntegrator integrator);  // "SEMI", "MID", "MAC", "BFECC"
const char* openVdbVersion();                             // of the library linked, "10.0.1"

std::unique_ptr<DensityAdvector> makeOpenVdbAdvector(VdbIntegrator integrator, VdbLimiter limiter);

}  // namespace eikon::sim
