#pragma once
// How light reaches the medium: the interface every light-transport method implements (Sun et
// al.'s photons, straight light volumes, and the methods to come), and the one output contract
// the viewing pass reads, whichever method produced it.
//
// A method is one folder under render/transport/ and one line in
// render/light_transport_registry.cpp. It parses its own settings section of the scene
// (render.light_transport.<name>), says which shared stages it needs before it runs (∇n, the
// octree), writes its part of the view parameters, keys its cache on its own settings, and runs on
// the CPU twin or on the GPU. The frame renderer reruns it only when its key changes; the view pass
// never asks which method ran.
//
// The output contract (shaders/shared/view_march.h reads it):
//  - lights lit straight (lightInFluence(params, l) false) come with a transmittance toward
//    the light, from a per-light volume (texture unit EK_UNIT_LIGHT_TRANSMITTANCE on the GPU,
//    outputCpu().lightTransmittance on the CPU) or marched at each view sample
//    (shadowMode(params) == EK_SHADOWS_MARCHED);
//  - lights lit through the fluence (lightInFluence, readsFluence) come summed in one
//    fluence volume (rgb: Σ flux·length per voxel) and one mean-direction volume (xyz: the
//    luminance-weighted sum of the directions light travels), units EK_UNIT_FLUENCE and
//    EK_UNIT_FLUENCE_DIRECTION on the GPU;
//  - receivers read their irradiance map (SSBO EK_SSBO_RECEIVER_MAP; every binding is named in
//    shaders/shared/bindings.h) for the lights in the fluence.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/dense_grid.h"
#include "core/scene.h"
#include "render/image.h"
#include "render/refraction_volume.h"
#include "render/view_params.h"

namespace eikon {

class GpuStageTimer;
class VolumeTextures;

// What a method reads besides the field volumes. The frame renderer computes these shared stages
// before the method runs, and only when their own inputs changed.
struct TransportNeeds {
    bool gradient = false;  // the ∇n volume (xyz = ∇n, w = n)
    bool octree = false;    // the octree over n (and over κ with octree.kappaTolerance > 0)
    OctreeSettings octreeSettings;
    // Under dispersion (dispersesView) a method that reads ∇n bends each colour channel's light
    // with that channel's own n: it reads TransportInputsCpu::channelGradients, or the GPU's
    // (TransportInputsGpu::dispersion), which the frame renderer computes for such scenes.
};

// Counters of the last run, for --stats and tests; zero where a method has no such thing.
struct TransportStats {
    int64_t steps = 0;            // particle steps of the last run
    int64_t particlesTraced = 0;  // particles (photons) that entered the volume
    int64_t particlesCut = 0;     // particles cut before they finished (step cap, stop rule)
    int rounds = 0;               // rounds of the march that had particles to march
    // Methods that refine their particles (wavefront patches): splits done, splits refused by the
    // patch budget, particles ended where they tore (still too wide at the level cap), and
    // particles removed at caustics.
    int64_t particlesSplit = 0;
    int64_t splitsRefused = 0;
    int64_t particlesTorn = 0;
    int64_t particlesRemoved = 0;
    // Methods that view as they light (viewsInterleaved): view ray steps taken, and samples of
    // rays that turned back against the sweep, read from the nearest light plane still held.
    int64_t viewSteps = 0;
    int64_t viewSamplesBehind = 0;
};

// Where the light of the last run went, per colour channel in power, for methods that account
// for it (photons do; light volumes store transmittance only). Balanced when emitted equals the
// sum of the others (removed is part of dropped).
struct EnergyBalance {
    glm::dvec3 emitted{0.0};       // entered the volume
    glm::dvec3 extinguished{0.0};  // absorbed or scattered out on the way
    glm::dvec3 escaped{0.0};       // left through the volume's faces
    glm::dvec3 dropped{0.0};       // in particles removed below a threshold or cut
    glm::dvec3 received{0.0};      // stopped on a receiver
    glm::dvec3 removed{0.0};       // of dropped: removed at caustics (the wavefront's rule)
    glm::dvec3 reflected{0.0};     // reflected at surfaces (Fresnel) and not followed

    // Where the emitted power is known to have gone: equal to emitted when balanced.
    glm::dvec3 accounted() const { return extinguished + escaped + dropped + received + reflected; }
};

// The output contract on the CPU: views into the method's own storage, valid until its next run.
struct TransportOutputCpu {
    std::vector<const glm::vec4*> lightTransmittance;  // per light lit straight; empty if none
    const glm::vec4* fluence = nullptr;                // when readsFluence(params)
    const glm::vec4* direction = nullptr;
    const glm::vec4* receiverMap = nullptr;  // receiverMapTexels(params) texels
    size_t fluenceVoxels = 0;                // voxels of fluence and direction
    size_t receiverTexels = 0;               // texels of receiverMap
};

// The contract's view of a method's fluence, mean-direction and receiver-map vectors (empty when
// nothing was computed), for methods that keep them as std::vector.
TransportOutputCpu fluenceOutputOf(const std::vector<glm::vec4>& fluence,
                                   const std::vector<glm::vec4>& direction,
                                   const std::vector<glm::vec4>& receiverMap);

// Where and how a method's GPU run computes (chosen once per renderer).
struct TransportDevice {
    bool gpu = false;
    bool hardwareTrilinear = false;  // the texture unit filters (shaders/shared/sampling.h)
    bool exactMath = false;          // the CPU twin's rounding (bit-identical on llvmpipe)
};

// One frame's inputs to a CPU run.
struct TransportInputsCpu {
    const ViewSetup& setup;
    const std::vector<const DenseGrid*>& slotGrids;
    const RefractionVolumeCpu& gradient;  // empty unless needs().gradient
    const RefractionVolumeCpu& octree;    // empty unless needs().octree
    GpuStageTimer* timer;                 // the method times its own stages
    // Under dispersion (dispersesView(setup)): the red and blue channels' ∇n volumes, `gradient`
    // being the green one's; null otherwise.
    const ChannelGradientsCpu* channelGradients = nullptr;
};

// One frame's inputs to a GPU run: the field textures are uploaded, the params SSBO bound at
// EK_SSBO_VIEW_PARAMS, and the ∇n and octree volumes computed when needs() asked for them.
struct TransportInputsGpu {
    const ViewSetup& setup;
    VolumeTextures& fields;
    const RefractionVolumesGpu& refraction;
    GpuStageTimer* timer;
    // Under dispersion (dispersesView(setup)): refraction holds the red and blue channels' ∇n
    // volumes too (RefractionVolumesGpu::channelGradientTexture).
    bool dispersion = false;
};

class LightTransport {
public:
    virtual ~LightTransport() = default;

    // The registered name ("photons", "light_volumes").
    virtual std::string name() const = 0;
    // The shared stages the run reads.
    virtual TransportNeeds needs() const = 0;
    // Whether it draws a directional light's disc (LightSpec::angularDiameterDeg): the registry
    // refuses a scene with one for a method that does not (requireLightsWithoutDisc).
    virtual bool drawsLightDiscs() const { return false; }
    // Writes the method's part of the view parameters (the setters in shaders/shared/gpu_types.h):
    // which lights come through the fluence (setLightInFluence, setReadsFluence) and how the view
    // finds transmittance (setShadowMode, setShadowStep); keeps what else of the scene its run
    // reads (the seed).
    virtual void configure(const Scene& scene, ViewSetup& setup) = 0;
    // The bytes the output depends on, for the setup configure() wrote: equal keys, equal output,
    // so the frame renderer skips the run. Empty when there is nothing to compute this frame
    // (nothing scatters and no receiver shows the light, or light is marched at each sample).
    virtual std::vector<unsigned char> cacheKey(
        const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids) const = 0;

    virtual void runCpu(const TransportInputsCpu& in) = 0;
    virtual void runGpu(const TransportInputsGpu& in) = 0;
    // The output of the last run (CPU runs; a GPU run's output stays on the GPU).
    virtual TransportOutputCpu outputCpu() const = 0;
    // Binds the output of the last GPU run to the contract's units and bindings.
    virtual void bindGpu() const = 0;
    virtual TransportStats stats() const = 0;
    // The timer stages its runs report (GpuStageTimer names), for benches that time a method.
    virtual std::vector<std::string> stages() const = 0;
    // The last run's energy accounting; none for a method that keeps none.
    virtual std::optional<EnergyBalance> energy() const { return std::nullopt; }
    // A merge patch for render.light_transport (as patchLightTransport takes it) that makes a
    // lighter run of this method, with these settings, for a preview picture: the viewer's, while
    // a light, a material or the frame changes (FrameRenderer::setPreview). Empty: nothing
    // lighter; the preview runs the method as set.
    virtual std::string previewPatch() const { return {}; }
    // Whether, for the setup configure() wrote last, the method renders the frame's image itself
    // in one pass with its light (the plane sweep's interleaved view): the frame renderer then
    // calls runWithViewCpu (runWithViewGpu) every frame instead of runCpu (runGpu) and the view
    // pass.
    virtual bool viewsInterleaved() const { return false; }
    // Lights and views in one pass; stats() as after runCpu. Only where viewsInterleaved().
    // `environment`: as renderViewCpu's.
    virtual Image runWithViewCpu(const TransportInputsCpu& in, const Image* environment);
    // The same on the GPU; `environmentTexture` as ViewPassGpu::render's.
    virtual Image runWithViewGpu(const TransportInputsGpu& in, unsigned environmentTexture);
};

// The fluence rate (rgb, power per area) at every voxel centre, x fastest, that the output
// contract of a CPU run describes: the fluence volume / voxel volume for the lights in it, plus,
// for each light lit straight, its unshadowed irradiance times the transmittance volume. Throws
// eikon::Error when a straight light's transmittance is marched at view time (no volume to read).
// What `eikon bench methods` measures every method by.
std::vector<glm::vec3> fluenceRateCpu(const ViewSetup& setup, const TransportOutputCpu& out);

// Whether the viewing pass reads a per-light transmittance volume: some light lit straight, some
// scattering material or receiver, and shadows from volumes (not marched at each sample).
bool viewReadsLightTransmittance(const ViewSetup& setup);

// Times one stage of a run, begin to end of scope (a null timer times nothing).
class StageScope {
public:
    StageScope(GpuStageTimer* timer, const char* stage);
    ~StageScope();
    StageScope(const StageScope&) = delete;
    StageScope& operator=(const StageScope&) = delete;

private:
    GpuStageTimer* timer_;
};

// The part of every method's key that any output depends on: the view parameters without the
// camera, the image, the environment and the receivers' shading, and the versions of the field
// grids. A method appends what else its output depends on (its settings, the receivers' maps).
std::vector<unsigned char> transportInputsKey(const ViewSetup& setup,
                                              const std::vector<const DenseGrid*>& slotGrids);

// For methods whose particles stop on receivers and fill their maps: the receivers' planes and
// map layouts, appended to a key.
void appendReceiverMapsKey(const ViewSetup& setup, std::vector<unsigned char>& key);

// What particle methods (photons, wavefronts) light: every light through the fluence, when some
// material scatters light toward the camera or a receiver shows it (setLightInFluence,
// setReadsFluence). Returns false, and sets nothing, when nothing would show their light.
bool lightAllThroughFluence(const Scene& scene, ViewSetup& setup);

// Throws eikon::Error at the first light with a disc (angular_diameter_deg > 0), for a method
// that draws every light from a single direction: its shadows would be sharp where the scene
// asks for soft ones.
void requireLightsWithoutDisc(const Scene& scene, const std::string& method);

}  // namespace eikon
