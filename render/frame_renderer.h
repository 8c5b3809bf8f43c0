#pragma once
// One frame from scene to image: sources -> fields -> dense volumes -> (upload) -> ∇n, octree ->
// the scene's light-transport method (render/light_transport.h) -> viewing pass. Each step reruns
// only when its input changed: files are read when the frame's file changes, fields are
// resampled when their version or the volume changes, textures are uploaded when the resampled
// grid changes, the ∇n volume and the octree when n (or, for the octree, κ) changes, and the
// method when its own cache key does (lights, optics, the volume, its settings). Runs on the GPU
// (headless EGL context it owns) or on the CPU twin.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/dense_grid.h"
#include "core/field_registry.h"
#include "core/scene.h"
#include "core/scene_sources.h"
#include "core/triangle_mesh.h"
#include "render/gpu_timer.h"
#include "render/image.h"
#include "render/light_transport.h"
#include "render/mesh_fields.h"

namespace eikon {

class EnvironmentMap;
class GlContext;
class MeshVoxelizerGpu;
class RefractionVolumesGpu;
class ParamsBuffer;
class VolumeTextures;
class ViewPassGpu;

enum class Backend { Gpu, Cpu };

// What the program rendering a scene hands the renderer for one frame, besides what the scene's
// own sources load (pipeline/scene_driver.h makes them each frame): the scene as it stands at that
// frame (its tracks evaluated, a viewer's camera), the object-space meshes made or moved since the
// last frame (a file's, a deformer's output), and the fields it computed itself (a live smoke
// simulation: sources of type Simulation). The renderer keeps what it was given: a mesh or a
// field not given again stays as it was, and only what changed reruns.
struct FrameInputs {
    FrameInputs() = default;
    FrameInputs(int frameNumber, Scene frameScene)
        : frame(frameNumber), scene(std::move(frameScene)) {}

    int frame = 0;
    Scene scene;
    // Scene mesh index and its triangles; core cannot read mesh files, so a file's mesh comes
    // here (sim/mesh_io.h); meshes from shapes are generated already.
    std::vector<std::pair<size_t, TriangleMesh>> meshes;
    // Each field is stored as a new version: it is resampled and uploaded again.
    FieldRegistry fields;
};

class FrameRenderer {
public:
    // Gpu renders in `context` (a window's, kept current by the caller) or, when null, in a
    // headless GL 4.3 context of its own; throws eikon::Error when there is none.
    FrameRenderer(const Scene& scene, Backend backend, GlContext* context = nullptr);
    ~FrameRenderer();

    // Renders frame `inputs.frame` of `inputs.scene` with its meshes and fields (camera, lights
    // and materials changes need no reload). Throws eikon::Error for a bad mesh index or an
    // unusable mesh, naming it, and for anything the scene's sources or optics get wrong.
    Image render(const FrameInputs& inputs);
    // Renders frame `frame` of the scene as last given (the constructor's or the last inputs').
    Image render(int frame);

    // Meshes voxelized so far: only when a mesh, its placement or the render volume changed.
    int voxelizations() const { return meshFields_.voxelizations(); }

    // The scene of the last frame rendered (the constructor's before any).
    const Scene& scene() const { return scene_; }
    const RenderVolume& volume() const { return volume_; }
    const FieldRegistry& fields() const { return fields_; }
    Backend backend() const { return backend_; }
    const GlContext* context() const { return gl_; }
    // Stage times summed since the last call (load, resample, upload, light, view, readback).
    std::vector<StageTime> takeStats();
    // `listener` hears each stage's name as it starts (render/gpu_timer.h).
    void setStageListener(std::function<void(const std::string&)> listener);
    int uploads() const;
    int resamples() const { return resamples_; }
    // How often the light-transport method `method` ran: only when its cache key changed
    // (lights, extinction, n, the volume or its settings; a camera move reruns nothing), but
    // every frame for a method that views as it lights (LightTransport::viewsInterleaved).
    int transportRuns(const std::string& method) const;
    // The method the scene's render.light_transport chose (render/light_transport_registry.h).
    const LightTransport& lightTransport() const { return *transport_; }
    // Preview pictures (the viewer's while something changes): a frame whose light transport
    // must run again runs the method's lighter settings instead (LightTransport::previewPatch),
    // and the full run's output and key stay as they were, for the picture that refines it
    // (rendered with setPreview(false), it runs the full method). A camera move runs nothing
    // either way and keeps the full output.
    void setPreview(bool preview) { preview_ = preview; }
    // How often the lighter preview run replaced the method's own (not in transportRuns).
    int previewTransportRuns() const { return previewRuns_; }
    // Particle steps of every run so far, and the last run's counters.
    int64_t transportSteps() const { return transportSteps_; }
    TransportStats lastTransportStats() const { return lastTransportStats_; }
    // How often the ∇n volume was computed: only for scenes with some ior ≠ 1 or a method that
    // needs it, and only when fields, materials' ior or the volume changed.
    int gradientUpdates() const { return gradientUpdates_; }
    // How often the octree was built: only for a method that needs it, and only when n, κ (the
    // κ-aware octree), the volume or its settings changed.
    int octreeUpdates() const { return octreeUpdates_; }
    // How often the environment image was read: once per change of its path.
    int environmentLoads() const;
    // Whether the GPU shaders let the texture unit filter (see useHardwareTrilinear).
    bool hardwareTrilinear() const { return hardwareTrilinear_; }

private:
    void setMesh(size_t index, TriangleMesh objectSpace);
    const DenseGrid& classifiedSlot(const std::string& slotName, const DenseGrid& field,
                                    const std::vector<glm::vec2>& transfer);
    void updateTransport(const ViewSetup& base, const std::vector<const DenseGrid*>& slotGrids);
    // The method with its preview patch applied, made again when the patch changes; null when
    // the method has nothing lighter.
    LightTransport* previewTransport();

    Scene scene_;
    Backend backend_;
    std::unique_ptr<GlContext> ownContext_;
    GlContext* gl_ = nullptr;  // ownContext_ or the caller's
    SceneSources sources_;
    FieldRegistry fields_;
    MeshFields meshFields_;
    std::unique_ptr<MeshVoxelizerGpu> voxelizerGpu_;
    std::map<std::string, DenseGrid> dense_;  // by field name, and by slot name (view_params.h)
    // What each transfer-function slot of dense_ was made from (classifiedSlot).
    struct Classified {
        std::uint64_t fieldVersion = 0;
        RenderVolume volume;
        std::vector<glm::vec2> transfer;
    };
    std::map<std::string, Classified> classified_;
    // Versions of classified slots: far above any field's (core/field_registry.h counts from 1),
    // so the two never meet.
    std::uint64_t nextClassifiedVersion_ = std::uint64_t(1) << 62;
    RenderVolume volume_;
    std::unique_ptr<VolumeTextures> textures_;
    std::unique_ptr<ParamsBuffer> paramsBuffer_;
    std::unique_ptr<ViewPassGpu> viewPass_;
    std::unique_ptr<EnvironmentMap> environment_;
    std::unique_ptr<RefractionVolumesGpu> refractionGpu_;
    std::vector<glm::vec4> gradientCpu_;
    ChannelGradientsCpu channelGradientsCpu_;  // dispersion's red and blue ∇n volumes
    std::vector<glm::vec4> octreeCpu_;
    TransportDevice device_;
    std::unique_ptr<LightTransport> transport_;
    std::string transportSection_;                // the render.light_transport it was made from
    std::vector<unsigned char> gradientInputs_;   // what the ∇n volume was computed from
    std::vector<unsigned char> octreeInputs_;     // what the octree was computed from
    std::vector<unsigned char> transportInputs_;  // what the method's output was computed from
    // The lighter run for previews (setPreview), made from the method's previewPatch().
    bool preview_ = false;
    std::unique_ptr<LightTransport> previewTransport_;
    std::string previewSection_;                // the patched render.light_transport
    std::vector<unsigned char> previewInputs_;  // what its output was computed from
    int previewRuns_ = 0;
    std::unique_ptr<GpuStageTimer> timer_;
    int resamples_ = 0;
    int gradientUpdates_ = 0;
    int octreeUpdates_ = 0;
    std::map<std::string, int> transportRuns_;
    int64_t transportSteps_ = 0;
    TransportStats lastTransportStats_;
    bool hardwareTrilinear_ = false;
};

}  // namespace eikon
