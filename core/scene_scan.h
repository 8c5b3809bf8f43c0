#pragma once
// Reading a scene's scan source ("type": "scan": a CT or MRI volume in an NRRD or raw file, read
// by core/scan_volume.h). Internal to core.
#include <filesystem>

#include "core/json_reader.h"
#include "core/scene.h"

namespace eikon::scene_detail {

// Reads the keys of a scan source after its "type" and "field": file, dims, value_type, endian,
// spacing, origin, window. The layout keys (dims, value_type, endian) are for headerless raw
// files: with an NRRD file, whose header says them, they are an error.
void readScanSource(json::Object& object, const std::filesystem::path& sceneDirectory,
                    SourceSpec& source);

}  // namespace eikon::scene_detail
