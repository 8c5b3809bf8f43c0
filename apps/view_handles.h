#pragma once
// The viewer's ARAP handles: Sun et al.'s interactive surface manipulation, with the deformer of
// sim/arap_drag.h. A ring marks each handle where the picture shows the centre of its vertices,
// the selected one yellow, the others cyan. A right click picks the handle nearest the cursor, H
// selects the next one, and a right drag moves the selected handle in the camera plane through
// it, so the handle stays under the cursor; the shape follows at once (SceneDriver::dragHandle).
// On release the view prints the key that keeps the pose in the scene file.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/camera.h"
#include "pipeline/scene_driver.h"
#include "render/image.h"

namespace eikon::app {

class ViewHandles {
public:
    ViewHandles(SceneDriver& driver, const Scene& scene);

    // Where the handles show on a `width`-wide image under `camera`, for the prepared frame:
    // after every prepared frame, before picking, dragging or drawing.
    void locate(const CameraFrame& camera, int width);

    // Selects the handle whose marker is nearest `cursor` (image pixels), if within four marker
    // radii of it; false (the selection kept) when none is.
    bool pick(glm::vec2 cursor);
    void selectNext();
    // Selects "mesh/handle" by the scene's names; throws eikon::Error naming the choices.
    void select(const std::string& meshSlashHandle);
    bool selected() const { return selected_ >= 0; }

    // Moves the selected handle so that its marker moves by `pixels` (x right, y down) on the
    // `width`-wide image under `camera`, and the prepared frame's shape after it (into `inputs`,
    // the frame's, which the renderer then takes).
    void drag(FrameInputs& inputs, const CameraFrame& camera, int width, glm::vec2 pixels);

    // The selected handle: its name, where its marker is, and the key (at `timeSeconds`) that
    // keeps its dragged pose.
    std::string describeSelected(double timeSeconds) const;

    void drawMarkers(Image& image) const;

private:
    SceneDriver& driver_;
    std::vector<SceneDriver::HandleRef> handles_;
    std::string scenePath_;
    std::vector<std::string> names_;  // "mesh/handle"
    std::vector<std::optional<glm::vec2>> onImage_;
    int selected_ = -1;
};

}  // namespace eikon::app
