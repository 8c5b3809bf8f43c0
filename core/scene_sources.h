#pragma once
// Turns a scene's sources into fields for a given frame: VDB files and scans once, sequences when
// the frame's file changes, procedural shapes once. Fields that did not change keep their version,
// so the GPU upload skips them.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/field_registry.h"
#include "core/scene.h"
#include "core/vdb_sequence.h"

namespace eikon {

// Throws eikon::Error when a sequence source of `scene` lacks a frame of `frames` and the source
// does not hold the nearest frame: checked before a command writes anything, so a bad range
// writes no image. The error lists the absent frames and the frames the sequence has.
void checkSequenceFrames(const Scene& scene, const std::vector<int>& frames);

class SceneSources {
public:
    explicit SceneSources(const Scene& scene);
    // Loads what frame `frame` needs into `fields`. Throws eikon::Error on bad files.
    void loadFrame(int frame, FieldRegistry& fields);

private:
    void addProcedural(const SourceSpec& src, const std::string& origin, FieldRegistry& fields);
    void addScan(const SourceSpec& src, const std::string& origin, FieldRegistry& fields);

    const Scene& scene_;
    std::set<std::string> proceduralFields_;    // fields procedural sources have written
    std::map<size_t, VdbSequence> sequences_;   // by source index
    std::map<size_t, std::string> loadedFile_;  // by source index: what is in the registry
};

}  // namespace eikon
