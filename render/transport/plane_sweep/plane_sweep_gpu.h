#pragma once
// The plane sweep on the GPU (shaders/plane_sweep.comp): the CPU twin's loop
// (plane_sweep_cpu.cpp) with each pass of a plane one dispatch over the plane's texels, the light
// buffers as 2D images that swap between planes, and the voxel-centre planes added into the
// output contract's fluence volumes, which stay on the GPU for the view pass.
// Receivers are gathered in fixed point (shaders/fixed_point.glsl) at the twin's scale; their map
// is read back, converted by the twin's code and uploaded for the view pass.
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "render/transport/plane_sweep/plane_sweep_cpu.h"

namespace eikon {

class GpuStageTimer;
class RefractionVolumesGpu;
class ShaderProgram;
class VolumeTextures;

class PlaneSweepGpu {
public:
    // exactMath: the CPU twin's rounding (exact_math.glsl), bit-identical on llvmpipe.
    explicit PlaneSweepGpu(bool exactMath);
    ~PlaneSweepGpu();
    PlaneSweepGpu(const PlaneSweepGpu&) = delete;
    PlaneSweepGpu& operator=(const PlaneSweepGpu&) = delete;

    // Sweeps every light that comes through the fluence; the fields are uploaded and the
    // params bound (TransportInputsGpu), `refraction` holds ∇n.
    void compute(const ViewSetup& setup, VolumeTextures& fields,
                 const RefractionVolumesGpu& refraction, const PlaneSweepSettings& settings,
                 GpuStageTimer* timer, bool dispersion = false);
    // The interleaved view's sweeps (plane_sweep_view.h): every light's (each channel's under
    // dispersion) across the planes of `axis` in lockstep, the twin's order, each with buffers of
    // its own; each voxel-centre plane is deposited into layer (slice % windowSlices) of
    // `window` (fluence and direction, RGBA32F volumes of res[u] × res[w] × windowSlices, zeroed
    // here first). After the swept-th voxel-centre plane, where isTurn(swept), the sweep's stage
    // closes and turn(swept) runs (the view rays' dispatches); the sweep then binds what it needs
    // again. The receiver map is complete and bound when it returns.
    void sweepWindowed(const ViewSetup& setup, VolumeTextures& fields,
                       const RefractionVolumesGpu& refraction, const PlaneSweepSettings& settings,
                       const SweepAxis& axis, const unsigned window[2], int windowSlices,
                       bool dispersion, GpuStageTimer* timer,
                       const std::function<bool(int swept)>& isTurn,
                       const std::function<void(int swept)>& turn);
    // The fluence volumes at the output contract's texture units.
    void bind() const;
    // The receiver map alone, at EK_SSBO_RECEIVER_MAP.
    void bindReceiverMap() const;
    // The last run's volumes, receiver map and counters, read back (tests, --stats).
    PlaneSweepResultCpu download() const;

    int64_t texels() const { return texels_; }
    int64_t texelSteps() const { return texelSteps_; }
    int64_t texelsLost() const;  // reads a counter back
    const PlaneSweepMemory& memory() const { return memory_; }

private:
    void allocateVolumes(glm::ivec3 res);
    void allocatePlanes(glm::ivec2 size);
    void dispatchPlane(glm::ivec2 size) const;
    // Binds the output images (fluence and direction) and the counters and uses the program;
    // `fresh`: a new run, its counters and receiver sums zeroed.
    void beginRun(const ViewSetup& setup, const PlaneSweepSettings& settings,
                  const unsigned output[2], bool fresh = true);
    // Reads the receiver sums back into the map and uploads it for the view.
    void finishRun(const ViewSetup& setup);
    // One light's sweep, plane by plane, with the gradient and the channels of its pass bound.
    void sweepPass(const ViewSetup& setup, const PlaneSweepPlan& plan,
                   const PlaneSweepSettings& settings, bool receivers);
    // Plane j of a sweep whose buffers are `planes` (light, direction twice each, traces;
    // planes[in] and planes[2 + in] the previous plane, the new one after it returns).
    void sweepPlane(const ViewSetup& setup, const PlaneSweepPlan& plan,
                    const PlaneSweepSettings& settings, int j, const unsigned planes[5], int& in,
                    bool receivers);
    // Adds plane j (just swept) to the output images at the depositSlice uniform.
    void depositPlane(const ViewSetup& setup, const PlaneSweepPlan& plan,
                      const PlaneSweepSettings& settings, int j, const unsigned planes[5], int in);
    std::vector<int64_t> downloadReceiverSums() const;

    std::unique_ptr<ShaderProgram> program_;
    unsigned volumes_[2] = {0, 0};          // fluence, mean direction
    unsigned planes_[5] = {0, 0, 0, 0, 0};  // light, direction (twice each), traces
    unsigned counters_ = 0;
    unsigned receiverSums_ = 0;       // 3 int64 (word pairs) per receiver map texel
    unsigned receiverMapBuffer_ = 0;  // the irradiance map the view pass reads
    size_t receiverSumCount_ = 0;
    double receiverScale_ = 0.0;
    std::vector<glm::vec4> receiverMap_;
    glm::ivec3 resolution_{0};
    glm::ivec2 planeSize_{0};
    int64_t texels_ = 0;
    int64_t texelSteps_ = 0;
    PlaneSweepMemory memory_;
};

}  // namespace eikon
