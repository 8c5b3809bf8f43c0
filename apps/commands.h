#pragma once
// The `eikon` subcommands; each registers its options on the CLI11 app and returns the exit code
// through the callback it installs.
#include <CLI/CLI.hpp>

namespace eikon::app {

void addInfoCommand(CLI::App& app, int& exitCode);
void addConvertCommand(CLI::App& app, int& exitCode);
void addRenderCommand(CLI::App& app, int& exitCode);
void addDiffCommand(CLI::App& app, int& exitCode);
void addViewCommand(CLI::App& app, int& exitCode);
void addSimulateCommand(CLI::App& app, int& exitCode);
void addRegressCommand(CLI::App& app, int& exitCode);
// `eikon bench smoke|advection|voxelize|arap|methods|soak`: benchmark programs (timings live here,
// never in unit tests).
void addBenchCommand(CLI::App& app, int& exitCode);
void addBenchSmokeCommand(CLI::App& bench, int& exitCode);
void addBenchAdvectionCommand(CLI::App& bench, int& exitCode);
void addBenchVoxelizeCommand(CLI::App& bench, int& exitCode);
void addBenchArapCommand(CLI::App& bench, int& exitCode);
void addBenchMethodsCommand(CLI::App& bench, int& exitCode);
void addBenchIntegratorsCommand(CLI::App& bench, int& exitCode);
void addBenchCausticCommand(CLI::App& bench, int& exitCode);
void addBenchSoakCommand(CLI::App& bench, int& exitCode);

}  // namespace eikon::app
