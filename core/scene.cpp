// The strict scene parser. The format is documented key by key in docs/scene-format.md; keep the
// two in step. Every check reports through json::Value / json::Object so that each message
// carries "<file>:<JSON pointer>" and the expected form.
#include "core/scene.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/field_registry.h"
#include "core/json_reader.h"
#include "core/procedural.h"
#include "core/scene_animation.h"
#include "core/scene_clip_planes.h"
#include "core/scene_dispersion.h"
#include "core/scene_helpers.h"
#include "core/scene_memory.h"
#include "core/scene_meshes.h"
#include "core/scene_receivers.h"
#include "core/scene_scan.h"
#include "core/scene_simulation.h"
#include "core/scene_transfer.h"
#include "core/scene_voxel_size.h"
#include "shaders/shared/gpu_types.h"

namespace eikon {

namespace {

namespace fs = std::filesystem;
using json::Object;
using json::Range;
using json::Value;
using scene_detail::checkSceneMemory;
using scene_detail::checkVoxelSize;
using scene_detail::formatVec3;
using scene_detail::resolveAgainst;

// Limits of the format (docs/scene-format.md). Materials and lights are capped because the GPU
// stages keep them in the fixed-size arrays of the parameter block (shaders/shared/gpu_types.h).
constexpr std::size_t kMaxMaterials = EK_MAX_MATERIALS;
constexpr std::size_t kMaxLights = EK_MAX_LIGHTS;
constexpr int kMaxVolumeResolution = 1024;
constexpr int kMinMaxResolution = 8;
constexpr int kMaxImageSize = 16384;
// A procedural source is voxelised at its own voxel size before resampling; this many voxels
// across is far beyond any render volume and guards against a voxel_size typo (1e-6) that
// would exhaust memory.
constexpr double kMaxProceduralVoxelsAcross = 4096.0;

const char* const kVec3Form = "an array of 3 numbers [x, y, z]";
const char* const kColorForm = "an array of 3 numbers >= 0 [r, g, b]";

// Materials and procedural sources produce or read one scalar per voxel; velocity and color
// are vector fields and cannot be.
std::vector<std::string> scalarFieldNames() {
    std::vector<std::string> names;
    for (const std::string& name : canonicalFieldNames()) {
        if (name != field::kVelocity && name != field::kColor) names.push_back(name);
    }
    return names;
}

// A scalar field name: a canonical one ("n"), or one with a label after a dot ("n.crown"), which
// keeps several fields of one kind apart (three glasses, each with its own index and colour).
std::string readScalarFieldName(const Value& value) {
    const std::vector<std::string> kinds = scalarFieldNames();
    if (!value.json().is_string()) return value.choice(kinds);  // throws the expected form
    const std::string text = value.string();
    const std::size_t dot = text.find('.');
    if (dot == std::string::npos) return value.choice(kinds);
    const std::string kind = text.substr(0, dot);
    const std::string label = text.substr(dot + 1);
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) {
        std::string names;
        for (const std::string& k : kinds) names += (names.empty() ? "" : ", ") + k;
        std::string reason = "expected a scalar field name before '.' (one of " + names +
                             "), got \"" + kind + "\" in \"" + text + "\"";
        const std::string suggestion = json::closestMatch(kind, kinds);
        if (!suggestion.empty()) reason += "; did you mean \"" + suggestion + "\"?";
        value.fail(reason);
    }
    if (label.empty() || !std::all_of(label.begin(), label.end(), scene_detail::isLabelCharacter)) {
        value.fail("expected a label of letters, digits and '_' after \"" + kind + ".\", got \"" +
                   text + "\"");
    }
    return text;
}

// A field value a procedural source writes: finite, and >= 0 for the fields where a negative
// value means nothing (field_registry.h).
float readFieldValue(const Value& value, const std::string& fieldName) {
    const float x = value.floatNumber();
    if (x < 0.0f && fieldMustBeNonNegative(fieldName)) {
        std::string why = "field '" + fieldName + "' must not be negative";
        if (fieldKind(fieldName) == field::kIor) {
            why += ": a material maps it to n = 1 + f·(ior − 1), which must not fall below 1";
        }
        value.failExpected("a number >= 0 (" + why + ")");
    }
    return x;
}

glm::vec3 readColor(const Value& value) {
    return value.vec3(Range::atLeast(0.0));
}

// ---- volume ----------------------------------------------------------------------------------

Bounds3 readBounds(const Value& value, const std::string& kind = "the volume bounds") {
    Object object(value, kind);
    Bounds3 bounds;
    bounds.min = object.required("min", kVec3Form).vec3();
    bounds.max = object.required("max", kVec3Form).vec3();
    object.finish();
    if (!bounds.valid()) {
        object.failAt("max", "expected max > min on every axis, got min " + formatVec3(bounds.min) +
                                 " and max " + formatVec3(bounds.max));
    }
    return bounds;
}

void readResolution(const Value& value, VolumeSettings& volume) {
    const int hi = kMaxVolumeResolution;
    if (value.isString("auto")) {
        volume.autoResolution = true;
    } else if (value.isNumber()) {
        volume.autoResolution = false;
        volume.resolution = glm::ivec3(static_cast<int>(value.integer(1, hi)));
    } else if (value.isArray()) {
        volume.autoResolution = false;
        volume.resolution = value.ivec3(1, hi);
    } else {
        value.failExpected("\"auto\", an integer in [1, " + std::to_string(hi) +
                           "] or an array of 3 such integers");
    }
}

VolumeSettings readVolume(const Value& value) {
    Object object(value, "the volume");
    VolumeSettings volume;
    if (auto bounds = object.optional("bounds")) {
        if (bounds->isString("auto")) {
            volume.autoBounds = true;
        } else if (bounds->isObject()) {
            volume.autoBounds = false;
            volume.bounds = readBounds(*bounds);
        } else {
            bounds->failExpected("\"auto\" or an object {\"min\": [x, y, z], \"max\": [x, y, z]}");
        }
    }
    if (auto resolution = object.optional("resolution")) readResolution(*resolution, volume);
    if (auto maxResolution = object.optional("max_resolution")) {
        volume.maxResolution =
            static_cast<int>(maxResolution->integer(kMinMaxResolution, kMaxVolumeResolution));
    }
    object.finish();
    if (!volume.autoBounds) {
        // An automatic resolution puts at most max_resolution voxels along the longest axis.
        const glm::vec3 extent = volume.bounds.size();
        const glm::vec3 voxel =
            volume.autoResolution
                ? glm::vec3(std::max({extent.x, extent.y, extent.z}) / float(volume.maxResolution))
                : extent / glm::vec3(volume.resolution);
        checkVoxelSize(object.value().child("bounds"), voxel, volume.bounds, "the volume's voxels");
    }
    return volume;
}

// ---- sources ---------------------------------------------------------------------------------

std::map<std::string, std::vector<std::string>> readAliases(const Value& value) {
    Object object(value, "the alias table");
    std::map<std::string, std::vector<std::string>> aliases;
    // A labelled scalar name ("density.left") is a key too: a grid loaded under it keeps two
    // files' fields of one kind apart (the caches of two smoke domains, both naming theirs
    // "density").
    std::vector<std::string> keys = canonicalFieldNames();
    for (const auto& item : value.json().items()) {
        if (item.key().find('.') == std::string::npos) continue;
        const json::Json key = item.key();  // checked as a field name, at the key's pointer
        keys.push_back(
            readScalarFieldName(Value(key, value.file(), value.child(item.key()).pointer())));
    }
    // Asking for every canonical name makes any other key an "unknown key" with a hint.
    for (const std::string& canonical : keys) {
        auto names = object.optional(canonical);
        if (!names) continue;
        std::vector<std::string>& gridNames = aliases[canonical];
        for (const Value& name : names->elements("an array of grid names")) {
            gridNames.push_back(name.nonEmptyString());
        }
    }
    object.finish();
    return aliases;
}

void readFileSource(Object& object, const fs::path& sceneDirectory, SourceSpec& source) {
    const Value file = object.required("file", "the path of a .vdb file");
    source.file = resolveAgainst(sceneDirectory, file.nonEmptyString());
    // The #### pattern only means something to a sequence; a plain vdb source would look for a
    // file literally named with #### in it.
    if (source.type == SourceType::Vdb && source.file.find('#') != std::string::npos) {
        file.fail("a file name with #### is a sequence pattern; use \"type\": \"vdb_sequence\"");
    }
    if (auto aliases = object.optional("aliases")) source.aliases = readAliases(*aliases);
    if (source.type == SourceType::VdbSequence)
        if (auto missing = object.optional("missing_frames"))
            source.holdMissingFrames = missing->choice({"error", "hold"}) == "hold";
}

void readRamp(const Value& value, SourceSpec& source) {
    Object object(value, "a ramp");
    const std::string axis =
        object.required("axis", "\"x\", \"y\" or \"z\"").choice({"x", "y", "z"});
    source.profile = SourceProfile::Ramp;
    source.rampAxis = axis == "x" ? 0 : axis == "y" ? 1 : 2;
    source.rampFrom = readFieldValue(object.required("from", "a number"), source.field);
    source.rampTo = readFieldValue(object.required("to", "a number"), source.field);
    object.finish();
}

// The procedural keys shared by sphere and box: which field, what value, how soft, how fine,
// a ramp in place of one value, a clip box.
void readProceduralCommon(Object& object, SourceSpec& source) {
    if (auto field = object.optional("field")) source.field = readScalarFieldName(*field);
    if (auto value = object.optional("value")) source.value = readFieldValue(*value, source.field);
    if (auto falloff = object.optional("falloff")) {
        source.falloff = falloff->floatNumber(Range::atLeast(0.0));
    }
    if (auto filter = object.optional("edge_filter")) {
        source.edgeFilter =
            filter->choice({"box", "bspline"}) == "box" ? EdgeFilter::Box : EdgeFilter::BSpline;
    }
    if (auto voxelSize = object.optional("voxel_size")) {
        source.voxelSize = voxelSize->floatNumber(Range::greaterThan(0.0));
        checkVoxelSize(*voxelSize, glm::vec3(source.voxelSize), Bounds3{}, "the voxels");
    }
    if (auto ramp = object.optional("ramp")) {
        object.forbid("value", "a ramp sets the values ('from' and 'to'); remove 'value'");
        readRamp(*ramp, source);
    }
    if (auto clip = object.optional("clip")) source.clip = readBounds(*clip, "the clip box");
}

// The shape's extent with its falloff must meet the clip box, or the source writes nothing.
void checkClip(const Object& object, const SourceSpec& source, glm::vec3 lo, glm::vec3 hi) {
    if (!source.clip) return;
    const Bounds3 reach{lo - source.falloff, hi + source.falloff};
    const Bounds3 kept{glm::max(reach.min, source.clip->min),
                       glm::min(reach.max, source.clip->max)};
    if (!kept.valid()) {
        object.failAt("clip", "expected a clip box that meets the shape (from " +
                                  formatVec3(reach.min) + " to " + formatVec3(reach.max) +
                                  " with its falloff), got min " + formatVec3(source.clip->min) +
                                  " and max " + formatVec3(source.clip->max));
    }
}

void checkVoxelCount(const Object& object, const SourceSpec& source, float extent) {
    const double voxelsAcross = static_cast<double>(extent) / source.voxelSize;
    if (voxelsAcross > kMaxProceduralVoxelsAcross) {
        std::ostringstream reason;
        reason << "expected a voxel size that gives at most " << kMaxProceduralVoxelsAcross
               << " voxels across the shape (extent " << extent << " including falloff), got "
               << source.voxelSize << " (" << std::ceil(voxelsAcross) << " voxels)";
        object.failAt("voxel_size", reason.str());
    }
    const Value& at = object.value();
    checkProceduralFieldMemory(
        source, at.json().contains("voxel_size") ? at.child("voxel_size").where() : at.where());
}

void readSphereSource(Object& object, SourceSpec& source) {
    if (auto center = object.optional("center")) source.center = center->vec3();
    if (auto radius = object.optional("radius")) {
        source.radius = radius->floatNumber(Range::greaterThan(0.0));
    }
    if (auto profile = object.optional("profile")) {
        if (profile->choice({"uniform", "luneburg"}) == "luneburg") {
            source.profile = SourceProfile::Luneburg;
            object.forbid("falloff",
                          "the luneburg profile is already 0 at the surface, so a falloff would "
                          "change nothing; remove 'falloff'");
            object.forbid("edge_filter",
                          "the luneburg profile has no step at the surface to filter; remove "
                          "'edge_filter'");
            object.forbid("ramp", "a sphere has one profile: remove 'ramp' or 'profile'");
        }
    }
    readProceduralCommon(object, source);
    checkVoxelCount(object, source, 2.0f * (source.radius + source.falloff));
    checkClip(object, source, source.center - source.radius, source.center + source.radius);
}

void readBoxSource(Object& object, SourceSpec& source) {
    if (auto min = object.optional("min")) source.boxMin = min->vec3();
    if (auto max = object.optional("max")) source.boxMax = max->vec3();
    readProceduralCommon(object, source);
    if (!Bounds3{source.boxMin, source.boxMax}.valid()) {
        object.failAt("max", "expected max > min on every axis, got min " +
                                 formatVec3(source.boxMin) + " and max " +
                                 formatVec3(source.boxMax));
    }
    const glm::vec3 size = source.boxMax - source.boxMin;
    if (auto radius = object.optional("corner_radius")) {
        // Up to half the thinnest side: a box rounded that far is a slab with round rims.
        source.cornerRadius =
            radius->floatNumber(Range::closed(0.0, 0.5 * std::min({size.x, size.y, size.z})));
    }
    const float extent = std::max({size.x, size.y, size.z}) + 2.0f * source.falloff;
    checkVoxelCount(object, source, extent);
    checkClip(object, source, source.boxMin, source.boxMax);
}

SourceSpec readSource(const Value& value, const fs::path& sceneDirectory) {
    Object object(value, "a source");
    SourceSpec source;
    source.jsonPath = value.pointer();
    // The type decides which other keys belong, so it is read first.
    const std::string type =
        object
            .required("type",
                      "\"vdb\", \"vdb_sequence\", \"scan\", \"sphere\", \"box\" or \"simulation\"")
            .choice({"vdb", "vdb_sequence", "scan", "sphere", "box", "simulation"});
    object.setKind("a " + type + " source");
    if (type == "simulation") {
        source.type = SourceType::Simulation;  // the scene's "simulation" is checked at the end
    } else if (type == "vdb" || type == "vdb_sequence") {
        source.type = type == "vdb" ? SourceType::Vdb : SourceType::VdbSequence;
        readFileSource(object, sceneDirectory, source);
    } else if (type == "scan") {
        source.type = SourceType::Scan;
        if (auto field = object.optional("field")) source.field = readScalarFieldName(*field);
        scene_detail::readScanSource(object, sceneDirectory, source);
    } else if (type == "sphere") {
        source.type = SourceType::Sphere;
        readSphereSource(object, source);
    } else {
        source.type = SourceType::Box;
        readBoxSource(object, source);
    }
    object.finish();
    return source;
}

std::vector<SourceSpec> readSources(const Value& value, const fs::path& sceneDirectory) {
    const std::string form = "a non-empty array of sources";
    std::vector<SourceSpec> sources;
    for (const Value& element : value.elements(form)) {
        sources.push_back(readSource(element, sceneDirectory));
    }
    if (sources.empty()) value.failExpected(form);
    return sources;
}

// ---- materials -------------------------------------------------------------------------------

MaterialSpec readMaterial(const Value& value) {
    Object object(value, "a material");
    MaterialSpec material;
    material.name = object.required("name", "a non-empty string").nonEmptyString();
    if (auto field = object.optional("field")) material.field = readScalarFieldName(*field);
    if (auto absorption = object.optional("absorption")) {
        material.absorption = readColor(*absorption);
    }
    if (auto scattering = object.optional("scattering")) {
        material.scattering = readColor(*scattering);
    }
    if (auto g = object.optional("g")) material.g = g->floatNumber(Range::open(-1.0, 1.0));
    if (auto emission = object.optional("emission")) material.emission = readColor(*emission);
    const auto ior = object.optional("ior");
    if (ior) material.ior = ior->floatNumber(Range::atLeast(1.0));
    if (auto gd = object.optional("gladstone_dale")) {
        if (ior) gd->fail("give either \"ior\" or \"gladstone_dale\", not both");
        material.gladstoneDale = gd->floatNumber(Range::greaterThan(0.0));
        if (auto t = object.optional("ambient_kelvin"))
            material.ambientKelvin = t->floatNumber(Range::greaterThan(0.0));
        material.ior = 1.0f - material.gladstoneDale / material.ambientKelvin;
    } else if (auto t = object.optional("ambient_kelvin")) {
        t->fail("\"ambient_kelvin\" needs \"gladstone_dale\"");
    }
    scene_detail::readDispersion(object, material, ior.has_value());
    scene_detail::readTransfer(object, material);
    scene_detail::readParticleColor(object, material);
    material.fresnel = material.gladstoneDale == 0.0f;
    if (auto fresnel = object.optional("fresnel")) material.fresnel = fresnel->boolean();
    if (auto roughness = object.optional("roughness")) {
        material.roughness = roughness->floatNumber(Range::closed(0.0, 1.0));
        if (material.roughness > 0.0f && (!material.fresnel || material.ior == 1.0f))
            roughness->fail(
                "\"roughness\" is of a sharp surface's highlights: it needs a "
                "refracting material (\"ior\" > 1) with \"fresnel\": true");
    }
    object.finish();
    return material;
}

std::vector<MaterialSpec> readMaterials(const Value& value) {
    const std::string form = "a non-empty array of materials";
    std::vector<MaterialSpec> materials;
    const std::vector<Value> elements = value.elements(form, kMaxMaterials);
    for (std::size_t i = 0; i < elements.size(); ++i) {
        MaterialSpec material = readMaterial(elements[i]);
        // Names identify materials to animation tracks and messages, so they must be unique.
        for (std::size_t j = 0; j < materials.size(); ++j) {
            if (materials[j].name == material.name) {
                elements[i].child("name").fail("duplicate material name \"" + material.name +
                                               "\" (already used by " + elements[j].pointer() +
                                               ")");
            }
        }
        materials.push_back(std::move(material));
    }
    if (materials.empty()) value.failExpected(form);
    return materials;
}

// ---- lights ----------------------------------------------------------------------------------

glm::vec3 readDirection(const Value& value) {
    // In double: the squares of large float components would overflow a float length.
    const glm::dvec3 direction(value.vec3());
    const double length = glm::length(direction);
    if (!(length > 0.0)) value.failExpected("a non-zero direction [x, y, z]");
    return glm::vec3(direction / length);
}

void readSpotCone(Object& object, LightSpec& light) {
    if (auto angle = object.optional("cone_angle_deg")) {
        light.coneAngleDeg = angle->floatNumber(Range::openClosed(0.0, 90.0));
    }
    // The default softness must not exceed a narrow cone the user asked for.
    light.coneSoftnessDeg = std::min(light.coneSoftnessDeg, light.coneAngleDeg);
    if (auto softness = object.optional("cone_softness_deg")) {
        const double limit = light.coneAngleDeg;
        if (softness->isNumber() && softness->json().get<double>() > limit) {
            std::ostringstream form;
            form << "a number in [0, " << limit << "] (at most cone_angle_deg)";
            softness->failExpected(form.str());
        }
        light.coneSoftnessDeg = softness->floatNumber(Range::closed(0.0, limit));
    }
}

LightSpec readLight(const Value& value) {
    Object object(value, "a light");
    LightSpec light;
    const std::string type = object.required("type", "\"point\", \"directional\" or \"spot\"")
                                 .choice({"point", "directional", "spot"});
    object.setKind("a " + type + " light");
    if (type == "directional") {
        light.type = LightType::Directional;
        object.forbid("position",
                      "a directional light has no position (it shines from infinitely far along "
                      "'direction'); remove 'position' or use \"type\": \"point\" or \"spot\"");
    } else {
        light.type = type == "point" ? LightType::Point : LightType::Spot;
        light.position = object.required("position", kVec3Form).vec3();
    }
    if (type == "point") {
        object.forbid("direction",
                      "a point light shines in every direction; remove 'direction' or use "
                      "\"type\": \"spot\"");
    } else {
        light.direction = readDirection(object.required("direction", "a non-zero [x, y, z]"));
    }
    if (auto color = object.optional("color")) light.color = readColor(*color);
    if (auto intensity = object.optional("intensity")) {
        light.intensity = intensity->floatNumber(Range::atLeast(0.0));
    }
    if (type == "spot") {
        readSpotCone(object, light);
    } else {
        const std::string onlySpot = " applies only to spot lights (\"type\": \"spot\")";
        object.forbid("cone_angle_deg", "'cone_angle_deg'" + onlySpot);
        object.forbid("cone_softness_deg", "'cone_softness_deg'" + onlySpot);
    }
    if (type == "directional") {
        if (auto diameter = object.optional("angular_diameter_deg"))
            light.angularDiameterDeg =
                diameter->floatNumber(Range::closed(0.0, double(kMaxAngularDiameterDeg)));
    } else {
        object.forbid("angular_diameter_deg",
                      "'angular_diameter_deg' is a directional light's disc; a " + type +
                          " light is a point (\"type\": \"directional\" for a soft distant light)");
    }
    object.finish();
    return light;
}

std::vector<LightSpec> readLights(const Value& value) {
    std::vector<LightSpec> lights;
    for (const Value& element : value.elements("an array of lights", kMaxLights)) {
        lights.push_back(readLight(element));
    }
    return lights;
}

// ---- camera, environment, render, output, time ----------------------------------------------

void checkCameraFrame(const Object& object, const CameraSpec& camera) {
    const glm::vec3 view = camera.lookAt - camera.position;
    if (!(glm::length(view) > 0.0f)) {
        object.failAt("look_at", "expected a point different from position " +
                                     formatVec3(camera.position) + ", got the same point");
    }
    const float upLength = glm::length(camera.up);
    const float sine = upLength > 0.0f
                           ? glm::length(glm::cross(glm::normalize(view), camera.up / upLength))
                           : 0.0f;
    // Below ~0.06 degrees the camera's right vector is numerically meaningless.
    if (!(sine > 1e-3f)) {
        const std::string which = object.has("up") ? "" : " (the default)";
        object.failAt("up", "expected an up vector not parallel to the view direction " +
                                formatVec3(glm::normalize(view)) + ", got " +
                                formatVec3(camera.up) + which);
    }
}

CameraSpec readCamera(const Value& value) {
    CameraSpec camera;
    if (value.isString("auto")) return camera;
    if (!value.isObject()) {
        value.failExpected("\"auto\" or an object with position, look_at, up, horizontal_fov_deg");
    }
    Object object(value, "the camera");
    camera.automatic = false;
    if (auto position = object.optional("position")) camera.position = position->vec3();
    if (auto lookAt = object.optional("look_at")) camera.lookAt = lookAt->vec3();
    if (auto up = object.optional("up")) camera.up = up->vec3();
    if (auto fov = object.optional("horizontal_fov_deg")) {
        camera.horizontalFovDeg = fov->floatNumber(Range::open(0.0, 180.0));
    }
    object.finish();
    checkCameraFrame(object, camera);
    return camera;
}

EnvironmentSpec readEnvironment(const Value& value, const fs::path& sceneDirectory) {
    Object object(value, "the environment");
    EnvironmentSpec environment;
    std::string type = "color";
    if (auto t = object.optional("type")) type = t->choice({"color", "gradient", "image"});
    object.setKind("a " + type + " environment");
    if (type == "color") {
        if (auto color = object.optional("color")) environment.color = readColor(*color);
    } else if (type == "gradient") {
        environment.type = EnvironmentType::Gradient;
        environment.zenith = readColor(object.required("zenith", kColorForm));
        environment.horizon = readColor(object.required("horizon", kColorForm));
        environment.ground = readColor(object.required("ground", kColorForm));
    } else {
        environment.type = EnvironmentType::Image;
        const Value file = object.required("file", "the path of an equirectangular .exr file");
        environment.file = resolveAgainst(sceneDirectory, file.nonEmptyString());
        if (auto intensity = object.optional("intensity")) {
            environment.intensity = intensity->floatNumber(Range::atLeast(0.0));
        }
        if (auto rotation = object.optional("rotation_deg")) {
            environment.rotationDeg = rotation->floatNumber();
        }
    }
    // Keys of the other types are unexpected here; finish() names them with the expected ones.
    object.finish();
    return environment;
}

RenderSettings readRender(const Value& value) {
    Object object(value, "the render settings");
    RenderSettings render;
    if (auto width = object.optional("width")) {
        render.width = static_cast<int>(width->integer(1, kMaxImageSize));
    }
    if (auto height = object.optional("height")) {
        render.height = static_cast<int>(height->integer(1, kMaxImageSize));
    }
    if (auto step = object.optional("step_voxels")) {
        render.stepVoxels = step->floatNumber(Range::greaterThan(0.0));
    }
    if (auto integrator = object.optional("integrator")) {
        render.integrator = rayIntegratorNamed(integrator->choice(rayIntegratorNames()));
    }
    if (auto cutoff = object.optional("min_transmittance")) {
        render.minTransmittance = cutoff->floatNumber(Range::closedOpen(0.0, 1.0));
    }
    if (auto fresnel = object.optional("fresnel")) render.fresnel = fresnel->boolean();
    if (auto slope = object.optional("surface_slope")) {
        if (!render.fresnel) slope->fail("\"surface_slope\" needs \"fresnel\": true");
        render.surfaceSlope = slope->floatNumber(Range::greaterThan(0.0));
    }
    if (auto exposure = object.optional("exposure")) render.exposure = exposure->floatNumber();
    if (auto curve = object.optional("tone_map")) {
        render.toneCurve =
            curve->choice({"filmic", "linear"}) == "filmic" ? ToneCurve::Filmic : ToneCurve::Linear;
    }
    if (auto seed = object.optional("seed")) {
        render.seed =
            static_cast<std::uint32_t>(seed->integer(0, std::numeric_limits<std::uint32_t>::max()));
    }
    // The method and its settings are read by the methods themselves (render/
    // light_transport_registry.h); core keeps the section as written.
    if (auto transport = object.optional("light_transport")) {
        if (!transport->isObject())
            transport->failExpected("an object (a method and its settings)");
        render.lightTransport = transport->json().dump();
    }
    // Where the settings of scenes written before the light-transport section went.
    object.forbid("photons",
                  "moved to render.light_transport: {\"method\": \"photons\", \"photons\": {...}} "
                  "(mode \"auto\", \"on\", \"off\" is method \"auto\", \"photons\", "
                  "\"light_volumes\")");
    object.forbid("shadows",
                  "moved to render.light_transport: {\"light_volumes\": {\"shadows\": ...}}");
    object.forbid("shadow_step_voxels",
                  "moved to render.light_transport: {\"light_volumes\": {\"shadow_step_voxels\": "
                  "...}}");
    object.finish();
    return render;
}

OutputSettings readOutput(const Value& value) {
    Object object(value, "the output settings");
    OutputSettings output;
    if (auto directory = object.optional("directory")) {
        output.directory = directory->nonEmptyString();
    }
    if (auto name = object.optional("name")) {
        output.name = name->nonEmptyString();
        output.nameSet = true;
        // The name is a file name prefix; folders belong in "directory".
        if (output.name.find_first_of("/\\") != std::string::npos) {
            name->failExpected("a file name without '/' or '\\' (put folders in \"directory\")");
        }
    }
    if (auto png = object.optional("png")) output.png = png->boolean();
    if (auto exr = object.optional("exr")) output.exr = exr->boolean();
    object.finish();
    return output;
}

TimeSettings readTime(const Value& value) {
    Object object(value, "the time settings");
    TimeSettings time;
    const std::int64_t maxFrame = std::numeric_limits<int>::max();
    if (auto fps = object.optional("fps")) time.fps = fps->number(Range::greaterThan(0.0));
    if (auto start = object.optional("frame_start")) {
        time.frameStart = static_cast<int>(start->integer(0, maxFrame));
    }
    // A scene that only moves its start renders that one frame.
    time.frameEnd = time.frameStart;
    if (auto end = object.optional("frame_end")) {
        time.frameEnd = static_cast<int>(end->integer(0, maxFrame));
        if (time.frameEnd < time.frameStart) {
            end->failExpected("an integer >= frame_start (" + std::to_string(time.frameStart) +
                              ")");
        }
    }
    object.finish();
    return time;
}

// A labelled field ("n.crown") exists only where a source writes it. Procedural sources name
// theirs; a VDB file may hold a grid of that name, which only loading it tells.
void checkLabelledFields(const Value& materials, const Scene& scene) {
    std::vector<std::string> written;
    for (const SourceSpec& source : scene.sources) {
        if (source.type == SourceType::Vdb || source.type == SourceType::VdbSequence) return;
        if (source.type == SourceType::Simulation) {
            for (const std::string& name : simulationFieldNames(scene.simulations))
                written.push_back(name);
            continue;
        }
        written.push_back(source.field);
    }
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const std::string& name = scene.materials[m].field;
        if (name.find('.') == std::string::npos) continue;
        if (std::find(written.begin(), written.end(), name) != written.end()) continue;
        std::string list;
        for (const std::string& w : written) list += (list.empty() ? "" : ", ") + w;
        std::string reason = "no source writes field '" + name + "' (sources write: " + list + ")";
        const std::string suggestion = json::closestMatch(name, written);
        if (!suggestion.empty()) reason += "; did you mean \"" + suggestion + "\"?";
        materials.element(m).child("field").fail(reason);
    }
}

// Appends the meshes' materials after the scene's own: names must stay unique, and all of them
// together must fit the GPU's material slots.
void addMeshMaterials(const Value& meshes, ParsedMeshes parsed, Scene& scene) {
    for (std::size_t i = 0; i < parsed.meshes.size(); ++i)
        for (const MaterialSpec& m : scene.materials)
            if (m.name == parsed.meshes[i].name || m.name == parsed.meshes[i].name + ".n")
                meshes.element(i).child("name").fail("mesh name \"" + parsed.meshes[i].name +
                                                     "\" clashes with material \"" + m.name + "\"");
    if (scene.materials.size() + parsed.materials.size() > kMaxMaterials)
        meshes.fail("the materials (" + std::to_string(scene.materials.size()) +
                    ") and the meshes' (" + std::to_string(parsed.materials.size()) +
                    ": one for n, one for absorption/scattering/emission per mesh) exceed " +
                    std::to_string(kMaxMaterials) + " material slots");
    scene.materials.insert(scene.materials.end(), parsed.materials.begin(), parsed.materials.end());
    scene.meshes = std::move(parsed.meshes);
}

Scene readScene(const Value& root, const std::string& file) {
    Object object(root, "the scene");
    Scene scene;
    scene.path = file;
    const fs::path sceneDirectory = fs::path(file).parent_path();
    if (auto volume = object.optional("volume")) scene.volume = readVolume(*volume);
    // Meshes carry their own materials, so a scene of meshes alone needs neither sources nor
    // materials.
    const auto meshes = object.optional("meshes");
    ParsedMeshes parsedMeshes;
    if (meshes) parsedMeshes = readMeshes(*meshes, sceneDirectory);
    const bool hasMeshes = !parsedMeshes.meshes.empty();
    // Before the materials: the fields its domains publish are fields materials may read.
    if (auto simulation = object.optional("simulation"))
        scene.simulations = readSimulations(*simulation, sceneDirectory, parsedMeshes.meshes);
    if (auto sources = object.optional("sources"); sources || !hasMeshes)
        scene.sources = readSources(
            sources ? *sources : object.required("sources", "a non-empty array of sources"),
            sceneDirectory);
    if (auto materials = object.optional("materials"); materials || !hasMeshes) {
        const Value list =
            materials ? *materials : object.required("materials", "a non-empty array of materials");
        scene.materials = readMaterials(list);
        checkLabelledFields(list, scene);
    }
    if (hasMeshes) addMeshMaterials(*meshes, std::move(parsedMeshes), scene);
    if (auto lights = object.optional("lights")) scene.lights = readLights(*lights);
    if (auto receivers = object.optional("receivers")) scene.receivers = readReceivers(*receivers);
    // After the meshes' materials: a plane may cut those too.
    if (auto clip = object.optional("clip_planes")) scene.clipPlanes = readClipPlanes(*clip, scene);
    if (auto camera = object.optional("camera")) scene.camera = readCamera(*camera);
    if (auto environment = object.optional("environment")) {
        scene.environment = readEnvironment(*environment, sceneDirectory);
    }
    if (auto render = object.optional("render")) scene.render = readRender(*render);
    if (auto output = object.optional("output")) scene.output = readOutput(*output);
    if (auto time = object.optional("time")) scene.time = readTime(*time);
    // The cache takes the scene's output name when it has one, so that a scene's images and
    // its simulation share a prefix.
    setSimulationCacheNames(scene.simulations, scene.output.nameSet ? scene.output.name : "smoke");
    // Last: tracks point into everything above.
    if (auto animation = object.optional("animation"))
        scene.animation = readAnimation(*animation, scene);
    checkObstaclesStandStill(scene);
    for (const SourceSpec& source : scene.sources)
        if (source.type == SourceType::Simulation && scene.simulations.empty())
            throw Error(file + ":" + source.jsonPath + "/type",
                        "a \"simulation\" source shows the scene's smoke simulation, and the scene "
                        "has no \"simulation\" section");
    object.finish();
    checkSceneMemory(scene, root);
    return scene;
}

}  // namespace

Scene parseScene(const std::string& jsonText, const std::string& fileForMessages) {
    const json::Json document = json::parseDocument(jsonText, fileForMessages);
    return readScene(Value(document, fileForMessages, ""), fileForMessages);
}

Scene loadScene(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Error(path, "scene file not found");
    if (fs::is_directory(path, ec)) throw Error(path, "is a folder, expected a scene file (.json)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path, std::string("cannot open the scene file: ") + std::strerror(errno));
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw Error(path, "cannot read the scene file");
    return parseScene(text, path);
}

}  // namespace eikon
