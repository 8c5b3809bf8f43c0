#include "apps/render_progress.h"

#include <cstdio>

#include "core/log.h"

namespace eikon::app {
namespace {

double seconds(std::chrono::steady_clock::duration d) {
    return std::chrono::duration<double>(d).count();
}

// "3.6 s", "4 min 12 s", "1 h 05 min": short, and whole units once they are large.
std::string formatDuration(double s) {
    char text[48];
    if (s < 60.0)
        std::snprintf(text, sizeof(text), "%.1f s", s);
    else if (s < 3600.0)
        std::snprintf(text, sizeof(text), "%d min %02d s", int(s) / 60, int(s) % 60);
    else
        std::snprintf(text, sizeof(text), "%d h %02d min", int(s) / 3600, int(s) % 3600 / 60);
    return text;
}

}  // namespace

RenderProgress::RenderProgress(size_t frames, bool quiet, bool interactive)
    : frames_(frames), quiet_(quiet), interactive_(interactive && !quiet) {
    if (!interactive_) return;
    // A warning during a frame goes on its own line, and the status line comes back under it.
    setLogSink([this](LogLevel level, const std::string& message) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (drawing_) std::fputs("\r\033[K", stderr);
        std::fprintf(stderr, "%s%s\n", level == LogLevel::Warning ? "warning: " : "",
                     message.c_str());
        if (drawing_) drawStatusLine();
        std::fflush(stderr);
    });
    ticker_ = std::thread([this] { tick(); });
}

RenderProgress::~RenderProgress() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    if (ticker_.joinable()) ticker_.join();
    if (interactive_) setLogSink({});
    eraseStatusLine();
}

void RenderProgress::startFrame(size_t index, int frame) {
    std::lock_guard<std::mutex> lock(mutex_);
    index_ = index;
    frame_ = frame;
    frameStart_ = Clock::now();
    stage_ = "starting";
    drawing_ = interactive_;
    if (drawing_) drawStatusLine();
}

void RenderProgress::stage(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    stage_ = name;
    if (drawing_) drawStatusLine();
}

void RenderProgress::pictureDone() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (drawing_) {
        std::fputs("\r\033[K", stderr);
        std::fflush(stderr);
    }
    drawing_ = false;
}

void RenderProgress::endFrame() {
    pictureDone();
    if (quiet_ || frames_ < 2) return;
    const Clock::time_point now = Clock::now();
    const double elapsed = seconds(now - start_);
    const size_t done = index_ + 1;
    const double left = elapsed / double(done) * double(frames_ - done);
    std::fprintf(stderr, "frame %zu/%zu (%04d) %.2f s; elapsed %s, about %s left\n", done, frames_,
                 frame_, seconds(now - frameStart_), formatDuration(elapsed).c_str(),
                 formatDuration(left).c_str());
    std::fflush(stderr);
}

void RenderProgress::drawStatusLine() {
    char line[160];
    std::snprintf(line, sizeof(line), "\r\033[Kframe %zu/%zu (%04d): %s, %s", index_ + 1, frames_,
                  frame_, stage_.c_str(),
                  formatDuration(seconds(Clock::now() - frameStart_)).c_str());
    std::fputs(line, stderr);
    std::fflush(stderr);
}

void RenderProgress::eraseStatusLine() {
    if (!interactive_) return;
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
}

void RenderProgress::tick() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_) {
        wake_.wait_for(lock, std::chrono::milliseconds(250));
        if (!stop_ && drawing_) drawStatusLine();
    }
}

}  // namespace eikon::app
