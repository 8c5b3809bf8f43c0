#pragma once
// One frame from scene to image: sources -> fields -> dense volumes -> (upload) -> ∇n, octree ->
// photons or light volumes -> viewing pass. Each step reruns only when its input changed: files
// are read when the frame's file changes, fields are resampled when their version or the volume
// changes, textures are uploaded when the resampled grid changes, photons are traced when
// lights, optics, the volume or the photon settings change (ARCHITECTURE.md's table). Runs on
// the GPU (headless EGL context it owns) or on the CPU twin.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/dense_grid.h"
#include "core/field_registry.h"
#include "core/scene.h"
#include "core/scene_sources.h"
#include "render/gpu_timer.h"
#include "render/image.h"
#include "render/light_volume.h"
#include "render/mesh_fields.h"
#include "render/photon_radiance.h"

namespace eikon {

class EnvironmentMap;
class GlContext;
class LightVolumesGpu;
class MeshVoxelizerGpu;
class PhotonRadianceGpu;
class RefractionVolumesGpu;
class ParamsBuffer;
class VolumeTextures;
class ViewPassGpu;

enum class Backend { Gpu, Cpu };

class FrameRenderer {
public:
    // Gpu renders in `context` (a window's, kept current by the caller) or, when null, in a
    // headless GL 4.3 context of its own; throws eikon::Error when there is none.
    FrameRenderer(const Scene& scene, Backend backend, GlContext* context = nullptr);
    ~FrameRenderer();

    Image render(int frame);

    // The object-space triangles of scene mesh `index`: a file's (core cannot read meshes; the
    // caller loads them through sim/mesh_io.h) or a deformer's output each frame. Meshes from
    // shapes are generated already. Throws eikon::Error for a bad index or an unusable mesh.
    void setMesh(size_t index, TriangleMesh objectSpace);
    // Meshes voxelized so far: only when a mesh, its placement or the render volume changed.
    int voxelizations() const { return meshFields_.voxelizations(); }

    // The scene, for changes between frames (camera, lights, materials need no reload).
    Scene& scene() { return scene_; }
    const Scene& scene() const { return scene_; }
    const RenderVolume& volume() const { return volume_; }
    const FieldRegistry& fields() const { return fields_; }
    // Where the program rendering the scene publishes fields it computes itself each frame (a
    // live smoke simulation: sources of type Simulation); a new version re-uploads the field.
    FieldRegistry& publishedFields() { return fields_; }
    Backend backend() const { return backend_; }
    const GlContext* context() const { return gl_; }
    // Stage times summed since the last call (load, resample, upload, light, view, readback).
    std::vector<StageTime> takeStats();
    int uploads() const;
    int resamples() const { return resamples_; }
    // How often the light transmittance volumes were computed: only when lights, extinction or
    // fields changed (a camera move reuses them).
    int lightVolumeUpdates() const { return lightVolumeUpdates_; }
    // How often the ∇n volume was computed: only for scenes with some ior ≠ 1, and only when
    // fields, materials' ior or the volume changed.
    int gradientUpdates() const { return gradientUpdates_; }
    // How often photons were traced (only when lights, extinction, n, the volume or the photon
    // settings changed), and the photon steps all those traces took together.
    int photonUpdates() const { return photonUpdates_; }
    int64_t photonSteps() const { return photonSteps_; }
    // Photons that entered the box in the last trace (0 before any).
    int64_t lastPhotonsTraced() const;
    // The last trace's photons cut (step cap or stop rule) and rounds of the march with photons
    // (render/photon_tracing.h); on the GPU, small read-backs.
    int64_t lastPhotonsCut() const;
    int lastPhotonRounds() const;
    // The smoothed photon volumes of the last trace (the GPU's read back), for tests; empty
    // when the scene has no photon lighting.
    PhotonRadianceCpu photonVolumes() const;
    // How often the environment image was read: once per change of its path.
    int environmentLoads() const;
    // Whether the GPU shaders let the texture unit filter (see useHardwareTrilinear).
    bool hardwareTrilinear() const { return hardwareTrilinear_; }

private:
    // Records what the stages that ran were computed from, and counts them.
    void commitInputs(bool gradientChanged, bool octreeChanged, bool photonsChanged,
                      bool lightsChanged, std::vector<unsigned char> refractionInputs,
                      std::vector<unsigned char> octreeKey, std::vector<unsigned char> photonKey,
                      std::vector<unsigned char> lightInputs);

    Scene scene_;
    Backend backend_;
    std::unique_ptr<GlContext> ownContext_;
    GlContext* gl_ = nullptr;  // ownContext_ or the caller's
    SceneSources sources_;
    FieldRegistry fields_;
    MeshFields meshFields_;
    std::unique_ptr<MeshVoxelizerGpu> voxelizerGpu_;
    std::map<std::string, DenseGrid> dense_;  // by field name
    RenderVolume volume_;
    std::unique_ptr<VolumeTextures> textures_;
    std::unique_ptr<ParamsBuffer> paramsBuffer_;
    std::unique_ptr<LightVolumesGpu> lightVolumesGpu_;
    std::unique_ptr<ViewPassGpu> viewPass_;
    std::unique_ptr<EnvironmentMap> environment_;
    std::vector<LightVolumeCpu> lightVolumesCpu_;
    std::unique_ptr<RefractionVolumesGpu> refractionGpu_;
    std::vector<glm::vec4> gradientCpu_;
    std::vector<glm::vec4> octreeCpu_;
    std::unique_ptr<PhotonRadianceGpu> photonsGpu_;
    PhotonRadianceCpu photonsCpu_;
    std::vector<unsigned char> gradientInputs_;  // what the ∇n volume was computed from
    std::vector<unsigned char> octreeInputs_;    // what the octree was computed from
    std::vector<unsigned char> photonInputs_;    // what the photon volumes were traced from
    std::vector<unsigned char> lightInputs_;     // what the light volumes were computed from
    std::unique_ptr<GpuStageTimer> timer_;
    int resamples_ = 0;
    int lightVolumeUpdates_ = 0;
    int gradientUpdates_ = 0;
    int photonUpdates_ = 0;
    int64_t photonSteps_ = 0;
    bool hardwareTrilinear_ = false;
    bool exactPhotonMath_ = false;
};

}  // namespace eikon
