#include "pipeline/simulation_ahead.h"

#include <utility>

namespace eikon {

void mergeFrameInputs(FrameInputs& older, FrameInputs&& newer) {
    older.frame = newer.frame;
    older.scene = std::move(newer.scene);
    for (auto& [index, mesh] : newer.meshes) {
        bool replaced = false;
        for (auto& [i, m] : older.meshes)
            if (i == index) m = std::move(mesh), replaced = true;
        if (!replaced) older.meshes.emplace_back(index, std::move(mesh));
    }
    for (const std::string& name : newer.fields.names()) {
        const Field& f = newer.fields.get(name);
        older.fields.set(name, f.grid, f.origin);
    }
}

SimulationAhead::SimulationAhead(SceneDriver& driver, const Scene& scene)
    : driver_(driver), scene_(scene) {}

SimulationAhead::~SimulationAhead() {
    stop();
}

void SimulationAhead::start(int frame, int count) {
    stop();
    std::lock_guard<std::mutex> lock(mutex_);
    next_ = frame;
    left_ = count;
    stopping_ = false;
    thread_ = std::thread([this] { run(); });
}

void SimulationAhead::stop() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    if (thread_.joinable()) thread_.join();
}

void SimulationAhead::run() {
    const TimeSettings& time = scene_.time;
    while (true) {
        int frame = 0;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            // Lockstep: one frame ahead of the one taken, and only the frames asked for.
            changed_.wait(lock, [&] { return stopping_ || left_ < 0 || !ready_; });
            if (stopping_ || left_ == 0) break;
            if (left_ > 0) --left_;
            frame = next_;
            next_ = frame >= time.frameEnd ? time.frameStart : frame + 1;
        }
        try {
            FrameInputs inputs = driver_.frameInputs(frame, scene_);
            std::lock_guard<std::mutex> lock(mutex_);
            if (ready_)
                mergeFrameInputs(*ready_, std::move(inputs));
            else
                ready_ = std::move(inputs);
        } catch (...) {
            std::lock_guard<std::mutex> lock(mutex_);
            failure_ = std::current_exception();
            stopping_ = true;
        }
        changed_.notify_all();
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;  // take(wait) must not wait for a thread that has ended
    }
    changed_.notify_all();
}

std::optional<FrameInputs> SimulationAhead::take(bool wait) {
    std::unique_lock<std::mutex> lock(mutex_);
    if (wait) changed_.wait(lock, [&] { return ready_.has_value() || stopping_ || failure_; });
    if (failure_) {
        std::exception_ptr failure = failure_;
        failure_ = nullptr;
        std::rethrow_exception(failure);
    }
    std::optional<FrameInputs> out = std::move(ready_);
    ready_.reset();
    lock.unlock();
    changed_.notify_all();  // lockstep: the next frame may be stepped
    return out;
}

}  // namespace eikon
