#include "core/cache_run_marker.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "core/atomic_write.h"

namespace eikon {

std::string cacheRunMarkerPath(const std::string& directory, const std::string& cacheName) {
    return (std::filesystem::path(directory) / (cacheName + ".simulating")).string();
}

void writeCacheRunMarker(const std::string& path, const CacheRunMarker& m) {
    writeAtomically(path, [&](const std::string& partial) {
        std::ofstream out(partial, std::ios::trunc);
        out << "eikon simulate run\npid " << m.pid << "\nstarted " << m.started << "\nframes "
            << m.firstFrame << " " << m.lastFrame << "\nfinished_through " << m.finishedThrough
            << "\n";
        out.close();
        if (!out) throw Error(path, "could not write the run's mark");
    });
}

std::optional<CacheRunMarker> readCacheRunMarker(const std::string& path) {
    std::ifstream in(path);
    if (!in) return std::nullopt;
    std::string title;
    std::getline(in, title);
    if (title != "eikon simulate run") return std::nullopt;
    CacheRunMarker m;
    std::string pid, started, frames, finished;
    if (!(in >> pid >> m.pid >> started >> m.started >> frames >> m.firstFrame >> m.lastFrame >>
          finished >> m.finishedThrough) ||
        pid != "pid" || started != "started" || frames != "frames" ||
        finished != "finished_through" || m.pid <= 0)
        return std::nullopt;
    return m;
}

void removeCacheRunMarker(const std::string& path) {
    std::error_code ec;
    std::filesystem::remove(path, ec);
    syncFolderToDisk(std::filesystem::path(path).parent_path());
}

namespace {

struct ProcessState {
    char state = 0;                // R, S, D, Z, ...
    unsigned long long start = 0;  // field 22 of /proc/<pid>/stat
};

std::optional<ProcessState> processState(long pid) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!std::getline(in, line)) return std::nullopt;
    // "pid (comm) state ...": comm may hold spaces and parentheses, so parse after the last ')'.
    const std::size_t close = line.rfind(')');
    if (close == std::string::npos) return std::nullopt;
    std::istringstream rest(line.substr(close + 1));
    ProcessState s;
    rest >> s.state;
    std::string field;
    for (int f = 4; f < 22 && rest >> field; ++f) {
    }
    if (!(rest >> s.start)) return std::nullopt;
    return s;
}

}  // namespace

CacheRunMarker thisRunMarker(int firstFrame, int lastFrame, int finishedThrough) {
    CacheRunMarker m;
    m.pid = long(getpid());
    if (const auto self = processState(m.pid)) m.started = self->start;
    m.firstFrame = firstFrame;
    m.lastFrame = lastFrame;
    m.finishedThrough = finishedThrough;
    return m;
}

bool cacheRunIsAlive(const CacheRunMarker& marker) {
    const std::optional<ProcessState> s = processState(marker.pid);
    return s && s->state != 'Z' && s->state != 'X' && s->start == marker.started;
}

std::string stoppedRunText(const CacheRunMarker& m) {
    std::ostringstream text;
    text << "an eikon simulate run into this cache (pid " << m.pid << ", frames " << m.firstFrame
         << "-" << m.lastFrame << ") did not finish: ";
    if (m.finishedThrough >= m.firstFrame)
        text << "frames " << m.firstFrame << "-" << m.finishedThrough << " are complete, ";
    else
        text << "no frame is complete, ";
    const int from = std::max(m.finishedThrough + 1, m.firstFrame);
    text << "frames " << from << "-" << m.lastFrame << " may be from an earlier run";
    return text.str();
}

}  // namespace eikon
