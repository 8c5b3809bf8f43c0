#pragma once
// What `eikon render` says while it works, on stderr, so that stdout keeps only results:
// - after each frame of a render of several, one plain line,
//     frame 3/24 (0003) 1.21 s; elapsed 3.6 s, about 25.4 s left
//   the same whether stderr is a terminal, a file or a pipe (logs stay parseable);
// - on a terminal only, during a frame, a status line redrawn in place every quarter second with
//   the stage the renderer is in and the frame's time so far, so a long frame is not silent;
//   it is erased before anything else is printed.
// Quiet: nothing (errors and warnings still reach stderr through their own paths).
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <string>
#include <thread>

namespace eikon::app {

class RenderProgress {
public:
    // `interactive`: stderr is a terminal (isatty), the status line is drawn.
    RenderProgress(size_t frames, bool quiet, bool interactive);
    ~RenderProgress();
    RenderProgress(const RenderProgress&) = delete;
    RenderProgress& operator=(const RenderProgress&) = delete;

    // Frame `frame` (the index-th of those rendered, from 0) begins.
    void startFrame(size_t index, int frame);
    // The renderer entered `stage` (render/gpu_timer.h listener).
    void stage(const std::string& name);
    // The frame's picture is ready: the status line is erased (the caller prints next).
    void pictureDone();
    // The frame's files are written: its line, with the elapsed and remaining time.
    void endFrame();

private:
    void tick();            // the status line thread
    void drawStatusLine();  // with mutex_ held
    void eraseStatusLine();

    const size_t frames_;
    const bool quiet_;
    const bool interactive_;
    using Clock = std::chrono::steady_clock;
    Clock::time_point start_ = Clock::now();
    Clock::time_point frameStart_;
    size_t index_ = 0;
    int frame_ = 0;

    std::mutex mutex_;
    std::condition_variable wake_;
    std::string stage_;
    bool drawing_ = false;  // a frame is under way and its status line is shown
    bool stop_ = false;
    std::thread ticker_;
};

}  // namespace eikon::app
