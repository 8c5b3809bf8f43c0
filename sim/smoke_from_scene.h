#pragma once
// Builds the smoke solver a scene's "simulation" section describes (core/simulation_spec.h):
// the one place where core's plain settings become sim's types.
#include "core/scene.h"
#include "core/simulation_spec.h"
#include "sim/smoke_solver.h"

namespace eikon::sim {

SmokeSettings smokeSettingsFrom(const SmokeSimulationSpec& spec, double fps);

// A solver with the spec's sources and obstacles added, at frame 0. Throws eikon::Error when
// the settings are unusable, or when an obstacle is a mesh (those need the scene's meshes: use
// the overload below).
SmokeSolver smokeSolverFrom(const SmokeSimulationSpec& spec, double fps);

// The solver of smoke domain `domain` of a scene (Scene::simulations; throws when there is no
// such domain), starting at the scene's frame_start: the same as above, and the scene's tracks on
// the domain's sources (/simulation/sources/... or /simulation/<domain>/sources/...) applied at
// every substep's time (SourceUpdate), so a moving source leaves a smooth trail; mesh obstacles
// read (files), placed and voxelized at the cell centres (core/mesh_voxelize.h).
SmokeSolver smokeSolverFrom(const Scene& scene, std::size_t domain = 0);

// The solver's form of the spec's sources.
std::vector<SmokeSource> smokeSourcesFrom(const SmokeSimulationSpec& spec);

}  // namespace eikon::sim
