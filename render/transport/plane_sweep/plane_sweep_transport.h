#pragma once
// Light transport method "plane_sweep": Magnus's plane-by-plane semi-Lagrangian light
// propagation (thesis ch. 4.2). Each light's 2D buffer advances slice by slice through the
// volume; every texel looks back along its direction to the previous plane, attenuates, bends by
// Δs∇n and corrects its intensity by the ratio of footprint areas, so curved light and caustics
// come without particles and without noise (render/transport/plane_sweep/plane_sweep_cpu.h).
//
// By default the swept planes are written into the output contract's fluence volumes, so every
// view pass and `eikon bench methods` read it like the other methods. With "view": "interleaved"
// the view rays advance with the planes, as in the thesis, and no volume is kept
// (plane_sweep_view.h), on the CPU twin or on the GPU.
//
// Settings: render.light_transport.plane_sweep (docs/scene-format.md).
// Runs on the CPU twin or on the GPU (plane_sweep_gpu.h), with the same results.
#include <memory>
#include <string>

#include "core/json_reader.h"
#include "render/light_transport.h"
#include "render/transport/plane_sweep/plane_sweep_cpu.h"
#include "render/transport/plane_sweep/plane_sweep_gpu.h"
#include "render/transport/plane_sweep/plane_sweep_view.h"

namespace eikon {

struct PlaneSweepTransportSettings {
    PlaneSweepSettings sweep;
    std::string where;  // the section's file and JSON pointer, for messages
};

// The settings section; null: all defaults. Throws eikon::Error at the offending key.
PlaneSweepTransportSettings readPlaneSweepTransportSettings(const json::Value* section);

class PlaneSweepTransport final : public LightTransport {
public:
    PlaneSweepTransport(PlaneSweepTransportSettings settings, TransportDevice device);
    ~PlaneSweepTransport() override;

    std::string name() const override { return "plane_sweep"; }
    TransportNeeds needs() const override;
    bool drawsLightDiscs() const override { return true; }
    void configure(const Scene& scene, ViewSetup& setup) override;
    std::vector<unsigned char> cacheKey(
        const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids) const override;
    void runCpu(const TransportInputsCpu& in) override;
    bool viewsInterleaved() const override { return interleaved_; }
    Image runWithViewCpu(const TransportInputsCpu& in, const Image* environment) override;
    Image runWithViewGpu(const TransportInputsGpu& in, unsigned environmentTexture) override;
    void runGpu(const TransportInputsGpu& in) override;
    TransportOutputCpu outputCpu() const override;
    void bindGpu() const override;
    TransportStats stats() const override { return stats_; }
    std::vector<std::string> stages() const override { return {"plane_sweep"}; }

    // What the last run allocated.
    const PlaneSweepMemory& memory() const;
    // The last GPU run's volumes and counters, read back (tests).
    PlaneSweepResultCpu downloadGpu() const;

private:
    PlaneSweepTransportSettings settings_;
    TransportDevice device_;
    PlaneSweepResultCpu result_;
    std::unique_ptr<PlaneSweepGpu> gpu_;
    std::unique_ptr<InterleavedViewGpu> interleavedGpu_;
    PlaneSweepMemory interleavedGpuMemory_;  // the last GPU interleaved frame's
    TransportStats stats_;
    bool interleaved_ = false;  // configure's: interleaved view asked for, light to sweep
};

}  // namespace eikon
