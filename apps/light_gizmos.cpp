#include "apps/light_gizmos.h"

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "core/error.h"

namespace eikon::app {
namespace {

constexpr float kSquareHalf = 5.0f;        // pixels from the centre to a side
constexpr float kSquareHalfWidth = 0.75f;  // pixels either side of the outline
// Far above any radiance a scene shows, so that any exposure saturates the marker's colour.
constexpr float kMarkerBrightness = 1e4f;

}  // namespace

void LightGizmos::locate(const Scene& shown, const Bounds3& volume, const CameraFrame& camera,
                         int width) {
    centre_ = 0.5f * (volume.min + volume.max);
    reach_ = 0.5f * glm::length(volume.max - volume.min);
    const float reach = reach_;
    anchors_.assign(shown.lights.size(), Anchor{});
    for (size_t i = 0; i < shown.lights.size(); ++i) {
        const LightSpec& light = shown.lights[i];
        Anchor& a = anchors_[i];
        a.directional = light.type == LightType::Directional;
        // The direction is the way the light travels: it comes from −direction.
        a.world =
            a.directional ? centre_ - reach * glm::normalize(light.direction) : light.position;
        a.onImage = projectToImage(camera, a.world, width);
    }
    if (selected_ >= int(anchors_.size())) selected_ = -1;
}

bool LightGizmos::pick(glm::vec2 cursor) {
    int best = -1;
    float bestDistance = 4.0f * kSquareHalf;
    for (size_t i = 0; i < anchors_.size(); ++i) {
        if (!anchors_[i].onImage) continue;
        const float d = glm::length(*anchors_[i].onImage - cursor);
        if (d <= bestDistance) best = int(i), bestDistance = d;
    }
    if (best >= 0) selected_ = best;
    return best >= 0;
}

void LightGizmos::select(const std::string& name, size_t lightCount) {
    for (size_t i = 0; i < lightCount; ++i)
        if (name == "lights/" + std::to_string(i)) {
            selected_ = int(i);
            return;
        }
    throw Error("--drag", "no light '" + name + "' (the scene has " + std::to_string(lightCount) +
                              " light" + (lightCount == 1 ? "" : "s") + ": lights/0 ...)");
}

void LightGizmos::drag(const Scene& shown, const CameraFrame& camera, int width, glm::vec2 pixels,
                       ViewEdits& edits) const {
    if (selected_ < 0 || size_t(selected_) >= anchors_.size()) return;
    const Anchor& a = anchors_[size_t(selected_)];
    const glm::vec3 moved = a.world + cameraPlaneMotion(camera, a.world, pixels, width);
    const std::string base = "/lights/" + std::to_string(selected_) + "/";
    if (a.directional) {
        // The square stays on its sphere about the volume's centre: where the ray through the
        // cursor's new pixel meets it (the crossing nearer the square's old place), or, for a ray
        // that passes by, the sphere's point nearest the ray.
        const glm::vec3 o = camera.origin, ray = glm::normalize(moved - o);
        const glm::vec3 oc = o - centre_;
        const float b = glm::dot(oc, ray), disc = b * b - (glm::dot(oc, oc) - reach_ * reach_);
        glm::vec3 onSphere;
        if (disc >= 0.0f) {
            const glm::vec3 nearHit = o + (-b - std::sqrt(disc)) * ray;
            const glm::vec3 farHit = o + (-b + std::sqrt(disc)) * ray;
            onSphere =
                glm::length(nearHit - a.world) <= glm::length(farHit - a.world) ? nearHit : farHit;
        } else {
            onSphere = centre_ + reach_ * glm::normalize(o - b * ray - centre_);
        }
        const glm::vec3 d = glm::normalize(centre_ - onSphere);
        edits.set(shown, base + "direction", {d.x, d.y, d.z});
    } else {
        edits.set(shown, base + "position", {moved.x, moved.y, moved.z});
    }
}

std::string LightGizmos::describeSelected(const ViewEdits& edits) const {
    if (selected_ < 0 || size_t(selected_) >= anchors_.size()) return "no light selected";
    const std::optional<glm::vec2>& at = anchors_[size_t(selected_)].onImage;
    char text[96];
    std::snprintf(text, sizeof(text), "light %d at pixel (%.3f, %.3f); ", selected_,
                  at ? at->x : NAN, at ? at->y : NAN);
    return text + ("to keep it, patch the scene with " + edits.jsonPatch());
}

void LightGizmos::drawMarkers(Image& image) const {
    for (size_t i = 0; i < anchors_.size(); ++i) {
        if (!anchors_[i].onImage) continue;
        const glm::vec2 c = *anchors_[i].onImage;
        const glm::vec4 colour =
            int(i) == selected_
                ? glm::vec4(kMarkerBrightness, 0.5f * kMarkerBrightness, 0.0f, 1.0f)
                : glm::vec4(kMarkerBrightness, kMarkerBrightness, kMarkerBrightness, 1.0f);
        const float reach = kSquareHalf + kSquareHalfWidth;
        for (int y = int(std::floor(c.y - reach)); y <= int(std::ceil(c.y + reach)); ++y)
            for (int x = int(std::floor(c.x - reach)); x <= int(std::ceil(c.x + reach)); ++x) {
                if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
                // Distance to the square's outline in the max norm.
                const glm::vec2 d = glm::abs(glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - c);
                if (std::abs(std::max(d.x, d.y) - kSquareHalf) <= kSquareHalfWidth)
                    image.at(x, y) = colour;
            }
    }
}

}  // namespace eikon::app
