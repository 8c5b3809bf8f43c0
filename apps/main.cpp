// eikon: the command line. Every eikon::Error becomes one line "eikon: <where>: <reason>" and a
// non-zero exit, so scripts and users see what to fix without a stack trace; command-line
// mistakes too (apps/usage_errors.h), with their own exit status.
#include <cstdio>

#include <openvdb/version.h>

#include "apps/bench_report.h"
#include "apps/commands.h"
#include "apps/huge_page_malloc.h"
#include "apps/usage_errors.h"
#include "core/error.h"

int main(int argc, char** argv) {
    eikon::app::restartWithHugePageMalloc(argv);
    CLI::App app{"Eikon: relighting of refractive, absorbing and scattering media"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("eikon ") + EIKON_VERSION + " (OpenVDB " +
                                          OPENVDB_LIBRARY_VERSION_STRING + ")");
    app.footer(
        "Exit status: 0 done, 1 bad input (a file, a scene, a value), 2 a wrong command line, 3 "
        "an internal fault.\n'eikon COMMAND --help' shows a command's options and examples.");
    int exitCode = 0;
    eikon::app::addInfoCommand(app, exitCode);
    eikon::app::addConvertCommand(app, exitCode);
    eikon::app::addRenderCommand(app, exitCode);
    eikon::app::addDiffCommand(app, exitCode);
    eikon::app::addViewCommand(app, exitCode);
    eikon::app::addSimulateCommand(app, exitCode);
    eikon::app::addRegressCommand(app, exitCode);
    eikon::app::addBenchCommand(app, exitCode);
    eikon::app::setBenchCommandLine(eikon::app::joinCommandLine(argc, argv));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return eikon::app::reportParseError(app, e, argc, argv);
    } catch (const eikon::Error& e) {
        std::fprintf(stderr, "eikon: %s\n", e.what());
        return eikon::app::kExitError;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "eikon: internal error: %s\n", e.what());
        return eikon::app::kExitInternal;
    }
    return exitCode;
}
