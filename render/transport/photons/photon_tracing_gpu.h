#pragma once
// Photon tracing on the GPU (shaders/photon_trace.comp): the port of
// render/transport/photons/photon_tracing.h's CPU twin, running the same shared functions and the
// same fixed-point sums, so that download() returns the CPU twin's PhotonResultCpu for the same
// inputs.
#include <memory>

#include "render/transport/photons/photon_tracing.h"

namespace eikon {

class GpuStageTimer;
class ShaderProgram;
class VolumeTextures;

class PhotonTracerGpu {
public:
    // Needs a current context. exactMath: the CPU twin's rounding for dot, length, normalize, mix,
    // smoothstep and exp (bit-identical results on llvmpipe; double-precision exp, slow on most
    // hardware GPUs, which should pass false and compare with the twin within tolerances).
    explicit PhotonTracerGpu(bool exactMath = true);
    ~PhotonTracerGpu();
    PhotonTracerGpu(const PhotonTracerGpu&) = delete;
    PhotonTracerGpu& operator=(const PhotonTracerGpu&) = delete;

    // Generates and traces the photons of every light of setup (planPhotons). fields are the
    // field volumes (already uploaded), refraction the ∇n and octree volumes already computed
    // from them, and the params SSBO is already bound at EK_SSBO_VIEW_PARAMS. Reads the generated
    // photons back once (the emitted power sets the fixed-point scales before anything is
    // deposited, as in the CPU twin), then marches them in rounds with the active photons compacted
    // on the GPU (shared/photon_rounds.h) without reading anything back; the results stay on the
    // GPU until download(). With `dispersion` (refraction's red and blue ∇n volumes computed),
    // one pass per colour channel, as the CPU twin (channelPassCount). Timer stage: "photons".
    void trace(const ViewSetup& setup, VolumeTextures& fields,
               const RefractionVolumesGpu& refraction, const PhotonSettings& settings = {},
               GpuStageTimer* timer = nullptr, bool dispersion = false);

    // The last trace's results, in the CPU twin's structure and units.
    PhotonResultCpu download() const;
    // The last trace's receiver map (render/receiver_map.h; reads back its fixed-point sums).
    std::vector<glm::vec4> receiverMap() const;
    // Photon steps of the last trace (reads back one int64).
    int64_t stepsTaken() const;
    // Photons of the last trace cut at the step cap or by the stop rule (reads back one int64).
    int64_t photonsCut() const;
    // Rounds of the last trace's march that had photons (reads back one word).
    int rounds() const;
    // Photons of the last trace that entered the box (known on the host: no read-back).
    int64_t photonsTraced() const { return host_.photonsTraced; }
    // For the passes that read the deposits on the GPU
    // (render/transport/photons/photon_radiance_gpu.cpp): the SSBO (6 int64 per voxel as (low,
    // high) words, see shaders/photon_trace.comp) and its fixed-point scales.
    unsigned depositBuffer() const { return deposits_; }
    const glm::dvec4& fixedPointScale() const { return host_.fixedPointScale; }

private:
    // Step 4 for one pass: every light's photons into slots base .. base + plan.photons − 1.
    void generatePass(const PhotonPlan& plan, const PhotonSettings& settings, size_t base);
    // After the first pass's generation: reads its photons back, warns of lights that miss the
    // volume, sums the emitted power into host (in the twin's order) and sets the fixed-point
    // scales from it. Returns the photons that entered the box.
    int64_t setScales(const ViewSetup& setup, const PhotonPlan& plan, PhotonResultCpu& host);
    // Step 5 for one pass: the march in rounds of the photons in slots base .., depositing the
    // channels `channels`.
    void marchPass(const PhotonPlan& plan, const PhotonSettings& settings,
                   const PhotonResultCpu& host, int64_t traced, size_t base, glm::vec3 channels);

    std::unique_ptr<ShaderProgram> generate_;
    std::unique_ptr<ShaderProgram> trace_;
    std::unique_ptr<ShaderProgram> round_;  // between rounds (shaders/photon_round.comp)
    unsigned photons_ = 0;           // SSBO: shared::GpuPhoton per photon and pass (dispersion: 3)
    unsigned deposits_ = 0;          // SSBO: 6 int64 (low, high uint words) per voxel
    unsigned totals_ = 0;            // SSBO: 14 int64, see shaders/photon_trace.comp
    unsigned receiverDeposits_ = 0;  // SSBO: 3 int64 (low, high words) per receiver map texel
    unsigned rounds_ = 0;            // SSBO and indirect arguments: round header, 2 index lists
    unsigned extinguished_ = 0;      // SSBO: vec4 per photon and pass, its extinction so far
    size_t photonCapacity_ = 0;
    size_t voxelCapacity_ = 0;
    size_t receiverCapacity_ = 0;
    PhotonResultCpu host_;  // what the trace knows on the host: scales, emitted power, counts
    shared::GpuViewParams params_{};  // the last trace's, for the receiver map's layout
};

}  // namespace eikon
