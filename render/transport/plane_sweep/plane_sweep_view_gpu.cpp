#include <epoxy/gl.h>

#include <algorithm>
#include <string>

#include "core/error.h"
#include "render/gpu_timer.h"
#include "render/image.h"
#include "render/params_buffer.h"
#include "render/refraction_volume.h"
#include "render/shader_program.h"
#include "render/transport/plane_sweep/plane_sweep_view.h"
#include "render/transport/plane_sweep/plane_sweep_view_window.h"
#include "render/view_params.h"
#include "render/volume_textures.h"
#include "shaders/shared/bindings.h"

namespace eikon {
namespace {

// view_interleaved.comp's passes.
constexpr int kPassStart = 0;
constexpr int kPassAdvance = 1;
constexpr int kPassShade = 2;
constexpr int kPassCompose = 3;

const char* const kWhere = "render.light_transport.plane_sweep.view \"interleaved\" (GPU)";

// A zeroed shader storage buffer of `bytes` (at least 4: GL refuses empty buffers).
void allocateBuffer(GLuint& buffer, size_t bytes) {
    if (!buffer) glGenBuffers(1, &buffer);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(std::max<size_t>(bytes, 4)), nullptr,
                 GL_DYNAMIC_COPY);
    const GLuint zero = 0;
    glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

// The bytes between two rays in the shader's ray buffer (std430, as the driver lays it out).
size_t rayStride(const ShaderProgram& program) {
    const GLuint index = glGetProgramResourceIndex(program.id(), GL_BUFFER_VARIABLE,
                                                   "InterleavedRays.rays[0].radiance");
    GLuint found = index;
    if (found == GL_INVALID_INDEX)
        found = glGetProgramResourceIndex(program.id(), GL_BUFFER_VARIABLE, "rays[0].radiance");
    if (found == GL_INVALID_INDEX)
        throw Error(kWhere, "the driver does not list the view rays' buffer variable");
    const GLenum property = GL_TOP_LEVEL_ARRAY_STRIDE;
    GLint stride = 0;
    glGetProgramResourceiv(program.id(), GL_BUFFER_VARIABLE, found, 1, &property, 1, nullptr,
                           &stride);
    if (stride <= 0) throw Error(kWhere, "the driver gave the view rays no array stride");
    return size_t(stride);
}

}  // namespace

InterleavedViewGpu::InterleavedViewGpu(bool exactMath) : sweep_(exactMath) {}

InterleavedViewGpu::~InterleavedViewGpu() {
    glDeleteTextures(2, window_);
    glDeleteTextures(1, &output_);
    GLuint buffers[4] = {rays_, flags_, hits_, counters_};
    glDeleteBuffers(4, buffers);
}

ShaderProgram& InterleavedViewGpu::program(bool curved, bool specular) {
    std::unique_ptr<ShaderProgram>& slot = programs_[(curved ? 1 : 0) + (specular ? 2 : 0)];
    if (!slot) {
        std::vector<std::string> defines = {"EK_FLUENCE_WINDOW"};
        if (curved) defines.push_back("EK_INTERLEAVED_CURVED");
        if (specular) defines.push_back("EK_SPECULAR");  // the lights' highlights (view_march.h)
        slot = std::make_unique<ShaderProgram>(
            ShaderProgram::compute("view_interleaved.comp", defines));
    }
    return *slot;
}

void InterleavedViewGpu::allocate(const shared::GpuViewParams& p, const SweepAxis& axis,
                                  size_t stride, int channels) {
    const glm::ivec3 res(p.resolution);
    const glm::ivec3 window(res[(axis.axis + 1) % 3], res[(axis.axis + 2) % 3],
                            kInterleavedWindowSlices);
    if (!window_[0] || window != windowSize_) {
        glDeleteTextures(2, window_);
        glGenTextures(2, window_);
        for (GLuint texture : window_) {
            glBindTexture(GL_TEXTURE_3D, texture);
            glTexStorage3D(GL_TEXTURE_3D, 1, GL_RGBA32F, window.x, window.y, window.z);
            setVolumeSampling();
        }
        glBindTexture(GL_TEXTURE_3D, 0);
        windowSize_ = window;
    }
    const int width = p.image.x, height = p.image.y;
    if (!output_ || width != outputWidth_ || height != outputHeight_) {
        glDeleteTextures(1, &output_);
        glGenTextures(1, &output_);
        glBindTexture(GL_TEXTURE_2D, output_);
        glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA32F, width, height);
        glBindTexture(GL_TEXTURE_2D, 0);
        outputWidth_ = width;
        outputHeight_ = height;
    }
    const size_t rays = size_t(width) * size_t(height) * size_t(channels);
    allocateBuffer(rays_, rays * stride);
    allocateBuffer(flags_, rays * sizeof(GLuint));
    allocateBuffer(hits_, rays * 2 * sizeof(glm::vec4));
    allocateBuffer(counters_, 2 * sizeof(GLuint));
    if (glGetError() != GL_NO_ERROR)
        throw Error(kWhere, "the driver refused the view rays' buffers or the window of " +
                                std::to_string(window.x) + "x" + std::to_string(window.y) + "x" +
                                std::to_string(window.z));
    windowBytes_ = 2 * size_t(window.x) * size_t(window.y) * size_t(window.z) * sizeof(glm::vec4);
    rayBytes_ = rays * (stride + sizeof(GLuint) +
                        (shared::receiverCount(p) > 0 ? 2 * sizeof(glm::vec4) : 0));
}

Image InterleavedViewGpu::render(const ViewSetup& setup, VolumeTextures& fields,
                                 const RefractionVolumesGpu& refraction,
                                 const PlaneSweepSettings& settings, unsigned environmentTexture,
                                 GpuStageTimer* timer) {
    const shared::GpuViewParams& p = setup.params;
    if (shared::environmentType(p) == EK_ENVIRONMENT_IMAGE && !environmentTexture)
        throw Error(kWhere, "the environment image was not uploaded");
    const SweepAxis axis = interleavedSweepAxis(setup);
    const bool curved = shared::curvedRays(p);
    // Under dispersion a ray a colour channel, each dispatched with its channel's params (uploaded
    // here once a frame; the sweeps read the scene's, bound again after) and ∇n volume.
    const bool dispersed = curved && dispersesView(setup);
    const int channels = dispersed ? 3 : 1;
    if (dispersed)
        for (int c = 0; c < 4; ++c) {
            if (!params_[c]) params_[c] = std::make_unique<ParamsBuffer>();
            params_[c]->upload(c < 3 ? channelViewParams(setup, c) : p);
        }
    const auto gradientOf = [&](int c) {
        return dispersed ? refraction.channelGradientTexture(c) : refraction.gradientTexture();
    };
    ShaderProgram& view = program(curved, curved && shared::anySurfaceHighlights(p));
    if (timer) timer->begin("view");
    allocate(p, axis, rayStride(view), channels);
    const int width = p.image.x, height = p.image.y;
    const int depth = p.resolution[axis.axis];
    const bool receivers = shared::receiverCount(p) > 0;
    const auto local = view.localSize();
    // Binds what the view's dispatches read (the sweep's dispatches rebind their own).
    const auto bindView = [&] {
        fields.bind();
        glActiveTexture(GL_TEXTURE0 + EK_UNIT_ENVIRONMENT);
        glBindTexture(GL_TEXTURE_2D, environmentTexture);
        glActiveTexture(GL_TEXTURE0 + EK_UNIT_FLUENCE);
        glBindTexture(GL_TEXTURE_3D, window_[0]);
        glActiveTexture(GL_TEXTURE0 + EK_UNIT_FLUENCE_DIRECTION);
        glBindTexture(GL_TEXTURE_3D, window_[1]);
        glActiveTexture(GL_TEXTURE0);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_INTERLEAVED_RAYS, rays_);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_INTERLEAVED_FLAGS, flags_);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_INTERLEAVED_HITS, hits_);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_INTERLEAVED_COUNTERS, counters_);
        sweep_.bindReceiverMap();
        view.use();
        view.setInt("rayChannels", channels);
    };
    const auto dispatch = [&](int pass) {
        view.setInt("interleavedPass", pass);
        glDispatchCompute(GLuint((width + local[0] - 1) / local[0]),
                          GLuint((height + local[1] - 1) / local[1]), 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    };
    // A pass over every channel's rays, each with its channel's params and ∇n; the scene's params
    // bound again after.
    const auto dispatchRays = [&](int pass) {
        for (int c = 0; c < channels; ++c) {
            if (dispersed) params_[c]->bind();
            glActiveTexture(GL_TEXTURE0 + EK_UNIT_GRADIENT);
            glBindTexture(GL_TEXTURE_3D, gradientOf(c));
            glActiveTexture(GL_TEXTURE0);
            view.setInt("rayChannel", c);
            dispatch(pass);
        }
        if (dispersed) params_[3]->bind();
    };
    // The window after `swept` slices: the CPU twin's (renderInterleavedCpu).
    const auto setWindow = [&](int swept) {
        const int oldest = std::max(swept - kInterleavedWindowSlices, 0), newest = swept - 1;
        const auto sliceAt = [&](int rank) { return axis.order > 0 ? rank : depth - 1 - rank; };
        view.setIVec4("fluenceWindow", glm::ivec4(axis.axis, kInterleavedWindowSlices,
                                                  std::min(sliceAt(oldest), sliceAt(newest)),
                                                  std::max(sliceAt(oldest), sliceAt(newest))));
        view.setInt("windowOrder", axis.order);
        view.setInt("windowSwept", swept);
    };
    bindView();
    setWindow(0);
    dispatchRays(kPassStart);
    if (timer) timer->end();

    int lastSwept = 0;
    sweep_.sweepWindowed(
        setup, fields, refraction, settings, axis, window_, kInterleavedWindowSlices, dispersed,
        timer, [&](int swept) { return interleavedViewTurn(swept, depth); },
        [&](int swept) {
            if (timer) timer->begin("view");
            bindView();
            setWindow(swept);
            dispatchRays(kPassAdvance);
            if (receivers) {
                view.setInt("interleavedAll", 0);
                dispatchRays(kPassShade);
            }
            lastSwept = swept;
            if (timer) timer->end();
        });

    if (timer) timer->begin("view");
    bindView();
    // With no light to sweep the rays read no fluence (the window is zero): they finish at once.
    setWindow(lastSwept > 0 ? lastSwept : depth);
    if (lastSwept == 0) dispatchRays(kPassAdvance);
    // The receivers' maps are complete: the hits left see them.
    if (receivers) {
        view.setInt("interleavedAll", 1);
        dispatchRays(kPassShade);
    }
    glBindImageTexture(EK_IMAGE_VIEW_OUTPUT, output_, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    dispatch(kPassCompose);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    if (timer) timer->end();

    if (timer) timer->begin("readback");
    Image image(width, height);
    glBindTexture(GL_TEXTURE_2D, output_);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, image.pixels.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    GLuint counts[2] = {0, 0};
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, counters_);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(counts), counts);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    samplesBehind_ = int64_t(counts[0]);
    viewSteps_ = int64_t(counts[1]);
    if (timer) timer->end();
    if (const GLenum err = glGetError(); err != GL_NO_ERROR)
        throw Error(kWhere, "OpenGL error " + std::to_string(err));
    return image;
}

}  // namespace eikon
