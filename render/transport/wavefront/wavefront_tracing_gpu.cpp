#include "render/transport/wavefront/wavefront_tracing_gpu.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <string>

#include "core/error.h"
#include "render/gpu_timer.h"
#include "render/gpu_transfer.h"
#include "render/params_buffer.h"
#include "render/receiver_map.h"
#include "render/shader_program.h"
#include "render/transport/channel_passes.h"
#include "render/transport/deposit_volumes_gpu.h"
#include "render/transport/fixed_point.h"
#include "render/transport/photons/lights_missing_volume.h"
#include "render/volume_kernels_cpu.h"
#include "render/volume_textures.h"
#include "shaders/shared/bindings.h"
#include "shaders/shared/wavefront_rounds.h"

namespace eikon {

namespace {

constexpr int kDepositChannels = 6;  // r, g, b, weighted direction x, y, z
constexpr size_t kRoundsWords = EK_WAVE_HEADER + EK_WAVE_TOTAL_WORDS;

// Dispatches `count` invocations of groups of `groupSize`, spread over x and y (a dispatch has
// at most 65535 groups in x; the shaders number them y-major).
void dispatchSpread(size_t count, size_t groupSize) {
    const size_t groups = (count + groupSize - 1) / groupSize;
    if (groups == 0) return;
    const size_t x = std::min<size_t>(groups, 65535);
    glDispatchCompute(GLuint(x), GLuint((groups + x - 1) / x), 1);
}

void bindStorage(GLuint binding, unsigned buffer) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer);
}

void checkBuffers(const std::string& what) {
    if (glGetError() != GL_NO_ERROR)
        throw Error("wavefront tracing", "the driver refused the buffers for " + what +
                                             "; lower max_patches or per_side");
}

}  // namespace

WavefrontTracerGpu::WavefrontTracerGpu(bool exactMath) {
    std::vector<std::string> defines;
    if (exactMath) defines.push_back("EK_EXACT_MATH");
    std::vector<std::string> generateDefines = defines;
    generateDefines.push_back("EK_WAVEFRONT_GENERATE");
    std::vector<std::string> scatterDefines = defines;
    scatterDefines.push_back("EK_WAVEFRONT_SCATTER");
    generate_ = std::make_unique<ShaderProgram>(
        ShaderProgram::compute("wavefront_trace.comp", generateDefines));
    trace_ =
        std::make_unique<ShaderProgram>(ShaderProgram::compute("wavefront_trace.comp", defines));
    scatter_ = std::make_unique<ShaderProgram>(
        ShaderProgram::compute("wavefront_trace.comp", scatterDefines));
    scan_ = std::make_unique<ShaderProgram>(ShaderProgram::compute("wavefront_scan.comp"));
    resizeStorageBuffer(roundsBuffer_, kRoundsWords * sizeof(GLuint));
}

WavefrontTracerGpu::~WavefrontTracerGpu() {
    for (unsigned* b : {&roots_, &lists_[0], &lists_[1], &scanBuffer_, &roundsBuffer_, &deposits_,
                        &receiverDeposits_, &rootState_})
        if (*b) glDeleteBuffers(1, b);
}

void WavefrontTracerGpu::bindPass(int k, unsigned gradient) const {
    if (passParams_.empty())
        bindStorage(EK_SSBO_VIEW_PARAMS, boundParams_);
    else
        passParams_[size_t(k)]->bind();
    glActiveTexture(GL_TEXTURE0 + EK_UNIT_GRADIENT);
    glBindTexture(GL_TEXTURE_3D, gradient);
    glActiveTexture(GL_TEXTURE0);
}

void WavefrontTracerGpu::reserveList(int which, size_t entries) {
    if (entries <= listCapacity_[which] && lists_[which]) return;
    // Doubling, so that a growing wavefront reallocates a few times a frame at most.
    const size_t capacity = std::max(entries, 2 * listCapacity_[which]);
    resizeStorageBuffer(lists_[which], capacity * sizeof(shared::GpuWavefrontEntry));
    checkBuffers(std::to_string(capacity) + " patches");
    listCapacity_[which] = capacity;
}

void WavefrontTracerGpu::trace(const ViewSetup& setup, VolumeTextures& fields,
                               const RefractionVolumesGpu& refraction,
                               const WavefrontSettings& settings, GpuStageTimer* timer,
                               bool dispersion) {
    const WavefrontPlan plan = planWavefronts(setup, settings);
    const std::vector<unsigned> gradients =
        channelPassGradientsGpu(refraction, dispersion, "wavefront tracing");
    const size_t voxels = size_t(plan.resolution.x) * plan.resolution.y * plan.resolution.z;
    if (voxels > voxelCapacity_ || !deposits_) {
        resizeStorageBuffer(deposits_, voxels * kDepositChannels * 2 * sizeof(GLuint));
        voxelCapacity_ = voxels;
    }
    const size_t receiverTexels = receiverMapTexels(setup.params);
    if (receiverTexels > receiverCapacity_ || !receiverDeposits_) {
        resizeStorageBuffer(receiverDeposits_, receiverTexels * 3 * 2 * sizeof(GLuint));
        receiverCapacity_ = receiverTexels;
    }
    checkBuffers(std::to_string(voxels) + " voxels");

    if (timer) timer->begin("wavefront");
    GLint bound = 0;
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, EK_SSBO_VIEW_PARAMS, &bound);
    boundParams_ = unsigned(bound);
    // Under dispersion each channel's wavefronts read that channel's params (as the twin's).
    passParams_.clear();
    if (gradients.size() > 1)
        for (int c = 0; c < 3; ++c) {
            passParams_.push_back(std::make_unique<ParamsBuffer>());
            passParams_.back()->upload(wavefrontChannelParams(setup, c));
        }
    fields.bind();
    clearStorageBuffer(deposits_);
    clearStorageBuffer(receiverDeposits_);
    clearStorageBuffer(roundsBuffer_);
    bindStorage(EK_SSBO_PHOTON_DEPOSITS, deposits_);
    bindStorage(EK_SSBO_RECEIVER_DEPOSITS, receiverDeposits_);
    bindStorage(EK_SSBO_WAVE_ROUNDS, roundsBuffer_);

    host_ = WavefrontResultCpu{};
    host_.resolution = plan.resolution;
    rounds_ = 0;
    largestList_ = 0;
    std::vector<std::vector<shared::GpuWavefrontEntry>> active;
    generate(setup, plan, settings, gradients, active);
    const WavefrontRoundSettings round = wavefrontRoundSettings(setup, settings, plan);
    for (size_t k = 0; k < gradients.size(); ++k) {
        bindPass(int(k), gradients[k]);
        tracePass(round, settings, active[k]);
    }
    bindStorage(EK_SSBO_VIEW_PARAMS, boundParams_);
    if (timer) timer->end();
    params_ = setup.params;
}

void WavefrontTracerGpu::generate(const ViewSetup& setup, const WavefrontPlan& plan,
                                  const WavefrontSettings& settings,
                                  const std::vector<unsigned>& gradients,
                                  std::vector<std::vector<shared::GpuWavefrontEntry>>& active) {
    const size_t passes = gradients.size();
    const size_t all = plan.patches * passes;
    resizeStorageBuffer(roots_, all * sizeof(shared::GpuWavefrontEntry));
    checkBuffers(std::to_string(all) + " starting patches");
    bindStorage(EK_SSBO_WAVE_LIST_OUT, roots_);
    generate_->use();
    generate_->setInt("perSide", plan.side);
    generate_->setFloat("fluxThreshold", settings.fluxThreshold);
    for (size_t k = 0; k < passes; ++k) {
        bindPass(int(k), gradients[k]);
        for (const PhotonLightPlan& light : plan.lights) {
            generate_->setInt("lightIndex", light.light);
            generate_->setInt("lightGrid", light.grid);
            generate_->setInt("patchOffset", int(k * plan.patches + light.first));
            generate_->setInt("patchCount", int(light.count));
            dispatchSpread(light.count, EK_WAVE_GROUP);
        }
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    // The emitted power sets the scales before anything is deposited; it is summed here in the
    // twin's order (pass after pass, index order, in double).
    const std::vector<shared::GpuWavefrontEntry> roots =
        readStorageArray<shared::GpuWavefrontEntry>(roots_, all);
    warnLightsMissingVolume(setup, plan.lights, [&](size_t i) {
        return int(roots[i].piece.state.x) == EK_PHOTON_ACTIVE;
    });
    active.assign(passes, {});
    for (size_t i = 0; i < all; ++i) {
        const shared::GpuWavefrontPatch& p = roots[i].piece;
        if (int(p.state.x) != EK_PHOTON_ACTIVE) continue;
        const glm::vec3 power(p.power);
        if (passes > 1 && power == glm::vec3(0.0f)) continue;  // a channel the light lacks
        host_.totals.emitted += glm::dvec3(power);
        active[i / plan.patches].push_back(roots[i]);
    }
    for (const auto& pass : active) host_.startingPatches += int64_t(pass.size());
    shared::VolumeAccessCpu volume{setup.params};  // for the shared volumeVoxelSize()
    const glm::vec3 h = volume.volumeVoxelSize();
    const double smallestVoxel = double(std::min({h.x, h.y, h.z}));
    const glm::dvec3& e = host_.totals.emitted;
    host_.fixedPointScale =
        glm::dvec4(fixedPointScaleFor(e.x, smallestVoxel), fixedPointScaleFor(e.y, smallestVoxel),
                   fixedPointScaleFor(e.z, smallestVoxel),
                   fixedPointScaleFor(rec709Luminance(e), smallestVoxel));
}

void WavefrontTracerGpu::scanStep(int stage, size_t count) const {
    scan_->setInt("stage", stage);
    if (stage == kStageTotals)
        glDispatchCompute(1, 1, 1);
    else
        dispatchSpread(count, EK_WAVE_SCAN_GROUP);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void WavefrontTracerGpu::sumWords(size_t count, bool requests, int source, int target, int blocks,
                                  int totalWord) const {
    scan_->setInt("requests", requests);
    scan_->setInt("source", source);
    scan_->setInt("target", target);
    scan_->setInt("blocks", blocks);
    scan_->setInt("totalWord", totalWord);
    scanStep(kStageBlocks, count);
    scanStep(kStageTotals, count);
}

void WavefrontTracerGpu::tracePass(const WavefrontRoundSettings& round,
                                   const WavefrontSettings& settings,
                                   std::vector<shared::GpuWavefrontEntry> roots) {
    size_t count = roots.size();
    if (count == 0) return;
    for (size_t r = 0; r < count; ++r) roots[r].tally.root = glm::ivec4(int(r), 0, 0, 0);
    reserveList(0, count);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, lists_[0]);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(count * sizeof(roots[0])),
                    roots.data());
    // Each starting patch has made itself.
    std::vector<GLuint> rootState(count * EK_WAVE_ROOT_WORDS, 0);
    for (size_t r = 0; r < count; ++r) rootState[r * EK_WAVE_ROOT_WORDS + EK_WAVE_ROOT_MADE] = 1;
    resizeStorageBuffer(rootState_, rootState.size() * sizeof(GLuint));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, rootState_);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(rootState.size() * sizeof(GLuint)),
                    rootState.data());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    checkBuffers(std::to_string(count) + " starting patches");
    bindStorage(EK_SSBO_WAVE_ROOT_STATE, rootState_);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    const glm::dvec3& e = host_.totals.emitted;
    const glm::dvec4& s = host_.fixedPointScale;
    for (ShaderProgram* program : {trace_.get(), scatter_.get()}) {
        program->use();
        program->setInt("maxSteps", round.maxSteps);
        program->setFloat("splitVoxels", round.splitVoxels);
        program->setInt("maxLevel", round.maxLevel);
        program->setFloat("dt", round.dt);
        program->setInt("integrator", round.integrator);
        program->setInt("atCaustic", round.atCaustic);
        program->setInt("samples", round.samples);
        program->setFloat("surfaceSlope", round.surfaceSlope);
        glUniform4d(program->uniformLocation("depositScale"), s.x, s.y, s.z, s.w);
        glUniform3d(program->uniformLocation("totalScale"), fixedPointScaleFor(e.x, 1.0),
                    fixedPointScaleFor(e.y, 1.0), fixedPointScaleFor(e.z, 1.0));
    }
    scan_->use();
    scan_->setUint("budget", GLuint(wavefrontRootBudget(settings, int64_t(count))));

    // A lineage takes at most maxSteps steps, maxLevel splits and one refusal, each round at
    // least one of them or a full round of steps: past this something is wrong, never a hang.
    const int roundCap = round.maxSteps / EK_WAVE_ROUND_STEPS + round.maxLevel + 4;
    int in = 0;
    for (int round = 0; count > 0; ++round) {
        if (round > roundCap)
            throw Error("wavefront tracing",
                        "the rounds did not end after " + std::to_string(roundCap) + " rounds");
        largestList_ = std::max(largestList_, int64_t(count));
        const int n = int(count);
        const int blocks = (n + EK_WAVE_SCAN_GROUP - 1) / EK_WAVE_SCAN_GROUP;
        const size_t scanWords = size_t(EK_WAVE_SCAN_WORDS(size_t(n), size_t(blocks)));
        if (scanWords > scanCapacity_ || !scanBuffer_) {
            scanCapacity_ = std::max(scanWords, 2 * scanCapacity_);
            resizeStorageBuffer(scanBuffer_, scanCapacity_ * sizeof(GLuint));
            checkBuffers(std::to_string(count) + " patches' prefix sums");
        }
        bindStorage(EK_SSBO_WAVE_SCAN, scanBuffer_);
        bindStorage(EK_SSBO_WAVE_LIST_IN, lists_[in]);

        trace_->use();
        trace_->setInt("patchCount", n);
        dispatchSpread(count, EK_WAVE_GROUP);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        // The requests' prefix sums, where each starting patch's run of them starts, the grants,
        // and the entries' prefix sums: the next list's layout.
        scan_->use();
        scan_->setInt("patchCount", n);
        sumWords(count, true, EK_WAVE_OUTCOMES(n), EK_WAVE_REQUESTS_BEFORE(n),
                 EK_WAVE_REQUEST_BLOCKS(n), EK_WAVE_REQUESTS);
        scanStep(kStageFirsts, count);
        scanStep(kStageGrants, count);
        sumWords(count, false, EK_WAVE_ENTRIES(n), EK_WAVE_ENTRIES_BEFORE(n),
                 EK_WAVE_ENTRY_BLOCKS(n, blocks), EK_WAVE_NEXT);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        // The one word read back a round: the next list's length.
        const size_t next = readStorageWords(roundsBuffer_, EK_WAVE_NEXT, 1)[0];
        reserveList(1 - in, next);
        bindStorage(EK_SSBO_WAVE_LIST_IN, lists_[in]);
        bindStorage(EK_SSBO_WAVE_LIST_OUT, lists_[1 - in]);
        scatter_->use();
        scatter_->setInt("patchCount", n);
        dispatchSpread(count, EK_WAVE_GROUP);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        count = next;
        in = 1 - in;
        ++rounds_;
    }
}

WavefrontResultCpu WavefrontTracerGpu::counts() const {
    WavefrontResultCpu r = host_;
    const std::vector<GLuint> words =
        readStorageWords(roundsBuffer_, EK_WAVE_HEADER, EK_WAVE_TOTAL_WORDS);
    const glm::dvec3& e = host_.totals.emitted;
    const glm::dvec3 scale(fixedPointScaleFor(e.x, 1.0), fixedPointScaleFor(e.y, 1.0),
                           fixedPointScaleFor(e.z, 1.0));
    auto total = [&](int at, glm::dvec3& out) {
        for (int c = 0; c < 3; ++c)
            out[c] = fromFixedPoint(joinFixedWords(&words[size_t(at + 2 * c)]), scale[c]);
    };
    total(EK_WAVE_ESCAPED, r.totals.escaped);
    total(EK_WAVE_EXTINGUISHED, r.totals.extinguished);
    total(EK_WAVE_DROPPED, r.totals.dropped);
    total(EK_WAVE_RECEIVED, r.totals.received);
    total(EK_WAVE_REMOVED_POWER, r.totals.removed);
    total(EK_WAVE_REFLECTED, r.totals.reflected);
    r.steps = joinFixedWords(&words[EK_WAVE_STEPS]);
    r.patchesCut = words[EK_WAVE_CUT];
    r.patchesTorn = words[EK_WAVE_TORN];
    r.patchesRemoved = words[EK_WAVE_REMOVED];
    r.causticCrossings = words[EK_WAVE_CROSSINGS];
    r.patchesSplit = words[EK_WAVE_SPLIT];
    r.splitsRefused = words[EK_WAVE_REFUSED];
    r.maxLevelReached = int(words[EK_WAVE_MAX_LEVEL]);
    r.patchesTraced = r.startingPatches + 4 * r.patchesSplit;
    r.rounds = rounds_;
    r.largestList = largestList_;
    return r;
}

std::vector<glm::vec4> WavefrontTracerGpu::receiverMap() const {
    return readFixedReceiverMap(receiverDeposits_, params_, host_.totals.emitted);
}

WavefrontResultCpu WavefrontTracerGpu::download() const {
    WavefrontResultCpu r = counts();
    r.receiverMap = receiverMap();
    readFixedDeposits(deposits_, r.resolution, host_.fixedPointScale, r.radiance, r.direction);
    return r;
}

}  // namespace eikon
