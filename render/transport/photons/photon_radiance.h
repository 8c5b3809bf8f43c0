#pragma once
// The photon radiance stage (Sun et al. 2008 steps 4-6): photons traced from the lights along
// curved paths (render/transport/photons/photon_tracing.h), their fixed-point deposits turned into
// float volumes, both smoothed (render/smoothing.h). The viewing pass reads the result through
// EK_FLUENCE_SLOT and EK_FLUENCE_DIRECTION_SLOT (shaders/shared/view_march.h).
//
// The light-transport method "photons" (render/transport/photons/) runs it; the frame renderer
// reruns it only when lights, extinction, n, the volume or the photon settings change: a camera
// move reuses the volumes and traces nothing.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec4.hpp>

#include "core/dense_grid.h"
#include "core/scene.h"
#include "render/light_transport.h"
#include "render/refraction_volume.h"
#include "render/transport/photons/photon_tracing.h"
#include "render/view_params.h"

namespace eikon {

class DepositVolumesGpu;
class GpuStageTimer;
class PhotonTracerGpu;
class VolumeTextures;

// The smoothed photon volumes, the receiver map and the trace's totals: what the CPU twin computes,
// and what PhotonRadianceGpu::download reads back from a GPU run.
struct PhotonVolumes {
    std::vector<glm::vec4> radiance;     // smoothed; rgb = Σ flux·length (see photon_tracing.h)
    std::vector<glm::vec4> direction;    // smoothed; xyz = Σ luminance-weighted direction
    std::vector<glm::vec4> receiverMap;  // irradiance per receiver texel (render/receiver_map.h)
    PhotonTotals totals;
    int64_t steps = 0;          // photon steps taken by the trace
    int64_t photonsTraced = 0;  // photons that entered the box
    int64_t photonsCut = 0;     // cut at the step cap or by the stop rule (PhotonSettings)
    int rounds = 0;             // rounds of the march that had photons
};

// The output contract's view of smoothed volumes (fluence, direction, receiver map); empty when
// nothing was computed. Shared by the particle methods that fill PhotonVolumes.
TransportOutputCpu transportOutputOf(const PhotonVolumes& volumes);

// CPU twin: traceLightPhotonsCpu (one pass per colour channel with channelGradients under
// dispersion), then smoothVolumeCpu of both volumes.
PhotonVolumes computePhotonRadianceCpu(const ViewSetup& setup,
                                       const std::vector<const DenseGrid*>& slotGrids,
                                       const RefractionVolumeCpu& gradient,
                                       const RefractionVolumeCpu& octree,
                                       const PhotonSettings& settings,
                                       const ChannelGradientsCpu* channelGradients = nullptr);

class PhotonRadianceGpu {
public:
    // exactMath: see PhotonTracerGpu (bit-identical to the CPU twin on llvmpipe).
    explicit PhotonRadianceGpu(bool exactMath);
    ~PhotonRadianceGpu();
    PhotonRadianceGpu(const PhotonRadianceGpu&) = delete;
    PhotonRadianceGpu& operator=(const PhotonRadianceGpu&) = delete;

    // Traces, resolves and smooths. The field textures are uploaded, the ∇n and octree volumes
    // computed (under dispersion the red and blue ∇n volumes too), the params SSBO bound at
    // EK_SSBO_VIEW_PARAMS. Timer stages: "photons", "smooth".
    void compute(const ViewSetup& setup, VolumeTextures& fields,
                 const RefractionVolumesGpu& refraction, const PhotonSettings& settings,
                 GpuStageTimer* timer, bool dispersion = false);
    // Binds the smoothed radiance and direction volumes to texture units EK_UNIT_FLUENCE and
    // EK_UNIT_FLUENCE_DIRECTION (the output contract's fluence), and the receiver map to
    // EK_SSBO_RECEIVER_MAP (shaders/shared/bindings.h).
    void bind() const;
    // Photon steps of the last compute (read back: 8 bytes).
    int64_t lastSteps() const;
    // Photons of the last compute that entered the box (no read-back).
    int64_t lastPhotonsTraced() const;
    // Photons of the last compute that were cut, and its rounds with photons (read back).
    int64_t lastPhotonsCut() const;
    int lastRounds() const;
    // The smoothed volumes and the trace's totals, for tests.
    PhotonVolumes download() const;

private:
    std::unique_ptr<PhotonTracerGpu> tracer_;
    std::unique_ptr<DepositVolumesGpu> volumes_;
};

}  // namespace eikon
