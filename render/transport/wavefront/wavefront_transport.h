#pragma once
// Light transport method "wavefront": Ihrke et al. 2007's eikonal wavefront tracing. Each light's
// wavefront, a mesh of patches with four particles each, advances in equal optical time steps
// through the ∇n volume; patches split where they grow past a voxel and carry power, so the
// intensity law E = Φ/A holds without noise; their centroids' chords fill the output contract's
// fluence and mean-direction volumes (render/transport/wavefront/wavefront_tracing.h).
//
// Settings: render.light_transport.wavefront (docs/scene-format.md#renderlight_transportwavefront).
// On the GPU (wavefront_tracing_gpu.h) and the CPU twin, in the same rounds.
#include <memory>
#include <string>

#include "core/json_reader.h"
#include "render/light_transport.h"
#include "render/transport/photons/photon_radiance.h"
#include "render/transport/wavefront/wavefront_tracing.h"

namespace eikon {

class DepositVolumesGpu;
class WavefrontTracerGpu;

struct WavefrontTransportSettings {
    WavefrontSettings trace;
    std::string where;  // the section's file and JSON pointer, for messages
};

// The settings section; null: all defaults. Throws eikon::Error at the offending key.
WavefrontTransportSettings readWavefrontTransportSettings(const json::Value* section);

// The patch integrator names of the settings ("euler", "midpoint", "rk4").
const std::vector<std::string>& wavefrontIntegratorNames();

class WavefrontTransport final : public LightTransport {
public:
    WavefrontTransport(WavefrontTransportSettings settings, TransportDevice device);
    ~WavefrontTransport() override;

    std::string name() const override { return "wavefront"; }
    TransportNeeds needs() const override;
    void configure(const Scene& scene, ViewSetup& setup) override;
    std::vector<unsigned char> cacheKey(
        const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids) const override;
    void runCpu(const TransportInputsCpu& in) override;
    void runGpu(const TransportInputsGpu& in) override;
    TransportOutputCpu outputCpu() const override;
    void bindGpu() const override;
    TransportStats stats() const override { return stats_; }
    std::vector<std::string> stages() const override { return {"wavefront", "smooth"}; }
    std::optional<EnergyBalance> energy() const override;
    // Patches split at twice the width (the "coarse" bench setting's rule, relative to these
    // settings): about a quarter of the patches where the wavefront spreads.
    std::string previewPatch() const override;

    // The smoothed volumes and totals of the last run (a GPU run's read back), for tests.
    PhotonVolumes volumes() const;

private:
    // The counts and energy account of a trace, for stats() and energy().
    void setResult(const WavefrontResultCpu& traced);

    WavefrontTransportSettings settings_;
    TransportDevice device_;
    PhotonVolumes cpu_;  // a GPU run: its counts and totals alone
    TransportStats stats_;
    std::unique_ptr<WavefrontTracerGpu> gpu_;
    std::unique_ptr<DepositVolumesGpu> volumesGpu_;
};

}  // namespace eikon
