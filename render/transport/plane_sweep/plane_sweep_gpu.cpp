#include "render/transport/plane_sweep/plane_sweep_gpu.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <functional>
#include <string>

#include "core/error.h"
#include "render/gpu_timer.h"
#include "render/gpu_transfer.h"
#include "render/receiver_map.h"
#include "render/refraction_volume.h"
#include "render/shader_program.h"
#include "render/transport/channel_passes.h"
#include "render/volume_textures.h"
#include "shaders/shared/bindings.h"

namespace eikon {
namespace {

// plane_sweep.comp's passes.
constexpr int kPassClear = 0;
constexpr int kPassTrace = 1;
constexpr int kPassAdvance = 2;
constexpr int kPassDeposit = 3;
constexpr int kPassStop = 4;

constexpr GLuint kGroup = 8;  // plane_sweep.comp's local size along x and y

GLuint groups(int n) {
    return GLuint((n + int(kGroup) - 1) / int(kGroup));
}

void bindImage(GLuint unit, GLuint texture, bool layered) {
    glBindImageTexture(unit, texture, 0, layered ? GL_TRUE : GL_FALSE, 0, GL_READ_WRITE,
                       GL_RGBA32F);
}

void barrier() {
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

const char* const kWhere = "render.light_transport.method \"plane_sweep\"";

}  // namespace

PlaneSweepGpu::PlaneSweepGpu(bool exactMath) {
    std::vector<std::string> defines;
    if (exactMath) defines.push_back("EK_EXACT_MATH");
    program_ = std::make_unique<ShaderProgram>(ShaderProgram::compute("plane_sweep.comp", defines));
    glGenBuffers(1, &counters_);
    glGenBuffers(1, &receiverSums_);
}

PlaneSweepGpu::~PlaneSweepGpu() {
    glDeleteTextures(2, volumes_);
    glDeleteTextures(5, planes_);
    glDeleteBuffers(1, &counters_);
    glDeleteBuffers(1, &receiverSums_);
    glDeleteBuffers(1, &receiverMapBuffer_);
}

void PlaneSweepGpu::allocateVolumes(glm::ivec3 res) {
    if (volumes_[0] && res == resolution_) return;
    glDeleteTextures(2, volumes_);
    glGenTextures(2, volumes_);
    for (GLuint texture : volumes_) {
        glBindTexture(GL_TEXTURE_3D, texture);
        glTexStorage3D(GL_TEXTURE_3D, 1, GL_RGBA32F, res.x, res.y, res.z);
        setVolumeSampling();
    }
    glBindTexture(GL_TEXTURE_3D, 0);
    if (glGetError() != GL_NO_ERROR)
        throw Error(kWhere, "the driver refused two RGBA32F volumes of " + std::to_string(res.x) +
                                "x" + std::to_string(res.y) + "x" + std::to_string(res.z));
    resolution_ = res;
}

void PlaneSweepGpu::allocatePlanes(glm::ivec2 size) {
    if (planes_[0] && size == planeSize_) return;
    glDeleteTextures(5, planes_);
    glGenTextures(5, planes_);
    for (GLuint texture : planes_) {
        glBindTexture(GL_TEXTURE_2D, texture);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, size.x, size.y);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    if (glGetError() != GL_NO_ERROR)
        throw Error(kWhere, "the driver refused five RGBA32F planes of " + std::to_string(size.x) +
                                "x" + std::to_string(size.y));
    planeSize_ = size;
}

void PlaneSweepGpu::dispatchPlane(glm::ivec2 size) const {
    glDispatchCompute(groups(size.x), groups(size.y), 1);
    barrier();
}

void PlaneSweepGpu::sweepPlane(const ViewSetup& setup, const PlaneSweepPlan& plan,
                               const PlaneSweepSettings& settings, int j, const unsigned planes[5],
                               int& in, bool receivers) {
    const shared::GpuPlaneSweep sweep = planeSweepStep(setup, plan, settings, j);
    program_->setIVec4("sweepAxes", sweep.axes);
    program_->setIVec4("sweepPlane", sweep.plane);
    program_->setVec4("sweepPlace", sweep.place);
    program_->setVec4("sweepLimit", sweep.limit);
    bindImage(EK_IMAGE_SWEEP_TRACE, planes[4], false);
    bindImage(EK_IMAGE_SWEEP_LIGHT_IN, planes[in], false);
    bindImage(EK_IMAGE_SWEEP_DIRECTION_IN, planes[2 + in], false);
    bindImage(EK_IMAGE_SWEEP_LIGHT_OUT, planes[1 - in], false);
    bindImage(EK_IMAGE_SWEEP_DIRECTION_OUT, planes[3 - in], false);
    program_->setInt("sweepPass", kPassTrace);
    dispatchPlane(plan.size);
    program_->setInt("sweepPass", kPassAdvance);
    dispatchPlane(plan.size);
    if (receivers) {
        program_->setInt("sweepPass", kPassStop);
        dispatchPlane(plan.size);
    }
    in = 1 - in;
    texelSteps_ += int64_t(plan.size.x) * int64_t(plan.size.y);
}

void PlaneSweepGpu::depositPlane(const ViewSetup& setup, const PlaneSweepPlan& plan,
                                 const PlaneSweepSettings& settings, int j,
                                 const unsigned planes[5], int in) {
    const shared::GpuPlaneSweep sweep = planeSweepStep(setup, plan, settings, j);
    program_->setIVec4("sweepAxes", sweep.axes);
    program_->setIVec4("sweepPlane", sweep.plane);
    program_->setVec4("sweepPlace", sweep.place);
    program_->setVec4("sweepLimit", sweep.limit);
    bindImage(EK_IMAGE_SWEEP_LIGHT_IN, planes[in], false);
    bindImage(EK_IMAGE_SWEEP_DIRECTION_IN, planes[2 + in], false);
    program_->setInt("sweepPass", kPassDeposit);
    dispatchPlane(plan.size);
}

void PlaneSweepGpu::sweepPass(const ViewSetup& setup, const PlaneSweepPlan& plan,
                              const PlaneSweepSettings& settings, bool receivers) {
    int in = 0;
    for (int j = 0; j < plan.planes; ++j) {
        sweepPlane(setup, plan, settings, j, planes_, in, receivers);
        const int slice = planeSweepSlice(plan, j);
        if (slice < 0) continue;
        program_->setInt("depositSlice", slice);
        depositPlane(setup, plan, settings, j, planes_, in);
    }
}

void PlaneSweepGpu::compute(const ViewSetup& setup, VolumeTextures& fields,
                            const RefractionVolumesGpu& refraction,
                            const PlaneSweepSettings& settings, GpuStageTimer* timer,
                            bool dispersion) {
    const shared::GpuViewParams& p = setup.params;
    const std::vector<unsigned> gradients = channelPassGradientsGpu(refraction, dispersion, kWhere);
    const int passes = int(gradients.size());
    const glm::ivec3 res(p.resolution);
    allocateVolumes(res);
    texels_ = 0;
    texelSteps_ = 0;
    memory_ = PlaneSweepMemory{};
    memory_.outputBytes = 2 * size_t(res.x) * size_t(res.y) * size_t(res.z) * sizeof(glm::vec4);

    if (timer) timer->begin("plane_sweep");
    fields.bind();
    beginRun(setup, settings, volumes_);
    program_->setInt("depositWindow", 0);
    program_->setInt("sweepPass", kPassClear);
    glDispatchCompute(groups(res.x), groups(res.y), GLuint(res.z));
    barrier();

    const bool receivers = shared::receiverCount(p) > 0;
    for (int l = 0; l < shared::lightCount(p); ++l) {
        if (!shared::lightInFluence(p, l)) continue;
        const PlaneSweepPlan plan = planPlaneSweep(setup, l, settings);
        allocatePlanes(plan.size);
        const size_t texels = size_t(plan.size.x) * size_t(plan.size.y);
        memory_.bufferBytes = std::max(memory_.bufferBytes, 5 * texels * sizeof(glm::vec4));
        for (int pass = 0; pass < passes; ++pass) {
            texels_ += int64_t(texels);
            glActiveTexture(GL_TEXTURE0 + EK_UNIT_GRADIENT);
            glBindTexture(GL_TEXTURE_3D, gradients[size_t(pass)]);
            glActiveTexture(GL_TEXTURE0);
            program_->setVec3("sweepChannels", channelPassMask(pass, passes));
            sweepPass(setup, plan, settings, receivers);
        }
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_BUFFER_UPDATE_BARRIER_BIT);
    if (timer) timer->end();
    finishRun(setup);
}

void PlaneSweepGpu::sweepWindowed(const ViewSetup& setup, VolumeTextures& fields,
                                  const RefractionVolumesGpu& refraction,
                                  const PlaneSweepSettings& settings, const SweepAxis& axis,
                                  const unsigned window[2], int windowSlices, bool dispersion,
                                  GpuStageTimer* timer,
                                  const std::function<bool(int swept)>& isTurn,
                                  const std::function<void(int swept)>& turn) {
    const shared::GpuViewParams& p = setup.params;
    const std::vector<unsigned> gradients = channelPassGradientsGpu(refraction, dispersion, kWhere);
    const int passes = int(gradients.size());
    texels_ = 0;
    texelSteps_ = 0;
    memory_ = PlaneSweepMemory{};
    // Every light's sweep, each channel's under dispersion, in the order the twin's
    // lightSweepSpecs lists them (its deposits add in that order), each with its own buffers.
    struct Sweep {
        PlaneSweepPlan plan;
        unsigned gradient;
        glm::vec3 channels;
        GLuint planes[5];  // light, direction (twice each), traces
        int in = 0;        // planes[in] and planes[2 + in] hold the previous plane
    };
    std::vector<Sweep> sweeps;
    struct PlaneTextures {
        std::vector<GLuint> names;
        ~PlaneTextures() { glDeleteTextures(GLsizei(names.size()), names.data()); }
    } owned;
    for (int l = 0; l < shared::lightCount(p); ++l) {
        if (!shared::lightInFluence(p, l)) continue;
        const PlaneSweepPlan plan = planPlaneSweep(setup, l, settings, &axis);
        for (int pass = 0; pass < passes; ++pass) {
            Sweep sweep{plan, gradients[size_t(pass)], channelPassMask(pass, passes), {}, 0};
            glGenTextures(5, sweep.planes);
            owned.names.insert(owned.names.end(), sweep.planes, sweep.planes + 5);
            for (GLuint texture : sweep.planes) {
                glBindTexture(GL_TEXTURE_2D, texture);
                glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, plan.size.x, plan.size.y);
            }
            glBindTexture(GL_TEXTURE_2D, 0);
            const size_t texels = size_t(plan.size.x) * size_t(plan.size.y);
            memory_.bufferBytes += 5 * texels * sizeof(glm::vec4);
            texels_ += int64_t(texels);
            sweeps.push_back(sweep);
        }
    }
    if (glGetError() != GL_NO_ERROR)
        throw Error(kWhere, "the driver refused the sweeps' RGBA32F planes");

    if (timer) timer->begin("plane_sweep");
    fields.bind();
    beginRun(setup, settings, window);
    program_->setInt("depositWindow", 1);
    const glm::ivec3 res(p.resolution);
    const glm::ivec2 windowSize(res[(axis.axis + 1) % 3], res[(axis.axis + 2) % 3]);
    program_->setInt("sweepPass", kPassClear);
    for (int layer = 0; layer < windowSlices; ++layer) {
        program_->setInt("depositSlice", layer);
        dispatchPlane(windowSize);
    }
    const bool receivers = shared::receiverCount(p) > 0;
    const int planes = sweeps.empty() ? 0 : sweeps.front().plan.planes;
    int swept = 0;
    for (int j = 0; j < planes; ++j) {
        for (Sweep& sweep : sweeps) {
            glActiveTexture(GL_TEXTURE0 + EK_UNIT_GRADIENT);
            glBindTexture(GL_TEXTURE_3D, sweep.gradient);
            glActiveTexture(GL_TEXTURE0);
            program_->setVec3("sweepChannels", sweep.channels);
            sweepPlane(setup, sweep.plan, settings, j, sweep.planes, sweep.in, receivers);
        }
        const int slice = planeSweepSlice(sweeps.front().plan, j);
        if (slice < 0) continue;
        program_->setInt("depositSlice", slice % windowSlices);
        program_->setInt("sweepPass", kPassClear);
        dispatchPlane(windowSize);
        for (Sweep& sweep : sweeps) {
            program_->setVec3("sweepChannels", sweep.channels);
            depositPlane(setup, sweep.plan, settings, j, sweep.planes, sweep.in);
        }
        ++swept;
        if (!isTurn(swept)) continue;
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        if (timer) timer->end();
        turn(swept);
        if (timer) timer->begin("plane_sweep");
        // The view's dispatches used another program and the same units: take them back.
        fields.bind();
        beginRun(setup, settings, window, false);
        program_->setInt("depositWindow", 1);
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    if (timer) timer->end();
    finishRun(setup);
}

void PlaneSweepGpu::beginRun(const ViewSetup& setup, const PlaneSweepSettings& settings,
                             const unsigned output[2], bool fresh) {
    // The volumes written here may not stay bound for sampling.
    for (GLuint unit : {EK_UNIT_FLUENCE, EK_UNIT_FLUENCE_DIRECTION}) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_3D, 0);
    }
    glActiveTexture(GL_TEXTURE0);
    bindImage(EK_IMAGE_SWEEP_FLUENCE, output[0], true);
    bindImage(EK_IMAGE_SWEEP_FLUENCE_DIRECTION, output[1], true);
    if (fresh) {
        const shared::GpuViewParams& p = setup.params;
        const GLuint zero = 0;
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, counters_);
        glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(GLuint), &zero, GL_DYNAMIC_READ);
        receiverSumCount_ = 3 * receiverMapTexels(p);
        receiverScale_ = planeSweepReceiverScale(setup, settings);
        // Two words per int64 sum, zeroed (at least one word: GL refuses empty buffers).
        const std::vector<GLuint> zeros(std::max<size_t>(2 * receiverSumCount_, 1), 0u);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, receiverSums_);
        glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(zeros.size() * sizeof(GLuint)),
                     zeros.data(), GL_DYNAMIC_READ);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_SWEEP_COUNTERS, counters_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_SWEEP_RECEIVER_SUMS, receiverSums_);
    program_->use();
    glUniform1d(program_->uniformLocation("receiverScale"), receiverScale_);
}

void PlaneSweepGpu::finishRun(const ViewSetup& setup) {
    // The map is read back and converted by the twin's own code (a few hundred KB once per run),
    // then uploaded for the view pass.
    receiverMap_ = planeSweepReceiverMap(setup, downloadReceiverSums().data(), receiverScale_);
    uploadVec4Buffer(receiverMapBuffer_, receiverMap_);
    if (const GLenum err = glGetError(); err != GL_NO_ERROR)
        throw Error(kWhere, "OpenGL error " + std::to_string(err));
}

std::vector<int64_t> PlaneSweepGpu::downloadReceiverSums() const {
    std::vector<GLuint> words(2 * receiverSumCount_);
    std::vector<int64_t> sums(receiverSumCount_);
    if (sums.empty()) return sums;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, receiverSums_);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(words.size() * sizeof(GLuint)),
                       words.data());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    for (size_t i = 0; i < sums.size(); ++i)
        sums[i] = int64_t((uint64_t(words[2 * i + 1]) << 32) | uint64_t(words[2 * i]));
    return sums;
}

void PlaneSweepGpu::bind() const {
    glActiveTexture(GL_TEXTURE0 + EK_UNIT_FLUENCE);
    glBindTexture(GL_TEXTURE_3D, volumes_[0]);
    glActiveTexture(GL_TEXTURE0 + EK_UNIT_FLUENCE_DIRECTION);
    glBindTexture(GL_TEXTURE_3D, volumes_[1]);
    glActiveTexture(GL_TEXTURE0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_RECEIVER_MAP, receiverMapBuffer_);
}

void PlaneSweepGpu::bindReceiverMap() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_RECEIVER_MAP, receiverMapBuffer_);
}

int64_t PlaneSweepGpu::texelsLost() const {
    GLuint lost = 0;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, counters_);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(GLuint), &lost);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    return int64_t(lost);
}

PlaneSweepResultCpu PlaneSweepGpu::download() const {
    PlaneSweepResultCpu out;
    if (!volumes_[0]) return out;
    out.fluence = downloadRgbaVolume(volumes_[0], resolution_);
    out.direction = downloadRgbaVolume(volumes_[1], resolution_);
    out.texels = texels_;
    out.texelSteps = texelSteps_;
    out.texelsLost = texelsLost();
    out.receiverMap = receiverMap_;
    out.memory = memory_;
    return out;
}

}  // namespace eikon
