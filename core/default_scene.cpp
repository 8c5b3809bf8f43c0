#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/camera.h"
#include "core/density_view.h"
#include "core/error.h"
#include "core/level_set.h"
#include "core/scene.h"
#include "core/vdb_import.h"
#include "core/vdb_reader.h"
#include "core/vdb_sequence.h"

namespace eikon {
namespace {

const char* axisName(glm::vec3 up) {
    return up.x > 0.5f ? "x" : up.z > 0.5f ? "z" : "y";
}

// The up axis of the automatic camera, by the rule docs/scene-format.md states: the user's
// choice; else the writer's (core/density_view.h); else, for a sequence, the axis along which the
// density's centre moved most from its first frame to its last, when it moved more than two
// voxels and twice as far as along any other axis (smoke rises, a splash falls: the axis, not
// the sign); else y. `reason` says which.
glm::vec3 chooseUp(const std::optional<glm::vec3>& given, const std::vector<DensityView>& views,
                   std::string& reason) {
    if (given) {
        reason = "";
        return *given;
    }
    if (views.front().up) {
        reason = views.front().upReason;
        return *views.front().up;
    }
    if (views.size() > 1 && views.front().visible && views.back().visible) {
        const glm::vec3 d = glm::abs(views.back().centroid - views.front().centroid);
        int axis = 0;
        for (int a = 1; a < 3; ++a)
            if (d[a] > d[axis]) axis = a;
        const float second = std::max(d[(axis + 1) % 3], d[(axis + 2) % 3]);
        if (d[axis] > 2.0f * views.front().voxelSize && d[axis] > 2.0f * second) {
            glm::vec3 up(0.0f);
            up[axis] = 1.0f;
            reason = std::string("the density moves along ") + "xyz"[axis] +
                     " over the sequence, more than along the other axes";
            return up;
        }
    }
    reason = "";
    return {0, 1, 0};
}

// The look shared by a file and a sequence: `src` with grey smoke on its density and a sun,
// the camera framing what shows in `framedFiles` (one file, or a sequence's first, middle and
// last frames) as one box, the same every frame.
Scene defaultSceneFor(const SourceSpec& src, const std::vector<std::string>& framedFiles,
                      const DefaultSceneChoices& camera, std::string& note) {
    std::vector<DensityView> views;
    for (const std::string& file : framedFiles) views.push_back(viewDensity(file));
    const float voxel = views.front().voxelSize;
    Scene scene;
    scene.path = src.file;
    scene.sources.push_back(src);
    Bounds3 framed;
    for (const DensityView& v : views)
        if (v.visible) framed = framed.unite(*v.visible);
    if (framed.valid()) scene.camera.framed = framed;
    std::string reason;
    scene.camera.up = chooseUp(camera.up, views, reason);
    if (!reason.empty())
        note = std::string("camera up +") + axisName(scene.camera.up) + ": " + reason +
               " (--up x|y|z to choose)";
    MaterialSpec smoke;
    smoke.name = "smoke";
    smoke.field = "density";
    smoke.scattering = glm::vec3(0.3f / voxel);  // per voxel 0.3, as vdb_render's default look
    smoke.absorption = glm::vec3(0.05f / voxel);
    scene.materials.push_back(smoke);

    LightSpec sun;
    sun.type = LightType::Directional;
    // From the upper right front as the camera sees it, whichever axis is up: (1, 1, 0.5) in
    // y-up terms (right, up, front).
    const glm::vec3 up = scene.camera.up, front = frontOf(up), right = glm::cross(up, front);
    sun.direction = -glm::normalize(right + up + 0.5f * front);
    // 4π: vdb_render leaves out the phase function's 1/(4π); this gives its brightness.
    sun.intensity = 12.566371f;
    scene.lights.push_back(sun);

    scene.output.name = "render";
    return scene;
}

// The look of a solid (core/level_set.h): glass (ior 1.5, a faint blue-green tint) standing over
// a floor under a sun from above, the floor a quarter of the solid's height below it, where a
// glass ball's caustic focuses (ball lens: f = nR/(2(n − 1)) = 1.5R from the centre), and room
// around for the shadow. The volume is 64 voxels along its longest side; the photons draw the
// caustic.
Scene levelSetScene(const std::string& path, const DefaultSceneChoices& choices,
                    std::string& note) {
    const LevelSet set = LevelSet::read(path, choices.grid);
    const Bounds3 box = set.bounds();
    const DensityView writer = writerUpOf(path);
    const glm::vec3 up = choices.up ? *choices.up : writer.up ? *writer.up : glm::vec3(0, 1, 0);
    const int upAxis = up.x > 0.5f ? 0 : up.z > 0.5f ? 2 : 1;
    const glm::vec3 size = box.size();
    const float longest = std::max({size.x, size.y, size.z});

    Scene scene;
    scene.path = path;
    MeshObjectSpec solid;
    solid.name = "solid";
    solid.shape = MeshShapeType::LevelSet;
    solid.file = path;
    solid.grid = choices.grid;
    solid.jsonPath = "(file)";
    scene.meshes.push_back(solid);
    const MeshFieldNames fields = meshMaterialFieldNames(solid);
    MaterialSpec tint;  // per scene unit: across the solid, about 10 % red, 3 % green lost
    tint.name = "solid";
    tint.field = fields.coverage;
    tint.absorption = glm::vec3(0.1f, 0.03f, 0.05f) / longest;
    scene.materials.push_back(tint);
    MaterialSpec glass;
    glass.name = "solid.n";
    glass.field = fields.index;
    glass.ior = 1.5f;
    scene.materials.push_back(glass);

    const float floor = box.min[upAxis] - 0.25f * size[upAxis];
    Bounds3 volume{box.min - 0.35f * longest, box.max + 0.35f * longest};
    volume.min[upAxis] = floor - 0.05f * longest;
    volume.max[upAxis] = box.max[upAxis] + 0.15f * longest;  // the index blur's 4 voxels
    scene.volume.autoBounds = false;
    scene.volume.bounds = volume;
    scene.volume.autoResolution = false;
    const float voxel = std::max({volume.size().x, volume.size().y, volume.size().z}) / 64.0f;
    scene.volume.resolution = glm::max(glm::ivec3(glm::ceil(volume.size() / voxel)), 8);

    ReceiverSpec ground;
    ground.axis = upAxis;
    ground.position = floor;
    ground.albedo = glm::vec3(0.75f);
    scene.receivers.push_back(ground);

    LightSpec sun;
    sun.type = LightType::Directional;
    const glm::vec3 front = frontOf(up), right = glm::cross(up, front);
    sun.direction = -glm::normalize(up + 0.25f * right + 0.15f * front);
    sun.intensity = 2.0f;
    scene.lights.push_back(sun);

    scene.camera.up = up;
    scene.camera.framed = volume;
    scene.environment.color = glm::vec3(0.02f, 0.02f, 0.03f);
    scene.render.lightTransport = R"({"photons":{"per_side":256}})";
    scene.output.name = "render";
    note = path + ": " + set.label() +
           " is a level set: rendered as glass (ior 1.5) over a floor, " + axisName(up) + " up" +
           (choices.up || !writer.up ? "" : " (" + writer.upReason + ")") +
           "; a scene gives it other optics under \"meshes\"";
    return scene;
}

}  // namespace

Scene defaultSceneForVdb(const std::string& vdbPath, const DefaultSceneChoices& choices,
                         std::string& note) {
    if (choices.grid.given()) return levelSetScene(vdbPath, choices, note);
    if (!holdsDensityGrid(vdbPath)) {
        try {
            return levelSetScene(vdbPath, choices, note);
        } catch (const Error& e) {
            throw Error(vdbPath,
                        "no density grid (names density, smoke, soot, density.*); " + e.reason());
        }
    }
    SourceSpec src;
    src.type = SourceType::Vdb;
    src.file = vdbPath;
    src.jsonPath = "(file)";
    return defaultSceneFor(src, {vdbPath}, choices, note);
}

Scene defaultSceneForVdbSequence(const std::string& fileOrPattern, bool holdMissingFrames,
                                 const DefaultSceneChoices& camera, std::string& note) {
    const VdbSequence seq = findVdbSequence(fileOrPattern);
    const std::string& first = seq.frames.begin()->second;
    if (!holdsDensityGrid(first)) {  // a level-set sequence: say so, not only "no density"
        std::string label;
        try {
            label = LevelSet::read(first, {}).label();
        } catch (const Error&) {  // neither: viewDensity below says what is missing
        }
        if (!label.empty())
            throw Error(first, "no density grid; " + label +
                                   " is a level set, and level sets are rendered one file at a "
                                   "time (eikon render " +
                                   first + ")");
    }
    SourceSpec src;
    src.type = SourceType::VdbSequence;
    src.file = seq.pattern();
    src.jsonPath = "(sequence)";
    src.holdMissingFrames = holdMissingFrames;
    // Framed once, on the first, middle and last frames: a plume that grows stays in view, and
    // the camera does not move as it grows (it reframed every frame, so the plume seemed to
    // shrink).
    std::vector<std::string> framed{first};
    const auto middle = seq.frames.lower_bound(seq.first() + (seq.last() - seq.first()) / 2);
    if (middle->second != framed.back()) framed.push_back(middle->second);
    if (seq.frames.rbegin()->second != framed.back()) framed.push_back(seq.frames.rbegin()->second);
    Scene scene = defaultSceneFor(src, framed, camera, note);
    scene.time.frameStart = seq.first();
    scene.time.frameEnd = seq.last();
    // The images take the cache's name and numbering: fluid_data_0007.vdb -> fluid_data_0007.png.
    scene.output.name = seq.prefix + std::string(size_t(std::max(seq.digits, 1)), '#');
    return scene;
}

}  // namespace eikon
