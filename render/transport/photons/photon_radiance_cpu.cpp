#include "render/smoothing.h"
#include "render/transport/photons/photon_radiance.h"

namespace eikon {

PhotonVolumes computePhotonRadianceCpu(const ViewSetup& setup,
                                       const std::vector<const DenseGrid*>& slotGrids,
                                       const RefractionVolumeCpu& gradient,
                                       const RefractionVolumeCpu& octree,
                                       const PhotonSettings& settings,
                                       const ChannelGradientsCpu* channelGradients) {
    PhotonResultCpu traced =
        traceLightPhotonsCpu(setup, slotGrids, gradient, octree, settings, channelGradients);
    PhotonVolumes out;
    out.radiance = smoothVolumeCpu(traced.radiance, traced.resolution);
    out.direction = smoothVolumeCpu(traced.direction, traced.resolution);
    out.totals = traced.totals;
    out.receiverMap = std::move(traced.receiverMap);
    out.steps = traced.steps;
    out.photonsTraced = traced.photonsTraced;
    out.photonsCut = traced.photonsCut;
    out.rounds = traced.rounds;
    return out;
}

TransportOutputCpu transportOutputOf(const PhotonVolumes& volumes) {
    return fluenceOutputOf(volumes.radiance, volumes.direction, volumes.receiverMap);
}

}  // namespace eikon
