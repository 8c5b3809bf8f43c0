#pragma once
// Light transport method "light_volumes": single scattering of straight light. Each light's
// transmittance exp(−∫κ) toward the light is computed once per change of lights or extinction in
// a volume at the render resolution (render/transport/light_volumes/light_volume.h), marched from
// every voxel centre or, for directional lights, swept slice by slice; or, as the reference,
// marched toward the light from every view sample (like OpenVDB's vdb_render), with no volume at
// all. Exact and cheap, but blind to refraction: light does not bend on its way in.
//
// Settings: render.light_transport.light_volumes (docs/scene-format.md).
#include <memory>

#include "core/json_reader.h"
#include "render/light_transport.h"
#include "render/transport/light_volumes/light_volume.h"

namespace eikon {

// Where the viewing pass gets a light's transmittance (EK_SHADOWS_* in
// shaders/shared/gpu_types.h).
enum class ShadowMode { Volume, Swept, Marched };

struct LightVolumeSettings {
    // Swept is the fastest, and the most accurate at default steps on smoke (BENCHMARKS.md).
    ShadowMode shadows = ShadowMode::Swept;
    float shadowStepVoxels = 3.0f;  // step toward the light, in voxels of the smallest edge
};

// The settings section; null: all defaults. Throws eikon::Error at the offending key.
LightVolumeSettings readLightVolumeSettings(const json::Value* section);

class LightVolumeTransport final : public LightTransport {
public:
    LightVolumeTransport(LightVolumeSettings settings, TransportDevice device);
    ~LightVolumeTransport() override;

    std::string name() const override { return "light_volumes"; }
    TransportNeeds needs() const override { return {}; }
    bool drawsLightDiscs() const override { return true; }  // 16 marches a disc
    void configure(const Scene& scene, ViewSetup& setup) override;
    std::vector<unsigned char> cacheKey(
        const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids) const override;
    void runCpu(const TransportInputsCpu& in) override;
    void runGpu(const TransportInputsGpu& in) override;
    TransportOutputCpu outputCpu() const override;
    void bindGpu() const override;
    TransportStats stats() const override { return {}; }
    std::vector<std::string> stages() const override { return {"light"}; }

    // Light l's volume of the last GPU run, read back (tests compare it with the CPU twin).
    LightVolumeCpu downloadGpu(int light) const;

private:
    LightVolumeSettings settings_;
    TransportDevice device_;
    std::vector<LightVolumeCpu> cpu_;
    std::unique_ptr<LightVolumesGpu> gpu_;
};

}  // namespace eikon
