#pragma once
// Playing a scene in the viewer without the simulation waiting for the view: a thread of its own
// steps the scene's frames (SceneDriver::frameInputs: live smoke, water, jellies, keyframes) one
// after another, while the viewer renders whichever frame is ready. Frames the viewer had no time
// to show are merged into the next (their meshes and fields replaced by the later ones'; the
// renderer keeps what it was given), so nothing the renderer needs is lost and at most one
// frame's inputs wait. While it runs, only its thread calls the driver.
//
// With a count (a scripted run, --exit-after) it steps in lockstep instead: one frame ahead of the
// one taken, and that many frames, so a script shows every frame once, in order, and the counts
// it prints are the same on every run.
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "pipeline/scene_driver.h"

namespace eikon {

class SimulationAhead {
public:
    SimulationAhead(SceneDriver& driver, const Scene& scene);
    ~SimulationAhead();  // stops the thread
    SimulationAhead(const SimulationAhead&) = delete;
    SimulationAhead& operator=(const SimulationAhead&) = delete;

    // Starts stepping from `frame` (after the scene's last frame, its first again). With
    // `count` ≥ 0: in lockstep, that many frames.
    void start(int frame, int count = -1);
    // Stops once the frame being stepped is done; what is stepped and not taken stays for take().
    void stop();
    bool running() const { return thread_.joinable(); }

    // The frames stepped since the last take, merged: the latest frame's number and scene, the
    // meshes and fields they gave. Nothing when none is ready; with `wait`, waits for one unless
    // stopped with none left. Rethrows what stepping threw (eikon::Error).
    std::optional<FrameInputs> take(bool wait);

private:
    void run();

    SceneDriver& driver_;
    const Scene& scene_;
    std::thread thread_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::optional<FrameInputs> ready_;
    std::exception_ptr failure_;
    int next_ = 0;
    int left_ = -1;  // frames still to step in lockstep; −1: free running
    bool stopping_ = false;
};

// `newer` merged into `older`: newer's frame and scene, older's meshes and fields replaced by
// newer's of the same index or name and kept otherwise.
void mergeFrameInputs(FrameInputs& older, FrameInputs&& newer);

}  // namespace eikon
