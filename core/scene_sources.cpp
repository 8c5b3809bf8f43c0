#include "core/scene_sources.h"

#include "core/error.h"
#include "core/log.h"
#include "core/procedural.h"
#include "core/scan_volume.h"
#include "core/vdb_import.h"

#include <openvdb/tools/Composite.h>

namespace eikon {

SceneSources::SceneSources(const Scene& scene) : scene_(scene) {
    for (size_t s = 0; s < scene.sources.size(); ++s) {
        const SourceSpec& src = scene.sources[s];
        if (src.type != SourceType::VdbSequence) continue;
        const VdbSequence& seq = sequences_.emplace(s, findVdbSequence(src.file)).first->second;
        // Asked to hold: said once, here. Otherwise a missing frame is an error when rendered.
        if (src.holdMissingFrames && !seq.missing.empty())
            logWarning(seq.pattern() + ": frames " + seq.missingText() +
                       " are missing; the nearest earlier frame stands in");
        if (src.holdMissingFrames && seq.first() > scene.time.frameStart)
            logWarning(seq.pattern() + " starts at frame " + std::to_string(seq.first()) +
                       "; it stands in for the frames before");
        if (src.holdMissingFrames && seq.last() < scene.time.frameEnd)
            logWarning(seq.pattern() + " ends at frame " + std::to_string(seq.last()) +
                       "; it stands in for the frames after");
    }
}

namespace {

// A rendered frame the sequence lacks, between its first and its last or outside them, is an
// error unless the scene asked to hold the nearest frame: a silent stand-in made a missing cache
// frame look like smoke that stopped moving, and a range past the cache's end write copies of its
// last frame. The reason lists every frame of `frames` that is absent.
void checkFramesPresent(const Scene& scene, const SourceSpec& src, const VdbSequence& seq,
                        const std::vector<int>& frames) {
    if (src.holdMissingFrames) return;
    std::vector<int> gaps, outside;
    for (int frame : frames) {
        if (seq.frames.count(frame)) continue;
        (frame < seq.first() || frame > seq.last() ? outside : gaps).push_back(frame);
    }
    if (gaps.empty() && outside.empty()) return;
    // A sequence given on the command line is its own scene: the pattern alone says where.
    const bool ownScene = scene.path == src.file;
    std::string reason = (ownScene ? "" : seq.pattern() + " ") + "has frames " + seq.framesText();
    if (!outside.empty()) reason += "; " + describeFrameRanges(outside) + " outside them";
    if (!gaps.empty()) reason += "; " + describeFrameRanges(gaps) + " missing between";
    throw Error(ownScene ? seq.pattern() : scene.path + ":" + src.jsonPath,
                reason +
                    "; write them, render the frames it has, or hold the nearest frame "
                    "(\"missing_frames\": \"hold\" in a scene, --hold on the command line)");
}

}  // namespace

void checkSequenceFrames(const Scene& scene, const std::vector<int>& frames) {
    for (const SourceSpec& src : scene.sources)
        if (src.type == SourceType::VdbSequence)
            checkFramesPresent(scene, src, findVdbSequence(src.file), frames);
}

void SceneSources::addProcedural(const SourceSpec& src, const std::string& origin,
                                 FieldRegistry& fields) {
    ensureOpenVdbInitialized();
    checkProceduralFieldMemory(src, origin);  // tracks may have grown the shape since parsing
    openvdb::FloatGrid::Ptr grid = makeProceduralField(src);
    // Shapes that write the same field overlap by taking the larger value (a union).
    if (proceduralFields_.count(src.field) && fields.has(src.field)) {
        auto previous = fields.floatGrid(src.field)->deepCopy();
        // compMax works in index space: both grids must share the transform.
        if (previous->transform() != grid->transform())
            throw Error(origin,
                        "shapes that write field '" + src.field + "' must share one voxel_size");
        openvdb::tools::compMax(*grid, *previous);
    }
    proceduralFields_.insert(src.field);
    fields.set(src.field, grid, origin);
}

void SceneSources::addScan(const SourceSpec& src, const std::string& origin,
                           FieldRegistry& fields) {
    ScanFileOptions options;
    options.dims = src.scanDims;
    if (!src.scanValueType.empty()) options.type = parseScanValueType(src.scanValueType);
    options.bigEndian = src.scanBigEndian;
    if (src.scanSpacing) options.spacing = glm::dvec3(*src.scanSpacing);
    if (src.scanOrigin) options.origin = glm::dvec3(*src.scanOrigin);
    options.read.fieldName = src.field;
    if (src.scanWindow) options.read.window = ScanWindow{src.scanWindow->x, src.scanWindow->y};
    try {
        const ScanFile scan = readScanFile(src.file, options);
        logInfo(describeScanFile(src.file, scan));
        fields.set(src.field, scan.volume.grid, origin);
    } catch (const Error& e) {
        // The file's own message, plus which source of the scene asked for it.
        throw Error(e.where(), e.reason() + " (source " + origin + ")");
    }
}

void SceneSources::loadFrame(int frame, FieldRegistry& fields) {
    for (size_t s = 0; s < scene_.sources.size(); ++s) {
        const SourceSpec& src = scene_.sources[s];
        std::string key;  // identifies what this source would put in the registry now
        switch (src.type) {
            case SourceType::Vdb:
            case SourceType::Scan:
                key = src.file;
                break;
            case SourceType::VdbSequence:
                checkFramesPresent(scene_, src, sequences_.at(s), {frame});
                key = sequences_.at(s).fileForFrame(frame);
                break;
            case SourceType::Sphere:
            case SourceType::Box:
                key = "procedural";
                break;
            case SourceType::Simulation:
                continue;  // the program stepping the simulation publishes its fields
        }
        if (loadedFile_.count(s) && loadedFile_[s] == key) continue;
        const std::string origin = scene_.path + ":" + src.jsonPath;
        switch (src.type) {
            case SourceType::Vdb:
            case SourceType::VdbSequence:
                try {
                    importVdb(key, fields, src.aliases);
                } catch (const Error& e) {
                    // The file's own message, plus which source of the scene asked for it.
                    throw Error(e.where(), e.reason() + " (source " + origin + ")");
                }
                break;
            case SourceType::Scan:
                addScan(src, origin, fields);
                break;
            case SourceType::Sphere:
            case SourceType::Box:
                addProcedural(src, origin, fields);
                break;
            case SourceType::Simulation:
                break;
        }
        loadedFile_[s] = key;
    }
}

}  // namespace eikon
