#include "render/gpu_timer.h"

#include <epoxy/gl.h>

#include <atomic>

#include "core/error.h"
#include "core/log.h"

namespace eikon {
namespace {

const char* const kWhere = "GPU timer";

// Queries waiting to be read before begin() reads them itself. A caller that never asks for the
// results (a loop that prints no stats) would otherwise make a query per stage per frame for
// ever; the oldest of 64 belong to frames long finished, so reading them does not stall.
constexpr size_t kMaxPendingQueries = 64;

bool timerQueriesSupported() {
    GLint bits = 0;
    glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
    if (bits > 0) return true;
    // Once per process: a timer is made per frame and the answer does not change.
    static std::atomic<bool> warned{false};
    if (!warned.exchange(true)) {
        logWarning(
            "GPU timer queries are not supported by this driver "
            "(GL_QUERY_COUNTER_BITS of GL_TIME_ELAPSED is 0); GPU stage times read -1");
    }
    return false;
}

}  // namespace

GpuStageTimer::GpuStageTimer(bool gpuQueries) : gpu_(gpuQueries && timerQueriesSupported()) {}

GpuStageTimer::~GpuStageTimer() {
    if (open_ && gpu_) glEndQuery(GL_TIME_ELAPSED);
    if (!allQueries_.empty())
        glDeleteQueries(static_cast<GLsizei>(allQueries_.size()), allQueries_.data());
}

void GpuStageTimer::begin(const std::string& stage) {
    if (open_) {
        throw Error(kWhere, "begin(\"" + stage + "\") while \"" + stages_[openStage_].name +
                                "\" is open; stages do not nest");
    }
    openStage_ = stageIndex(stage);
    if (listener_) listener_(stage);
    if (gpu_) {
        if (pending_.size() >= kMaxPendingQueries) collectPending();
        const GLuint query = acquireQuery();
        glBeginQuery(GL_TIME_ELAPSED, query);
        pending_.push_back({openStage_, query});
    }
    open_ = true;
    openedAt_ = std::chrono::steady_clock::now();
}

void GpuStageTimer::end() {
    if (!open_) throw Error(kWhere, "end() without begin()");
    const auto elapsed = std::chrono::steady_clock::now() - openedAt_;
    if (gpu_) glEndQuery(GL_TIME_ELAPSED);
    Stage& stage = stages_[openStage_];
    stage.cpuMs += std::chrono::duration<double, std::milli>(elapsed).count();
    ++stage.calls;
    open_ = false;
}

std::vector<StageTime> GpuStageTimer::results() {
    if (open_) {
        throw Error(kWhere, "results() while \"" + stages_[openStage_].name + "\" is still open");
    }
    collectPending();
    std::vector<StageTime> times;
    times.reserve(stages_.size());
    for (const Stage& stage : stages_) {
        const double gpuMs = gpu_ ? static_cast<double>(stage.gpuNs) * 1e-6 : -1.0;
        times.push_back({stage.name, gpuMs, stage.cpuMs, stage.calls});
    }
    return times;
}

void GpuStageTimer::reset() {
    if (open_) throw Error(kWhere, "reset() while \"" + stages_[openStage_].name + "\" is open");
    // Reading the results frees their queries; the values themselves are dropped.
    collectPending();
    stages_.clear();
}

size_t GpuStageTimer::stageIndex(const std::string& name) {
    for (size_t i = 0; i < stages_.size(); ++i)
        if (stages_[i].name == name) return i;
    stages_.push_back({name});
    return stages_.size() - 1;
}

unsigned int GpuStageTimer::acquireQuery() {
    if (freeQueries_.empty()) {
        GLuint query = 0;
        glGenQueries(1, &query);
        allQueries_.push_back(query);
        return query;
    }
    const unsigned int query = freeQueries_.back();
    freeQueries_.pop_back();
    return query;
}

void GpuStageTimer::collectPending() {
    for (const Pending& p : pending_) {
        GLuint64 ns = 0;
        // GL_QUERY_RESULT waits until the GPU has finished the stage.
        glGetQueryObjectui64v(p.query, GL_QUERY_RESULT, &ns);
        stages_[p.stage].gpuNs += ns;
        freeQueries_.push_back(p.query);
    }
    pending_.clear();
}

}  // namespace eikon
