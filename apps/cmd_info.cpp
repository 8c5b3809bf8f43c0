#include <cstdio>
#include <memory>

#include "apps/commands.h"
#include "core/vdb_info.h"

namespace eikon::app {

void addInfoCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand("info", "Print the grids of a VDB file");
    auto path = std::make_shared<std::string>();  // CLI11 binds by reference
    cmd->add_option("file", *path, "VDB file")->required();
    cmd->callback([path, &exitCode] {
        std::fputs(formatVdbInfo(inspectVdb(*path)).c_str(), stdout);
        exitCode = 0;
    });
}

}  // namespace eikon::app
