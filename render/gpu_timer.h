#pragma once
// Per-stage timing of the pipeline: GPU time from GL_TIME_ELAPSED queries and CPU wall time from
// steady_clock, so that --stats and the speed bench can tell a GPU-bound stage from one that
// waits on the host. Query results are read in results(), so timing does not stall a frame, or by
// begin() once 64 wait, so that a caller that never reads them holds a bounded number.
#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace eikon {

struct StageTime {
    std::string name;
    double gpuMs = -1.0;  // -1: GPU timing unavailable (no timer queries, or a CPU-only timer)
    double cpuMs = 0.0;   // host wall time between begin() and end(): submission, not GPU work
    int calls = 0;        // how many begin()/end() pairs were summed
};

class GpuStageTimer {
public:
    // With gpuQueries (needs a current GL context) GPU time is measured where the driver supports
    // timer queries; otherwise, or with gpuQueries = false (CPU twin, no GL), it reads -1.
    explicit GpuStageTimer(bool gpuQueries = true);
    ~GpuStageTimer();
    GpuStageTimer(const GpuStageTimer&) = delete;
    GpuStageTimer& operator=(const GpuStageTimer&) = delete;

    // Opens a stage; a name seen before adds to that stage. Stages do not nest (GL allows one
    // GL_TIME_ELAPSED query at a time), so begin() with a stage open throws Error.
    void begin(const std::string& stage);
    // Closes the open stage; throws Error when none is open.
    void end();

    // Stages in order of first begin(), times summed over repeats. Waits for the GPU results.
    std::vector<StageTime> results();
    // Forgets all stages (the query objects are kept for reuse).
    void reset();

    bool gpuTiming() const { return gpu_; }

    // Called with the stage's name at every begin() (a command's progress line shows which stage
    // a long frame is in); empty: none.
    void setListener(std::function<void(const std::string&)> listener) {
        listener_ = std::move(listener);
    }

private:
    struct Stage {
        std::string name;
        unsigned long long gpuNs = 0;
        double cpuMs = 0.0;
        int calls = 0;
    };
    struct Pending {
        size_t stage;
        unsigned int query;
    };

    size_t stageIndex(const std::string& name);
    unsigned int acquireQuery();
    void collectPending();

    bool gpu_ = false;
    std::vector<Stage> stages_;
    std::vector<Pending> pending_;
    std::vector<unsigned int> freeQueries_;
    std::vector<unsigned int> allQueries_;
    bool open_ = false;
    size_t openStage_ = 0;
    std::chrono::steady_clock::time_point openedAt_;
    std::function<void(const std::string&)> listener_;
};

}  // namespace eikon
