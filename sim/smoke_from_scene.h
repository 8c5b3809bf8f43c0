#pragma once
// Builds the smoke solver a scene's "simulation" section describes (core/simulation_spec.h):
// the one place where core's plain settings become sim's types.
#include "core/simulation_spec.h"
#include "sim/smoke_solver.h"

namespace eikon::sim {

SmokeSettings smokeSettingsFrom(const SmokeSimulationSpec& spec, double fps);

// A solver with the spec's sources and obstacles added, at frame 0. Throws eikon::Error when
// the settings are unusable.
SmokeSolver smokeSolverFrom(const SmokeSimulationSpec& spec, double fps);

}  // namespace eikon::sim
