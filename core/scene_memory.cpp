#include "core/scene_memory.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include "core/memory_limit.h"
#include "core/procedural.h"
#include "core/scene.h"

namespace eikon::scene_detail {
namespace {

struct MemoryPart {
    std::string where;  // file:pointer
    std::string what;
    double bytes = 0.0;
    std::string advice;
};

// The deepest existing value along `keys` below `root` (the key itself may be absent, its
// default then applies): "scene.json:/render/width", or "scene.json:/render".
std::string whereOf(const json::Value& root, const std::vector<std::string>& keys) {
    json::Value at = root;
    for (const std::string& key : keys) {
        if (!at.json().is_object() || !at.json().contains(key)) break;
        at = at.child(key);
    }
    return at.where();
}

std::string voxelsText(glm::ivec3 n) {
    std::ostringstream text;
    text << n.x << "×" << n.y << "×" << n.z;
    return text.str();
}

double product(glm::ivec3 n) {
    return double(n.x) * double(n.y) * double(n.z);
}

std::vector<MemoryPart> sceneParts(const Scene& scene, const json::Value& root) {
    std::vector<MemoryPart> parts;
    if (!scene.volume.autoResolution)
        parts.push_back({whereOf(root, {"volume", "resolution"}),
                         "the render volume of " + voxelsText(scene.volume.resolution) + " voxels",
                         renderVolumeBytes(product(scene.volume.resolution)),
                         "lower volume.resolution"});
    parts.push_back(
        {whereOf(root, {"render", "width"}),
         "the " + std::to_string(scene.render.width) + "×" + std::to_string(scene.render.height) +
             " image",
         double(scene.render.width) * double(scene.render.height) * kRenderBytesPerPixel,
         "lower render.width and render.height"});
    for (const SourceSpec& source : scene.sources)
        if (source.type == SourceType::Sphere || source.type == SourceType::Box)
            parts.push_back({scene.path + ":" + source.jsonPath, "the field of " + source.jsonPath,
                             proceduralFieldBytes(source), "use a larger voxel_size"});
    for (const SmokeSimulationSpec& simulation : scene.simulations)
        parts.push_back({scene.path + ":" + simulation.jsonPath + "/resolution",
                         "the smoke domain of " + voxelsText(simulation.resolution) + " cells",
                         product(simulation.resolution) * kSmokeBytesPerCell,
                         "lower its resolution"});
    return parts;
}

}  // namespace

void checkSceneMemory(const Scene& scene, const json::Value& root) {
    const std::vector<MemoryPart> parts = sceneParts(scene, root);
    double total = 0.0;
    for (const MemoryPart& part : parts) {
        checkMemory(part.where, part.bytes, part.what, part.advice);
        total += part.bytes;
    }
    if (parts.empty()) return;
    // Each part fits; all of them are alive at once while a frame renders.
    const MemoryPart& largest = *std::max_element(
        parts.begin(), parts.end(),
        [](const MemoryPart& a, const MemoryPart& b) { return a.bytes < b.bytes; });
    checkMemory(
        largest.where, total,
        "the scene (its largest part: " + largest.what + ", " + formatBytes(largest.bytes) + ")",
        largest.advice);
}

}  // namespace eikon::scene_detail
