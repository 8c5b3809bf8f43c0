#include "core/log.h"

#include <cstdio>
#include <mutex>

namespace eikon {
namespace {

std::mutex& sinkMutex() {
    static std::mutex m;
    return m;
}

LogSink& currentSink() {
    static LogSink sink;
    return sink;
}

void emit(LogLevel level, const std::string& message) {
    std::lock_guard<std::mutex> lock(sinkMutex());
    if (currentSink()) {
        currentSink()(level, message);
        return;
    }
    std::fprintf(stderr, "%s%s\n", level == LogLevel::Warning ? "warning: " : "", message.c_str());
}

}  // namespace

void setLogSink(LogSink sink) {
    std::lock_guard<std::mutex> lock(sinkMutex());
    currentSink() = std::move(sink);
}

void logInfo(const std::string& message) {
    emit(LogLevel::Info, message);
}
void logWarning(const std::string& message) {
    emit(LogLevel::Warning, message);
}

ScopedWarningCapture::ScopedWarningCapture() {
    std::lock_guard<std::mutex> lock(sinkMutex());
    previous_ = currentSink();
    currentSink() = [this](LogLevel level, const std::string& message) {
        if (level == LogLevel::Warning) warnings_.push_back(message);
    };
}

ScopedWarningCapture::~ScopedWarningCapture() {
    setLogSink(previous_);
}

bool ScopedWarningCapture::contains(const std::string& fragment) const {
    for (const auto& w : warnings_)
        if (w.find(fragment) != std::string::npos) return true;
    return false;
}

}  // namespace eikon
