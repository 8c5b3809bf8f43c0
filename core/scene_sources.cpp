#include "core/scene_sources.h"

#include "core/error.h"
#include "core/log.h"
#include "core/procedural.h"
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
    }
}

namespace {

// A rendered frame the sequence lacks between its first and its last is an error, unless the
// scene asked to hold the nearest earlier frame: a silent stand-in made a missing cache frame look
// like smoke that stopped moving.
void checkFramePresent(const Scene& scene, const SourceSpec& src, const VdbSequence& seq,
                       int frame) {
    if (src.holdMissingFrames || frame < seq.first() || frame > seq.last() ||
        seq.frames.count(frame))
        return;
    throw Error(scene.path + ":" + src.jsonPath,
                seq.pattern() + " has no frame " + std::to_string(frame) +
                    " (missing: " + seq.missingText() +
                    "); write it, or set \"missing_frames\": \"hold\" to "
                    "show the nearest earlier frame instead");
}

}  // namespace

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

void SceneSources::loadFrame(int frame, FieldRegistry& fields) {
    for (size_t s = 0; s < scene_.sources.size(); ++s) {
        const SourceSpec& src = scene_.sources[s];
        std::string key;  // identifies what this source would put in the registry now
        switch (src.type) {
            case SourceType::Vdb:
                key = src.file;
                break;
            case SourceType::VdbSequence:
                checkFramePresent(scene_, src, sequences_.at(s), frame);
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
