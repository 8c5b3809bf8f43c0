#pragma once
// The viewer's light gizmos: a square marks each light in the picture, the selected one orange,
// the others white; they show with the panel (Tab hides both). A point or spot light's square is
// its position; a directional light's is the point a half diagonal of the render volume from its
// centre, toward the light, so that it shows where the light comes from. A right drag moves the
// square in the camera plane through it (as ARAP handles move, apps/view_handles.h): a positioned
// light goes with it, a directional light turns to shine from it toward the volume's centre (its
// square stays on the sphere of that half diagonal, and slides along the sphere's outline where the
// cursor leaves it). Each drag is an edit (apps/view_edits.h), kept over the frames and in the JSON
// Patch.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "apps/view_edits.h"
#include "core/bounds.h"
#include "core/camera.h"
#include "core/scene.h"
#include "render/image.h"

namespace eikon::app {

class LightGizmos {
public:
    // Where each light of `shown` (the scene on screen, edits in) shows on a `width`-wide image
    // under `camera`, the render volume `volume` placing directional lights' squares.
    void locate(const Scene& shown, const Bounds3& volume, const CameraFrame& camera, int width);

    // Selects the light whose square is nearest `cursor` (image pixels), within four square
    // sizes; false (the selection kept) when none is.
    bool pick(glm::vec2 cursor);
    // Selects "lights/<i>" (--drag); throws eikon::Error at "--drag" for a light not there.
    void select(const std::string& name, size_t lightCount);
    bool selected() const { return selected_ >= 0; }
    void deselect() { selected_ = -1; }

    // Moves the selected light's square by `pixels` (x right, y down) on the image of the last
    // locate(), keeping the light in `edits` (a position, or a direction).
    void drag(const Scene& shown, const CameraFrame& camera, int width, glm::vec2 pixels,
              ViewEdits& edits) const;

    // The selected light: where its square is, and the edits as a JSON Patch that keeps them.
    std::string describeSelected(const ViewEdits& edits) const;

    void drawMarkers(Image& image) const;

private:
    struct Anchor {
        glm::vec3 world{0.0f};
        bool directional = false;
        std::optional<glm::vec2> onImage;
    };
    std::vector<Anchor> anchors_;
    glm::vec3 centre_{0.0f};  // the render volume's, and its half diagonal
    float reach_ = 1.0f;
    int selected_ = -1;
};

}  // namespace eikon::app
