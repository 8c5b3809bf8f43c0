#include <algorithm>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/scene.h"
#include "core/vdb_import.h"
#include "core/vdb_reader.h"
#include "core/vdb_sequence.h"

namespace eikon {
namespace {

// The density grid's voxel size, read from metadata only (no voxel data), so that the default
// material can be stated per voxel like vdb_render's -scatter/-absorb: a cache of any scale then
// renders with the same look.
float densityVoxelSize(const std::string& path) {
    VdbReader reader(path);
    for (size_t i = 0; i < reader.entries().size(); ++i)
        if (canonicalFieldFor(reader.entries()[i].name) == "density") {
            const openvdb::Vec3d vs = reader.readGrid(i)->voxelSize();
            return float(std::min({vs.x(), vs.y(), vs.z()}));
        }
    throw Error(path, "no density grid (looked for the names density, smoke, soot, density.*)");
}

// The look shared by a file and a sequence: `src` with grey smoke on its density and a sun.
Scene defaultSceneFor(const SourceSpec& src, const std::string& densityFile) {
    const float voxel = densityVoxelSize(densityFile);
    Scene scene;
    scene.path = src.file;
    scene.sources.push_back(src);

    MaterialSpec smoke;
    smoke.name = "smoke";
    smoke.field = "density";
    smoke.scattering = glm::vec3(0.3f / voxel);  // per voxel 0.3, as vdb_render's default look
    smoke.absorption = glm::vec3(0.05f / voxel);
    scene.materials.push_back(smoke);

    LightSpec sun;
    sun.type = LightType::Directional;
    sun.direction = -glm::normalize(glm::vec3(1.0f, 1.0f, 0.5f));
    // 4π: vdb_render leaves out the phase function's 1/(4π); this gives its brightness.
    sun.intensity = 12.566371f;
    scene.lights.push_back(sun);

    scene.output.name = "render";
    return scene;
}

}  // namespace

Scene defaultSceneForVdb(const std::string& vdbPath) {
    SourceSpec src;
    src.type = SourceType::Vdb;
    src.file = vdbPath;
    src.jsonPath = "(file)";
    return defaultSceneFor(src, vdbPath);
}

Scene defaultSceneForVdbSequence(const std::string& fileOrPattern, bool holdMissingFrames) {
    const VdbSequence seq = findVdbSequence(fileOrPattern);
    SourceSpec src;
    src.type = SourceType::VdbSequence;
    src.file = seq.pattern();
    src.jsonPath = "(sequence)";
    src.holdMissingFrames = holdMissingFrames;
    Scene scene = defaultSceneFor(src, seq.frames.begin()->second);
    scene.time.frameStart = seq.first();
    scene.time.frameEnd = seq.last();
    // The images take the cache's name and numbering: fluid_data_0007.vdb -> fluid_data_0007.png.
    scene.output.name = seq.prefix + std::string(size_t(std::max(seq.digits, 1)), '#');
    return scene;
}

}  // namespace eikon
