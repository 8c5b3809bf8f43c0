#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "render/gpu_timer.h"
#include "render/gpu_transfer.h"
#include "render/receiver_map.h"
#include "render/shader_program.h"
#include "render/transport/channel_passes.h"
#include "render/transport/deposit_volumes_gpu.h"
#include "render/transport/fixed_point.h"
#include "render/transport/photons/lights_missing_volume.h"
#include "render/transport/photons/photon_tracing_gpu.h"
#include "render/volume_kernels_cpu.h"
#include "render/volume_textures.h"
#include "shaders/shared/bindings.h"
#include "shaders/shared/photon_rounds.h"

namespace eikon {

namespace {

constexpr int kLocalSize = EK_ROUND_GROUP;
constexpr int kDepositChannels = 6;  // r, g, b, weighted direction x, y, z
// escaped rgb, extinguished rgb, dropped rgb, steps, cut, received rgb
constexpr int kTotalsCount = 14;

// Runs `program` over photons [base, base + count) of its range in dispatches the driver must
// accept (GL promises 65535 work groups in x, fewer than a cube layout of N = 1024 needs): each
// dispatch covers photonCount photons from photonFirst.
void dispatchPhotons(const ShaderProgram& program, size_t count, size_t base = 0) {
    const size_t perDispatch = size_t(65535) * kLocalSize;
    for (size_t first = 0; first < count; first += perDispatch) {
        const size_t n = std::min(count - first, perDispatch);
        program.setInt("photonFirst", int(base + first));
        program.setInt("photonCount", int(n));
        glDispatchCompute(GLuint((n + kLocalSize - 1) / kLocalSize), 1, 1);
    }
}

}  // namespace

PhotonTracerGpu::PhotonTracerGpu(bool exactMath) {
    std::vector<std::string> defines;
    if (exactMath) defines.push_back("EK_EXACT_MATH");
    std::vector<std::string> generateDefines = defines;
    generateDefines.push_back("EK_PHOTON_GENERATE");
    generate_ = std::make_unique<ShaderProgram>(
        ShaderProgram::compute("photon_trace.comp", generateDefines));
    trace_ = std::make_unique<ShaderProgram>(ShaderProgram::compute("photon_trace.comp", defines));
    round_ = std::make_unique<ShaderProgram>(ShaderProgram::compute("photon_round.comp"));
    resizeStorageBuffer(totals_, kTotalsCount * 2 * sizeof(GLuint));
}

PhotonTracerGpu::~PhotonTracerGpu() {
    for (GLuint* b :
         {&photons_, &deposits_, &totals_, &receiverDeposits_, &rounds_, &extinguished_})
        if (*b) glDeleteBuffers(1, b);
}

void PhotonTracerGpu::trace(const ViewSetup& setup, VolumeTextures& fields,
                            const RefractionVolumesGpu& refraction, const PhotonSettings& settings,
                            GpuStageTimer* timer, bool dispersion) {
    // The same derived settings as traceLightPhotonsCpu.
    PhotonResultCpu host;
    const PhotonPlan plan = planPhotons(setup, settings);
    host.resolution = plan.resolution;
    const size_t voxels = plan.voxels;
    const size_t photonCount = plan.photons;
    // Under dispersion one pass per channel, each through its channel's ∇n volume.
    const std::vector<unsigned> passGradients =
        channelPassGradientsGpu(refraction, dispersion, "photon tracing");
    const int passes = int(passGradients.size());
    // Every pass's photons keep their slots (download() returns them all, as the twin does); the
    // round lists hold one pass's indices at a time.
    const size_t slots = photonCount * size_t(passes);
    if (slots > photonCapacity_ || !photons_) {
        resizeStorageBuffer(photons_, slots * sizeof(shared::GpuPhoton));
        resizeStorageBuffer(rounds_, (EK_ROUND_HEADER + 2 * photonCount * passes) * sizeof(GLuint));
        resizeStorageBuffer(extinguished_, slots * sizeof(glm::vec4));
        photonCapacity_ = slots;
    }
    if (voxels > voxelCapacity_ || !deposits_) {
        resizeStorageBuffer(deposits_, voxels * kDepositChannels * 2 * sizeof(GLuint));
        voxelCapacity_ = voxels;
    }
    const size_t receiverTexels = receiverMapTexels(setup.params);
    if (receiverTexels > receiverCapacity_ || !receiverDeposits_) {
        resizeStorageBuffer(receiverDeposits_, receiverTexels * 3 * 2 * sizeof(GLuint));
        receiverCapacity_ = receiverTexels;
    }
    if (glGetError() != GL_NO_ERROR)
        throw Error("photon tracing", "the driver refused the buffers for " +
                                          std::to_string(photonCount) + " photons and " +
                                          std::to_string(voxels) + " voxels");

    if (timer) timer->begin("photons");
    fields.bind();
    glActiveTexture(GL_TEXTURE0 + EK_UNIT_OCTREE);
    glBindTexture(GL_TEXTURE_3D, refraction.octreeTexture());
    glActiveTexture(GL_TEXTURE0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_PHOTONS, photons_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_PHOTON_DEPOSITS, deposits_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_PHOTON_TOTALS, totals_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_RECEIVER_DEPOSITS, receiverDeposits_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_PHOTON_ROUNDS, rounds_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_PHOTON_EXTINGUISHED, extinguished_);
    clearStorageBuffer(deposits_);
    clearStorageBuffer(totals_);
    clearStorageBuffer(receiverDeposits_);
    clearStorageBuffer(rounds_);  // EK_ROUND_MARCHED counts over every pass

    int64_t tracedPerPass = 0;
    for (int pass = 0; pass < passes; ++pass) {
        glActiveTexture(GL_TEXTURE0 + EK_UNIT_GRADIENT);
        glBindTexture(GL_TEXTURE_3D, passGradients[pass]);
        glActiveTexture(GL_TEXTURE0);
        const size_t base = size_t(pass) * photonCount;
        generatePass(plan, settings, base);
        if (pass == 0) {
            tracedPerPass = setScales(setup, plan, host);
            host.photonsTraced = tracedPerPass * passes;
        }
        marchPass(plan, settings, host, tracedPerPass, base, channelPassMask(pass, passes));
    }
    if (timer) timer->end();

    host.photons.resize(slots);  // filled by download()
    host_ = std::move(host);
    params_ = setup.params;
}

void PhotonTracerGpu::generatePass(const PhotonPlan& plan, const PhotonSettings& settings,
                                   size_t base) {
    generate_->use();
    generate_->setInt("photonsPerSide", plan.side);
    generate_->setUint("seed", settings.seed);
    generate_->setUint("frame", glm::uint(settings.frame));
    generate_->setFloat("fluxThreshold", settings.fluxThreshold);
    for (const PhotonLightPlan& light : plan.lights) {
        generate_->setInt("lightIndex", light.light);
        generate_->setInt("lightGrid", light.grid);
        generate_->setInt("photonOffset", int(base + light.first));
        dispatchPhotons(*generate_, light.count);
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

int64_t PhotonTracerGpu::setScales(const ViewSetup& setup, const PhotonPlan& plan,
                                   PhotonResultCpu& host) {
    // The emitted power sets the scales before anything is deposited; it is summed here in the
    // CPU twin's order (index order, in double), which a GPU reduction would not reproduce.
    const std::vector<shared::GpuPhoton> started =
        readStorageArray<shared::GpuPhoton>(photons_, plan.photons);
    warnLightsMissingVolume(setup, plan.lights, [&](size_t i) {
        return int(started[i].position.w) == EK_PHOTON_ACTIVE;
    });
    int64_t traced = 0;
    for (const shared::GpuPhoton& p : started) {
        if (int(p.position.w) != EK_PHOTON_ACTIVE) continue;
        host.totals.emitted += glm::dvec3(glm::vec3(p.flux));
        ++traced;
    }
    shared::VolumeAccessCpu volume{setup.params};  // for the shared volumeVoxelSize()
    const glm::vec3 h = volume.volumeVoxelSize();
    const double smallestVoxel = double(std::min({h.x, h.y, h.z}));
    const glm::dvec3& emitted = host.totals.emitted;
    host.fixedPointScale = glm::dvec4(fixedPointScaleFor(emitted.x, smallestVoxel),
                                      fixedPointScaleFor(emitted.y, smallestVoxel),
                                      fixedPointScaleFor(emitted.z, smallestVoxel),
                                      fixedPointScaleFor(rec709Luminance(emitted), smallestVoxel));
    return traced;
}

void PhotonTracerGpu::marchPass(const PhotonPlan& plan, const PhotonSettings& settings,
                                const PhotonResultCpu& host, int64_t traced, size_t base,
                                glm::vec3 channels) {
    // The march in rounds (PhotonSettings::stepsPerRound). Round 0 covers every photon of the
    // pass by a direct dispatch; each later one only the photons the round before appended to
    // its list, by an indirect dispatch whose arguments photon_round.comp wrote (shared/
    // photon_rounds.h). The header starts with round 0's count, the photons traced, so that it
    // counts as a round with photons, as in the CPU twin; EK_ROUND_MARCHED is kept from the
    // passes before.
    GLuint header[EK_ROUND_MARCHED] = {};
    header[EK_ROUND_ARGS + 1] = header[EK_ROUND_ARGS + 2] = 1;
    header[EK_ROUND_COUNT] = GLuint(traced);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, rounds_);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(header), header);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    const glm::dvec3& emitted = host.totals.emitted;
    const glm::dvec3 totalScale(fixedPointScaleFor(emitted.x, 1.0),
                                fixedPointScaleFor(emitted.y, 1.0),
                                fixedPointScaleFor(emitted.z, 1.0));
    trace_->use();
    trace_->setFloat("minStep", plan.minStep);
    trace_->setInt("integrator", static_cast<int>(settings.integrator));
    trace_->setInt("listCapacity", int(plan.photons));
    glUniform3f(trace_->uniformLocation("photonChannels"), channels.x, channels.y, channels.z);
    const glm::dvec4& s = host.fixedPointScale;
    glUniform4d(trace_->uniformLocation("depositScale"), s.x, s.y, s.z, s.w);
    glUniform3d(trace_->uniformLocation("totalScale"), totalScale.x, totalScale.y, totalScale.z);
    round_->use();
    round_->setUint("stopCount", GLuint(photonStopCount(plan, traced)));
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, rounds_);
    for (int round = 0; round < plan.rounds && traced > 0; ++round) {
        const int listIn = round & 1;
        trace_->use();
        trace_->setInt("roundSteps", photonRoundSteps(plan, round));
        trace_->setInt("lastRound", round == plan.rounds - 1);
        trace_->setInt("fromList", round > 0);
        trace_->setInt("listIn", listIn);
        if (round == 0) {
            dispatchPhotons(*trace_, plan.photons, base);
        } else {
            glDispatchComputeIndirect(0);
        }
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        round_->use();
        round_->setInt("listIn", listIn);
        glDispatchCompute(1, 1, 1);
        glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                        GL_BUFFER_UPDATE_BARRIER_BIT);
        // No read-back to end the loop early: rounds after the last photon ended dispatch zero
        // groups. Reading the count back after rounds 1, 2, 4, 8, ... did not measurably pay on
        // llvmpipe (BENCHMARKS.md, photon rounds), so the host never waits on the march.
    }
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

std::vector<glm::vec4> PhotonTracerGpu::receiverMap() const {
    return readFixedReceiverMap(receiverDeposits_, params_, host_.totals.emitted);
}

int64_t PhotonTracerGpu::stepsTaken() const {
    return joinFixedWords(readStorageWords(totals_, 18, 2).data());
}

int64_t PhotonTracerGpu::photonsCut() const {
    return joinFixedWords(readStorageWords(totals_, 20, 2).data());
}

int PhotonTracerGpu::rounds() const {
    return int(readStorageWords(rounds_, EK_ROUND_MARCHED, 1)[0]);
}

PhotonResultCpu PhotonTracerGpu::download() const {
    PhotonResultCpu r = host_;
    r.photons = readStorageArray<shared::GpuPhoton>(photons_, r.photons.size());
    const std::vector<GLuint> totals = readStorageArray<GLuint>(totals_, kTotalsCount * 2);
    const glm::dvec4& scale = r.fixedPointScale;
    const glm::dvec3 totalScale(fixedPointScaleFor(r.totals.emitted.x, 1.0),
                                fixedPointScaleFor(r.totals.emitted.y, 1.0),
                                fixedPointScaleFor(r.totals.emitted.z, 1.0));
    for (int c = 0; c < 3; ++c) {
        r.totals.escaped[c] = fromFixedPoint(joinFixedWords(&totals[2 * c]), totalScale[c]);
        r.totals.extinguished[c] =
            fromFixedPoint(joinFixedWords(&totals[6 + 2 * c]), totalScale[c]);
        r.totals.dropped[c] = fromFixedPoint(joinFixedWords(&totals[12 + 2 * c]), totalScale[c]);
    }
    r.steps = joinFixedWords(&totals[18]);
    r.photonsCut = joinFixedWords(&totals[20]);
    for (int c = 0; c < 3; ++c)
        r.totals.received[c] = fromFixedPoint(joinFixedWords(&totals[22 + 2 * c]), totalScale[c]);
    r.receiverMap = receiverMap();
    r.rounds = rounds();

    readFixedDeposits(deposits_, r.resolution, scale, r.radiance, r.direction);
    return r;
}

}  // namespace eikon
