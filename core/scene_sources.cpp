#include "core/scene_sources.h"

#include "core/error.h"
#include "core/procedural.h"
#include "core/vdb_import.h"

namespace eikon {

SceneSources::SceneSources(const Scene& scene) : scene_(scene) {
    for (size_t s = 0; s < scene.sources.size(); ++s)
        if (scene.sources[s].type == SourceType::VdbSequence)
            sequences_.emplace(s, findVdbSequence(scene.sources[s].file));
}

void SceneSources::loadFrame(int frame, FieldRegistry& fields) {
    for (size_t s = 0; s < scene_.sources.size(); ++s) {
        const SourceSpec& src = scene_.sources[s];
        std::string key;  // identifies what this source would put in the registry now
        switch (src.type) {
            case SourceType::Vdb: key = src.file; break;
            case SourceType::VdbSequence: key = sequences_.at(s).fileForFrame(frame); break;
            case SourceType::Sphere:
            case SourceType::Box: key = "procedural"; break;
        }
        if (loadedFile_.count(s) && loadedFile_[s] == key) continue;
        const std::string origin = scene_.path + ":" + src.jsonPath;
        switch (src.type) {
            case SourceType::Vdb:
            case SourceType::VdbSequence: importVdb(key, fields, src.aliases); break;
            case SourceType::Sphere:
                ensureOpenVdbInitialized();
                fields.set(src.field,
                           makeSphereField(src.center, src.radius, src.value, src.falloff,
                                           src.voxelSize),
                           origin);
                break;
            case SourceType::Box:
                ensureOpenVdbInitialized();
                fields.set(src.field,
                           makeBoxField(src.boxMin, src.boxMax, src.value, src.falloff,
                                        src.voxelSize),
                           origin);
                break;
        }
        loadedFile_[s] = key;
    }
}

}  // namespace eikon
