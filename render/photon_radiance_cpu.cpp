#include "render/photon_radiance.h"
#include "render/smoothing.h"

namespace eikon {

PhotonSettings photonSettingsFor(const Scene& scene) {
    PhotonSettings s;
    s.photonsPerSide = scene.render.photons.perSide;
    s.minStepVoxels = scene.render.photons.minStepVoxels;
    s.fluxThreshold = scene.render.photons.fluxThreshold;
    s.stopFraction = scene.render.photons.stopFraction;
    s.stepsPerRound = scene.render.photons.stepsPerRound;
    s.seed = scene.render.seed;
    s.frame = 0;  // the same jitter every frame: a still light's photons do not flicker
    return s;
}

OctreeSettings octreeSettingsFor(const Scene& scene) {
    OctreeSettings s;
    s.kappaTolerance = scene.render.photons.kappaTolerance;
    return s;
}

PhotonRadianceCpu computePhotonRadianceCpu(const ViewSetup& setup,
                                           const std::vector<const DenseGrid*>& slotGrids,
                                           const RefractionVolumeCpu& gradient,
                                           const RefractionVolumeCpu& octree,
                                           const PhotonSettings& settings) {
    PhotonResultCpu traced = traceLightPhotonsCpu(setup, slotGrids, gradient, octree, settings);
    PhotonRadianceCpu out;
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

}  // namespace eikon
