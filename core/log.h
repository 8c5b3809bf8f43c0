#pragma once
// Warnings and progress go through one sink so that tests can capture them and the command line
// can print them; nothing in the libraries writes to stdout directly.
#include <functional>
#include <string>
#include <vector>

namespace eikon {

enum class LogLevel { Info, Warning };
using LogSink = std::function<void(LogLevel, const std::string&)>;

// Replaces the sink; an empty function restores the default (stderr, "warning: " prefix).
void setLogSink(LogSink sink);
void logInfo(const std::string& message);
void logWarning(const std::string& message);

// Collects warnings while alive (tests assert on them); restores the previous sink after.
class ScopedWarningCapture {
public:
    ScopedWarningCapture();
    ~ScopedWarningCapture();
    const std::vector<std::string>& warnings() const { return warnings_; }
    bool contains(const std::string& fragment) const;

private:
    std::vector<std::string> warnings_;
    LogSink previous_;
};

}  // namespace eikon
