#pragma once
// This process's memory as Linux reports it (/proc/self/status) and as glibc's allocator holds
// it (mallinfo2; AddressSanitizer's own count in an ASan build), for `eikon bench soak`: a long run
// shows a leak as growth after its warm-up.
#include <cstdint>

namespace eikon::app {

struct ProcessMemory {
    std::int64_t rssKib = -1;      // VmRSS: resident now (anonymous, file-backed and shared)
    std::int64_t hwmKib = -1;      // VmHWM: the most VmRSS has been
    std::int64_t rssAnonKib = -1;  // RssAnon: resident anonymous pages (heaps, not libraries)
    // Bytes glibc's malloc has handed out and not had back (arenas and mmapped blocks): what the
    // program holds through malloc/new, whatever the allocator keeps cached beside it.
    std::int64_t heapInUseKib = -1;
};

// -1 where the system does not say (no /proc).
ProcessMemory readProcessMemory();

}  // namespace eikon::app
