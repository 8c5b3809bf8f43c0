#pragma once
// A mark that an `eikon simulate` run is writing a cache: "<dir>/<name>.simulating" beside
// <name>_####.vdb, holding the run's process id, its frame range and the last frame it finished.
// Every frame file is written atomically, so each one is complete; but a run killed (kill -9, a
// power cut) after frame 5 of 12 over an older cache leaves frames 1-5 new and 6-12 old, a
// cache that mixes two runs and looks whole. The run removes its mark when it ends (after
// removing, on a handled failure, the later frames of earlier runs), so a mark whose process is
// gone says the cache is mixed, and from which frame: a "vdb_sequence" source refuses it
// (core/vdb_sequence.cpp) and the next `eikon simulate` says so.
#include <optional>
#include <string>

namespace eikon {

struct CacheRunMarker {
    long pid = 0;
    // The process's start time (clock ticks after boot, /proc/<pid>/stat): with the pid, it
    // names one process, so a later process given the same pid is not taken for the run.
    unsigned long long started = 0;
    int firstFrame = 0;  // the frames the run was to write
    int lastFrame = 0;
    int finishedThrough = 0;  // every frame up to this one is written (firstFrame − 1: none)
};

// "<directory>/<cacheName>.simulating".
std::string cacheRunMarkerPath(const std::string& directory, const std::string& cacheName);

// Writes the mark atomically (core/atomic_write.h); throws eikon::Error naming the path.
void writeCacheRunMarker(const std::string& path, const CacheRunMarker& marker);
// The mark at `path`, or nullopt when there is none or it is not one of ours.
std::optional<CacheRunMarker> readCacheRunMarker(const std::string& path);
void removeCacheRunMarker(const std::string& path);

// A mark for this process: its pid and start time, with the frames given.
CacheRunMarker thisRunMarker(int firstFrame, int lastFrame, int finishedThrough);

// Whether the run that wrote the mark is still running: its process exists, started when the
// mark says, and is not a zombie (a killed run whose parent has not reaped it is not running).
bool cacheRunIsAlive(const CacheRunMarker& marker);

// "frames 6-12 may be from an earlier run": what a stopped run's mark says about its cache.
std::string stoppedRunText(const CacheRunMarker& marker);

}  // namespace eikon
