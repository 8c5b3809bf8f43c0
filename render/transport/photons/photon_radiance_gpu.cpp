#include <epoxy/gl.h>

#include <algorithm>

#include "core/error.h"
#include "render/gpu_timer.h"
#include "render/gpu_transfer.h"
#include "render/shader_program.h"
#include "render/smoothing.h"
#include "render/transport/deposit_volumes_gpu.h"
#include "render/transport/photons/photon_radiance.h"
#include "render/transport/photons/photon_tracing_gpu.h"
#include "render/volume_textures.h"
#include "shaders/shared/bindings.h"

namespace eikon {

PhotonRadianceGpu::PhotonRadianceGpu(bool exactMath)
    : tracer_(std::make_unique<PhotonTracerGpu>(exactMath)),
      volumes_(std::make_unique<DepositVolumesGpu>()) {}

PhotonRadianceGpu::~PhotonRadianceGpu() = default;

void PhotonRadianceGpu::compute(const ViewSetup& setup, VolumeTextures& fields,
                                const RefractionVolumesGpu& refraction,
                                const PhotonSettings& settings, GpuStageTimer* timer,
                                bool dispersion) {
    const shared::GpuViewParams& p = setup.params;
    tracer_->trace(setup, fields, refraction, settings, timer, dispersion);
    volumes_->compute(glm::ivec3(p.resolution.x, p.resolution.y, p.resolution.z),
                      tracer_->depositBuffer(), tracer_->fixedPointScale(), tracer_->receiverMap(),
                      timer);
}

void PhotonRadianceGpu::bind() const {
    volumes_->bind();
}

int64_t PhotonRadianceGpu::lastPhotonsTraced() const {
    return tracer_->photonsTraced();
}

int64_t PhotonRadianceGpu::lastPhotonsCut() const {
    return tracer_->photonsCut();
}

int PhotonRadianceGpu::lastRounds() const {
    return tracer_->rounds();
}

int64_t PhotonRadianceGpu::lastSteps() const {
    return tracer_->stepsTaken();
}

PhotonVolumes PhotonRadianceGpu::download() const {
    const PhotonResultCpu traced = tracer_->download();
    PhotonVolumes out;
    out.radiance = volumes_->radiance();
    out.direction = volumes_->direction();
    out.totals = traced.totals;
    out.receiverMap = traced.receiverMap;
    out.steps = traced.steps;
    out.photonsTraced = traced.photonsTraced;
    out.photonsCut = traced.photonsCut;
    out.rounds = traced.rounds;
    return out;
}

}  // namespace eikon
