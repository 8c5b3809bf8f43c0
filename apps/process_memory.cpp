#include "apps/process_memory.h"

#include <malloc.h>

#include <cstddef>

#include <fstream>
#include <sstream>
#include <string>

#if defined(__SANITIZE_ADDRESS__)
// AddressSanitizer's allocator replaces malloc's, and mallinfo2 reads zeros there: ask it
// (declared in compiler-rt's sanitizer/allocator_interface.h, which GCC does not ship).
extern "C" std::size_t __sanitizer_get_current_allocated_bytes();
#endif

namespace eikon::app {

ProcessMemory readProcessMemory() {
    ProcessMemory m;
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        std::istringstream fields(line);
        std::string key;
        std::int64_t kib = -1;
        if (!(fields >> key >> kib)) continue;
        if (key == "VmRSS:") m.rssKib = kib;
        if (key == "VmHWM:") m.hwmKib = kib;
        if (key == "RssAnon:") m.rssAnonKib = kib;
    }
#if defined(__SANITIZE_ADDRESS__)
    m.heapInUseKib = std::int64_t(__sanitizer_get_current_allocated_bytes() / 1024);
#elif defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
    const struct mallinfo2 info = mallinfo2();
    m.heapInUseKib = std::int64_t((info.uordblks + info.hblkhd) / 1024);
#endif
    return m;
}

}  // namespace eikon::app
