#pragma once
// What the commands that render a scene hand the renderer for each frame (FrameInputs), so that
// `eikon render` and `eikon view` show the same state at the same frame: the scene's keyframe
// tracks evaluated at the frame's time on the one clock (sim/clock.h, the scene's fps), and every
// simulated or dragged mesh (water surfaces, jellies, ARAP handles) stepped to that frame from its
// start at frame 0, so a
// frame is the same however it is reached. Mesh files are read once, here (sim/refractive_mesh.h:
// holes closed as the scene asks, then checked closed), since the renderer cannot read them, and
// liquids are made once from their containers (sim/container_fill.h). A scene whose source is its
// own smoke simulation has it stepped here and its fields handed over every new frame
// (sim/field_simulation.h); moving meshes are sim/moving_mesh.h's.
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "render/frame_renderer.h"
#include "sim/animation.h"
#include "sim/clock.h"
#include "sim/field_simulation.h"
#include "sim/moving_mesh.h"

namespace eikon {

class SceneDriver {
public:
    // `simulationFromCache`: live simulations read the frames `eikon simulate` cached
    // (sim/field_simulation.h makeFieldSimulations).
    explicit SceneDriver(const Scene& scene, bool simulationFromCache = false);

    // What the renderer takes for frame `frame` (render/frame_renderer.h FrameInputs): `base`,
    // the scene as the command set it up, with its tracks evaluated at the frame's time; the
    // meshes read once (on the first call) or moved to this frame; and the fields of the live
    // simulations when they moved on. Nothing is written into the renderer: it gets this.
    FrameInputs frameInputs(int frame, const Scene& base);
    double timeOfFrame(int frame) const { return clock_.timeOfFrame(frame); }

    // The user's drags of ARAP handles (eikon view). A drag moves a handle at every frame, on
    // top of what its tracks do, so playing or stepping frames keeps it; the frame on screen
    // follows at once, by more iterations from its current shape (sim/arap_drag.h
    // dragCurrentFrame), and a frame reached later is solved from rest with the drags in.
    // All of them work on the last frame frameInputs prepared, and throw before the first.
    struct HandleRef {
        size_t mesh = 0;    // index into scene.meshes
        size_t handle = 0;  // index into that mesh's deformer handles
    };
    std::vector<HandleRef> arapHandles() const;
    // The world position of the centre of the handle's vertices in the prepared frame's shape.
    glm::vec3 handleCentre(HandleRef h) const;
    // Moves the handle by `worldMotion` (in the prepared frame's placement), re-solves the
    // prepared frame's shape and adds it to `inputs`, that frame's.
    void dragHandle(HandleRef h, glm::vec3 worldMotion, FrameInputs& inputs);
    // The handle's translation at the prepared frame with the drags in: the value a key of its
    // /meshes/i/deformer/handles/j/translate track needs to keep the dragged pose.
    glm::vec3 handleTranslation(HandleRef h) const;

private:
    sim::SceneAnimation animation_;
    SimulationClock clock_;
    // The meshes something moves (sim/moving_mesh.h): only a new frame changes one, so a camera
    // move on the same frame re-voxelizes nothing.
    struct Moving {
        std::unique_ptr<sim::MovingMesh> mesh;
        int frameSet = -1;  // the frame whose mesh the renderer has
    };
    std::vector<Moving> moving_;
    // Throws unless mesh `mesh` has an ARAP deformer.
    sim::ArapMovingMesh& arapOf(size_t mesh);
    const sim::ArapMovingMesh& arapOf(size_t mesh) const {
        return const_cast<SceneDriver*>(this)->arapOf(mesh);
    }
    // The simulations whose fields the scene shows live (sim/field_simulation.h).
    std::vector<std::unique_ptr<sim::FieldSimulation>> fieldSimulations_;
    // Meshes made here that no simulation moves (read from files, liquids filling their
    // containers): handed to the renderer once.
    std::vector<std::pair<size_t, TriangleMesh>> fixedMeshes_;
    bool fixedMeshesSet_ = false;
    // The scene of the frame frameInputs prepared last (tracks evaluated), which the handles'
    // placements are read from; empty before.
    std::optional<Scene> prepared_;
    const Scene& preparedScene() const;
};

}  // namespace eikon
