#pragma once
// Eikonal wavefront tracing on the GPU (shaders/wavefront_trace.comp, shaders/wavefront_scan.comp):
// the port of wavefront_tracing.h's CPU twin, running the same shared patch code in the same
// rounds (shaders/shared/wavefront_rounds.h) with the same fixed-point sums, so that download()
// returns the twin's WavefrontResultCpu (without the final patches) for the same inputs.
#include <cstdint>
#include <memory>
#include <vector>

#include "render/transport/wavefront/wavefront_tracing.h"

namespace eikon {

class GpuStageTimer;
class ParamsBuffer;
class ShaderProgram;
class VolumeTextures;

class WavefrontTracerGpu {
public:
    // Needs a current context. exactMath: the CPU twin's rounding where llvmpipe's built-ins
    // differ (PhotonTracerGpu says more).
    explicit WavefrontTracerGpu(bool exactMath = true);
    ~WavefrontTracerGpu();
    WavefrontTracerGpu(const WavefrontTracerGpu&) = delete;
    WavefrontTracerGpu& operator=(const WavefrontTracerGpu&) = delete;

    // Traces every light's wavefront (under `dispersion` one per light and colour channel, each
    // through its channel's ∇n volume, which refraction holds). The field textures are uploaded,
    // ∇n computed, the params SSBO bound at EK_SSBO_VIEW_PARAMS (bound again at the end). Reads
    // the starting patches back once (their power sets the fixed-point scales before anything is
    // deposited, as in the twin), then per round one word, the next list's length, to size the
    // lists and to stop; the lists themselves are compacted and expanded on the GPU. Timer
    // stage: "wavefront".
    void trace(const ViewSetup& setup, VolumeTextures& fields,
               const RefractionVolumesGpu& refraction, const WavefrontSettings& settings,
               GpuStageTimer* timer = nullptr, bool dispersion = false);

    // The last trace's results in the twin's structure and units (reads back the deposits and
    // totals); `patches` stays empty.
    WavefrontResultCpu download() const;
    // The last trace's counts and energy account alone (reads back the totals: 192 bytes).
    WavefrontResultCpu counts() const;
    // The last trace's receiver map (render/receiver_map.h; reads back its fixed-point sums).
    std::vector<glm::vec4> receiverMap() const;
    // The deposits (6 int64 per voxel as (low, high) words) and their scales, for
    // render/transport/deposit_volumes_gpu.h.
    unsigned depositBuffer() const { return deposits_; }
    const glm::dvec4& fixedPointScale() const { return host_.fixedPointScale; }
    // Rounds the last trace ran, and the most patches one of its lists held.
    int rounds() const { return rounds_; }
    int64_t largestList() const { return largestList_; }

private:
    // The starting patches of every pass into roots_, read back; sets host_'s emitted power,
    // scales and starting patches and fills `active` with each pass's active roots.
    void generate(const ViewSetup& setup, const WavefrontPlan& plan,
                  const WavefrontSettings& settings, const std::vector<unsigned>& gradients,
                  std::vector<std::vector<shared::GpuWavefrontEntry>>& active);
    // One pass's rounds, from its active starting patches.
    void tracePass(const WavefrontRoundSettings& round, const WavefrontSettings& settings,
                   std::vector<shared::GpuWavefrontEntry> roots);
    // wavefront_scan.comp's stages (the numbers of its EK_WAVE_STAGE_*) over a list of `count`.
    static constexpr int kStageBlocks = 0, kStageTotals = 1, kStageFirsts = 2, kStageGrants = 3;
    void scanStep(int stage, size_t count) const;
    // Exclusive prefix sums of the list's words at `source` (with `requests`, of whether each
    // outcome there asks for a split) into `target`, the blocks' at `blocks`, the total into the
    // header's word `totalWord`.
    void sumWords(size_t count, bool requests, int source, int target, int blocks,
                  int totalWord) const;
    // Binds pass k's params (the bound ones without dispersion) and ∇n volume.
    void bindPass(int k, unsigned gradient) const;
    // Makes list `which` hold at least `entries` entries (its contents are lost when it grows).
    void reserveList(int which, size_t entries);

    std::unique_ptr<ShaderProgram> generate_;
    std::unique_ptr<ShaderProgram> trace_;
    std::unique_ptr<ShaderProgram> scatter_;
    std::unique_ptr<ShaderProgram> scan_;
    std::vector<std::unique_ptr<ParamsBuffer>> passParams_;  // under dispersion, per channel
    unsigned boundParams_ = 0;    // the params SSBO bound when trace began
    unsigned roots_ = 0;          // SSBO: every pass's starting patches (GpuWavefrontEntry)
    unsigned lists_[2] = {0, 0};  // SSBOs: a round reads one list and writes the other
    size_t listCapacity_[2] = {0, 0};
    unsigned rootState_ = 0;   // SSBO: EK_WAVE_ROOT_WORDS per starting patch of the pass
    unsigned scanBuffer_ = 0;  // SSBO: outcomes and prefix sums (wavefront_scan.comp)
    size_t scanCapacity_ = 0;
    unsigned roundsBuffer_ = 0;  // SSBO: the round header and the totals
    unsigned deposits_ = 0;      // SSBO: 6 int64 (low, high words) per voxel
    unsigned receiverDeposits_ = 0;
    size_t voxelCapacity_ = 0;
    size_t receiverCapacity_ = 0;
    int rounds_ = 0;
    int64_t largestList_ = 0;
    WavefrontResultCpu host_;         // what the trace knows on the host: scales, emitted, starting
    shared::GpuViewParams params_{};  // the last trace's, for the receiver map's layout
};

}  // namespace eikon
