#include "apps/view_handles.h"

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "core/error.h"

namespace eikon::app {

namespace {

constexpr float kMarkerRadius = 6.0f;      // pixels
constexpr float kMarkerHalfWidth = 0.75f;  // pixels either side of the ring
// Far above any radiance a scene shows, so that any exposure saturates the marker's colour.
constexpr float kMarkerBrightness = 1e4f;

}  // namespace

ViewHandles::ViewHandles(SceneDriver& driver, const Scene& scene)
    : driver_(driver), handles_(driver.arapHandles()), scenePath_(scene.path) {
    for (const SceneDriver::HandleRef& h : handles_)
        names_.push_back(scene.meshes[h.mesh].name + "/" +
                         scene.meshes[h.mesh].arap->handles[h.handle].name);
    onImage_.assign(handles_.size(), std::nullopt);
}

void ViewHandles::locate(const CameraFrame& camera, int width) {
    for (size_t i = 0; i < handles_.size(); ++i)
        onImage_[i] = projectToImage(camera, driver_.handleCentre(handles_[i]), width);
}

bool ViewHandles::pick(glm::vec2 cursor) {
    int best = -1;
    float bestDistance = 4.0f * kMarkerRadius;
    for (size_t i = 0; i < handles_.size(); ++i) {
        if (!onImage_[i]) continue;
        const float d = glm::length(*onImage_[i] - cursor);
        if (d <= bestDistance) best = int(i), bestDistance = d;
    }
    if (best >= 0) selected_ = best;
    return best >= 0;
}

void ViewHandles::selectNext() {
    if (!handles_.empty()) selected_ = (selected_ + 1) % int(handles_.size());
}

void ViewHandles::select(const std::string& meshSlashHandle) {
    std::string choices;
    for (size_t i = 0; i < names_.size(); ++i) {
        if (names_[i] == meshSlashHandle) {
            selected_ = int(i);
            return;
        }
        choices += (i ? ", " : "") + names_[i];
    }
    throw Error("--drag",
                "no ARAP handle '" + meshSlashHandle + "' in " + scenePath_ +
                    " (its handles: " + (choices.empty() ? std::string("none") : choices) + ")");
}

void ViewHandles::drag(FrameInputs& inputs, const CameraFrame& camera, int width,
                       glm::vec2 pixels) {
    if (selected_ < 0) return;
    const SceneDriver::HandleRef h = handles_[size_t(selected_)];
    const glm::vec3 centre = driver_.handleCentre(h);
    driver_.dragHandle(h, cameraPlaneMotion(camera, centre, pixels, width), inputs);
}

std::string ViewHandles::describeSelected(double timeSeconds) const {
    if (selected_ < 0) return "no handle selected";
    const SceneDriver::HandleRef h = handles_[size_t(selected_)];
    const std::optional<glm::vec2>& at = onImage_[size_t(selected_)];
    const glm::vec3 t = driver_.handleTranslation(h);
    char text[512];
    std::snprintf(text, sizeof(text),
                  "handle %s at pixel (%.3f, %.3f); to keep this pose: {\"target\": "
                  "\"/meshes/%zu/deformer/handles/%zu/translate\", \"times\": [%.6g], "
                  "\"values\": [[%.6g, %.6g, %.6g]]}",
                  names_[size_t(selected_)].c_str(), at ? at->x : NAN, at ? at->y : NAN, h.mesh,
                  h.handle, timeSeconds, t.x, t.y, t.z);
    return text;
}

void ViewHandles::drawMarkers(Image& image) const {
    for (size_t i = 0; i < handles_.size(); ++i) {
        if (!onImage_[i]) continue;
        const glm::vec2 c = *onImage_[i];
        const glm::vec4 colour = int(i) == selected_
                                     ? glm::vec4(kMarkerBrightness, kMarkerBrightness, 0.0f, 1.0f)
                                     : glm::vec4(0.0f, kMarkerBrightness, kMarkerBrightness, 1.0f);
        const float reach = kMarkerRadius + kMarkerHalfWidth;
        for (int y = int(std::floor(c.y - reach)); y <= int(std::ceil(c.y + reach)); ++y)
            for (int x = int(std::floor(c.x - reach)); x <= int(std::ceil(c.x + reach)); ++x) {
                if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
                const float d = glm::length(glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - c);
                if (std::abs(d - kMarkerRadius) <= kMarkerHalfWidth) image.at(x, y) = colour;
            }
    }
}

}  // namespace eikon::app
