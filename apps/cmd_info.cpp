#include <cstdio>
#include <memory>

#include "apps/commands.h"
#include "apps/memory_limit_option.h"
#include "core/error.h"
#include "core/file_kind.h"
#include "core/scan_info.h"
#include "core/vdb_info.h"
#include "sim/mesh_check.h"
#include "sim/mesh_info.h"
#include "sim/mesh_io.h"

namespace eikon::app {

void addInfoCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand(
        "info",
        "Print the grids of a VDB file, the counts, bounds and problems of a mesh, or the layout, "
        "values and histogram of a scan");
    addMemoryLimitOption(cmd);
    auto path = std::make_shared<std::string>();  // CLI11 binds by reference
    cmd->add_option("file", *path,
                    "VDB file, mesh (.obj, .off, .ply, .stl), or scan (NRRD, "
                    "<name>_<X>x<Y>x<Z>_<type>.raw)")
        ->required();
    cmd->footer(
        "Examples (from the repository root):\n  eikon info "
        "../shared/data/vdb/houdini_smoke1.vdb\n  eikon info "
        "../shared/data/meshes/stanford-bunny.obj\n  eikon info "
        "../shared/data/volumes/tooth_103x94x161_uint8.raw\n");
    cmd->callback([path, &exitCode] {
        // Chosen by extension: a mesh problem is reported, not an error; an unreadable file is.
        if (isScanFile(*path)) {
            ScanFileOptions options;
            options.read.fieldName = "scan";  // any value, negative included: this only reports
            std::fputs(formatScanInfo(*path, readScanFile(*path, options)).c_str(), stdout);
        } else if (isMeshFile(*path)) {
            const LoadedMesh loaded = loadMesh(*path);
            std::fputs(formatMeshInfo(*path, loaded, checkMesh(loaded)).c_str(), stdout);
        } else {
            // Told by content: a scene, a NanoVDB or an empty file gets its own line, not a
            // stream error from the VDB reader.
            switch (sniffFileKind(*path)) {
                case FileKind::Vdb:
                case FileKind::NanoVdb:
                    std::fputs(formatVdbInfo(inspectVdb(*path)).c_str(), stdout);
                    break;
                case FileKind::Json:
                    throw Error(*path,
                                "a scene file (JSON), not a VDB file or a mesh; render it "
                                "with eikon render");
            }
        }
        exitCode = 0;
    });
}

}  // namespace eikon::app
