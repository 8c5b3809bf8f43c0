// `eikon convert scan.nrrd out.vdb`: a scanned volume (NRRD, or a raw file) written as an OpenVDB
// fog volume that Houdini, Blender and OpenVDB's tools read, and that a scene's "vdb" source
// renders; the same reader, options and errors as a scene's "scan" source
// (docs/scene-format.md). The file is written atomically; an existing one is kept unless
// --overwrite says otherwise, and the input is never written over.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "apps/memory_limit_option.h"
#include "core/error.h"
#include "core/field_registry.h"
#include "core/log.h"
#include "core/scan_volume.h"
#include "core/vdb_export.h"

namespace fs = std::filesystem;

namespace eikon::app {
namespace {

struct ConvertOptions {
    std::string input;
    std::string output;
    std::string field = "density";
    std::vector<double> window, spacing, origin;
    std::vector<int> dims;
    std::string valueType;
    bool bigEndian = false;
    bool overwrite = false;
};

glm::dvec3 vec3Of(const std::vector<double>& v) {
    return glm::dvec3(v[0], v[1], v[2]);
}

void checkOutput(const ConvertOptions& o) {
    std::error_code ec;
    if (fs::exists(o.output, ec) && fs::equivalent(o.input, o.output, ec))
        throw Error(o.output, "is the scan being converted; give another output file");
    if (fs::exists(o.output, ec) && !o.overwrite)
        throw Error(o.output, "exists; give another file or --overwrite");
    if (fs::is_directory(o.output, ec)) throw Error(o.output, "is a folder; give a .vdb file");
}

void convert(const ConvertOptions& o) {
    if (!isCanonicalFieldName(fieldKind(o.field)) || o.field == field::kVelocity ||
        o.field == field::kColor)
        throw Error("--field",
                    "expected a scalar field name (density, temperature, flame, n, "
                    "kappa, sigma, g, emission; labelled as density.ct), got \"" +
                        o.field + "\"");
    checkOutput(o);
    ScanFileOptions options;
    if (!o.dims.empty()) options.dims = glm::ivec3(o.dims[0], o.dims[1], o.dims[2]);
    if (!o.valueType.empty()) {
        options.type = parseScanValueType(o.valueType);
        if (!options.type)
            throw Error("--type",
                        "expected uint8, int8, uint16, int16, uint32, int32, uint64, "
                        "int64, float32 or float64, got \"" +
                            o.valueType + "\"");
    }
    options.bigEndian = o.bigEndian;
    if (!o.spacing.empty()) options.spacing = vec3Of(o.spacing);
    if (!o.origin.empty()) options.origin = vec3Of(o.origin);
    options.read.fieldName = o.field;
    if (!o.window.empty()) {
        if (!(o.window[1] > o.window[0]))
            throw Error("--window", "expected LOW HIGH with HIGH > LOW");
        options.read.window = ScanWindow{o.window[0], o.window[1]};
    }
    const ScanFile scan = readScanFile(o.input, options);
    FieldRegistry fields;
    fields.set(o.field, scan.volume.grid, o.input);
    exportVdb(o.output, fields, {o.field});
    logInfo(describeScanFile(o.input, scan));
    std::printf("wrote %s (grid '%s', %llu active voxels)\n", o.output.c_str(),
                exportGridName(o.field).c_str(),
                static_cast<unsigned long long>(scan.volume.grid->activeVoxelCount()));
}

}  // namespace

void addConvertCommand(CLI::App& app, int& exitCode) {
    auto* cmd = app.add_subcommand(
        "convert", "Write a scanned volume (NRRD, or a raw file) as an OpenVDB fog volume");
    addMemoryLimitOption(cmd);
    auto o = std::make_shared<ConvertOptions>();  // CLI11 binds by reference
    cmd->add_option("scan", o->input,
                    "NRRD file (.nrrd, .nhdr), or raw samples named <name>_<X>x<Y>x<Z>_<type>.raw")
        ->required();
    cmd->add_option("output", o->output, "the .vdb file to write")->required();
    cmd->add_option("--field", o->field, "the field (and grid name) the samples become")
        ->capture_default_str();
    cmd->add_option("--window", o->window, "LOW HIGH: stored values mapped to [0, 1], clamped")
        ->expected(2);
    cmd->add_option("--spacing", o->spacing, "X Y Z: units between samples (replaces the header's)")
        ->expected(3);
    cmd->add_option("--origin", o->origin, "X Y Z: where sample (0, 0, 0) is")->expected(3);
    cmd->add_option("--dims", o->dims, "X Y Z: samples along each axis (raw files)")->expected(3);
    cmd->add_option("--type", o->valueType, "uint8, int16, float32, ... (raw files)");
    cmd->add_flag("--big-endian", o->bigEndian, "multi-byte raw samples are big-endian");
    cmd->add_flag("--overwrite", o->overwrite, "replace an existing output file");
    cmd->footer(
        "Examples (from the repository root):\n"
        "  eikon convert ../shared/data/volumes/tooth_103x94x161_uint8.raw tooth.vdb "
        "--window 100 240 --spacing 0.0125 0.0125 0.0125\n"
        "  eikon convert chest.nhdr chest.vdb --field density.ct --window -200 400\n");
    cmd->callback([o, &exitCode] {
        convert(*o);
        exitCode = 0;
    });
}

}  // namespace eikon::app
