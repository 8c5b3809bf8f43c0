#pragma once
// Runs a program as a child process in a process group of its own, its output (stdout and
// stderr) appended to a log file, killed with its children when it outlives a timeout. Used by
// `eikon regress` to run each case's eikon commands: a case that crashes or hangs is reported
// and the other cases go on.
#include <string>
#include <vector>

namespace eikon::app {

struct ProcessResult {
    int exitCode = -1;      // the exit status when it exited
    int signal = 0;         // the signal that ended it, else 0
    bool timedOut = false;  // killed by us after the timeout
    double seconds = 0.0;

    bool succeeded() const { return signal == 0 && !timedOut && exitCode == 0; }
    // "exit status 1", "killed by signal 11 (Segmentation fault)", "timed out after 600 s".
    std::string describe(int timeoutSeconds) const;
};

// `argv[0]` is the program's path. Throws eikon::Error when the log cannot be opened or the
// program cannot be started.
ProcessResult runProcess(const std::vector<std::string>& argv, const std::string& logPath,
                         int timeoutSeconds);

// This program's own path (/proc/self/exe resolved), to run it again as a child.
std::string selfExecutable();

}  // namespace eikon::app
