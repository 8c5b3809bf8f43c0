#pragma once
// Light transport method "photons": Sun et al. 2008's adaptive photon tracing. N×N photons per
// light march the ray equation through the ∇n volume with steps the octree allows, deposit
// Σ flux·length and their luminance-weighted directions into fixed-point volumes, which are
// smoothed into the output contract's fluence and mean-direction volumes
// (render/transport/photons/photon_radiance.h); photons crossing a plane receiver fill its
// irradiance map.
//
// Settings: render.light_transport.photons (docs/scene-format.md#renderlight_transportphotons).
#include <memory>
#include <string>

#include "core/json_reader.h"
#include "render/light_transport.h"
#include "render/transport/photons/photon_radiance.h"

namespace eikon {

struct PhotonTransportSettings {
    PhotonSettings trace;  // per side, steps, threshold, rounds, stop rule (defaults there)
    // Optical depth by which extinction may vary across an octree node that photons cross in one
    // step (OctreeSettings::kappaTolerance); 0: it does not limit steps, as in Sun et al. 0.1
    // (BENCHMARKS.md): 65x less image error than 0 on the glass sphere in fog, for 2.4x the
    // photon steps.
    float kappaTolerance = 0.1f;
    // The longest step where n varies a little (OctreeSettings::stepLimitVoxels, the paper's user
    // limit); where it is flat within ε steps are unlimited, and near strong variation they are
    // min_step_voxels.
    float maxStepVoxels = 8.0f;
    // The section's file and JSON pointer, for the memory check's message; empty: the scene's
    // render.light_transport.
    std::string where;
};

// The settings section; null: all defaults. Throws eikon::Error at the offending key.
PhotonTransportSettings readPhotonTransportSettings(const json::Value* section);

class PhotonTransport final : public LightTransport {
public:
    PhotonTransport(PhotonTransportSettings settings, TransportDevice device);
    ~PhotonTransport() override;

    std::string name() const override { return "photons"; }
    TransportNeeds needs() const override;
    bool drawsLightDiscs() const override { return true; }
    void configure(const Scene& scene, ViewSetup& setup) override;
    std::vector<unsigned char> cacheKey(
        const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids) const override;
    void runCpu(const TransportInputsCpu& in) override;
    void runGpu(const TransportInputsGpu& in) override;
    TransportOutputCpu outputCpu() const override;
    void bindGpu() const override;
    TransportStats stats() const override;
    std::vector<std::string> stages() const override { return {"photons", "smooth"}; }
    std::optional<EnergyBalance> energy() const override;
    // Half the photons per side (a quarter of the photons, at least 16 per side): the fluence
    // keeps its expected value, with twice the noise.
    std::string previewPatch() const override;

    // The trace's settings with the scene's seed. The jitter depends on the seed, not on the
    // frame: a light and medium that stay still keep their photons, so noise does not flicker in
    // an animation, and a frame change alone traces nothing.
    PhotonSettings traceSettings() const;
    // The smoothed volumes and totals of the last run (a GPU run's read back), for tests.
    PhotonVolumes volumes() const;

private:
    PhotonTransportSettings settings_;
    TransportDevice device_;
    uint32_t seed_ = 0;  // the scene's render.seed, from configure()
    PhotonVolumes cpu_;
    std::unique_ptr<PhotonRadianceGpu> gpu_;
};

}  // namespace eikon
