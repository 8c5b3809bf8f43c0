// eikon: the command line. Every eikon::Error becomes one line "eikon: <where>: <reason>" and a
// non-zero exit, so scripts and users see what to fix without a stack trace.
#include <cstdio>

#include "apps/bench_report.h"
#include "apps/commands.h"
#include "core/error.h"

int main(int argc, char** argv) {
    CLI::App app{"Eikon: relighting of refractive, absorbing and scattering media"};
    app.require_subcommand(1);
    int exitCode = 0;
    eikon::app::addInfoCommand(app, exitCode);
    eikon::app::addRenderCommand(app, exitCode);
    eikon::app::addDiffCommand(app, exitCode);
    eikon::app::addViewCommand(app, exitCode);
    eikon::app::addSimulateCommand(app, exitCode);
    eikon::app::addBenchCommand(app, exitCode);
    eikon::app::setBenchCommandLine(eikon::app::joinCommandLine(argc, argv));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const eikon::Error& e) {
        std::fprintf(stderr, "eikon: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "eikon: internal error: %s\n", e.what());
        return 2;
    }
    return exitCode;
}
