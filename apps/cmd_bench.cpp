// `eikon bench`: the benchmark programs. Speed is measured here, with the command line and the
// machine printed beside the figures, and never by timed unit tests.
#include "apps/commands.h"

namespace eikon::app {

void addBenchCommand(CLI::App& app, int& exitCode) {
    auto* bench = app.add_subcommand("bench", "Benchmarks: print timings with their settings");
    bench->require_subcommand(1);
    addBenchSmokeCommand(*bench, exitCode);
    addBenchAdvectionCommand(*bench, exitCode);
    addBenchVoxelizeCommand(*bench, exitCode);
    addBenchArapCommand(*bench, exitCode);
    addBenchMethodsCommand(*bench, exitCode);
    addBenchIntegratorsCommand(*bench, exitCode);
    addBenchCausticCommand(*bench, exitCode);
    addBenchSoakCommand(*bench, exitCode);
}

}  // namespace eikon::app
