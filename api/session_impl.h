#pragma once
// What a Session holds (include/eikon/eikon.h): the scene as the user set it up, the driver that
// steps its simulations and animation (pipeline/scene_driver.h), the renderer, and what the driver
// handed over since the last render, so that stepping without rendering loses nothing (the
// renderer keeps what it was given: meshes handed once, fields only when they moved).
#include <memory>
#include <optional>

#include "core/field_registry.h"
#include "eikon/eikon.h"
#include "pipeline/backend_choice.h"
#include "pipeline/scene_driver.h"
#include "render/frame_renderer.h"

namespace eikon {

struct Session::Impl {
    Scene base;  // the scene with the user's changes; tracks are evaluated on it per frame
    BackendChoice backend;
    std::unique_ptr<SceneDriver> driver;
    std::unique_ptr<FrameRenderer> renderer;
    // Handed over by the driver since the last render: its meshes, and fields that moved.
    std::vector<std::pair<size_t, TriangleMesh>> pendingMeshes;
    FieldRegistry pendingFields;
    // Every field the driver handed over so far (live simulations), the newest of each.
    FieldRegistry steppedFields;
    std::optional<int> steppedFrame;

    Impl(Scene scene, Device device);
    // The driver's inputs for `frame`, with what was pending folded in.
    FrameInputs step(int frame);
};

}  // namespace eikon
