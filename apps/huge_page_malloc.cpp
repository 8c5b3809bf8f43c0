#include "apps/huge_page_malloc.h"

#include <cstdlib>
#include <cstring>
#include <string>

#include <unistd.h>

// Why: every stage allocates volumes of megabytes for each frame (resampled fields, ∇n, the
// octree's temporaries, the photon volumes, their smoothing), and on 4 KiB pages each first touch
// is a page fault, about 10 µs in the VM this was measured in. `eikon render` of
// glass_sphere_fog.json at 128³ took 2.13 s, 1.16 s with the tunable (∇n 140 → 35 ms, octree
// 750 → 300 ms; BENCHMARKS.md). The tunable is read by the dynamic loader before main, hence the
// restart; its price is loading the program twice (tens of milliseconds).
#if defined(__SANITIZE_ADDRESS__)
#define EIKON_MALLOC_REPLACED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define EIKON_MALLOC_REPLACED 1
#endif
#endif

namespace eikon::app {

void restartWithHugePageMalloc(char** argv) {
#ifndef EIKON_MALLOC_REPLACED
    constexpr const char* kTunable = "glibc.malloc.hugetlb=1";
    if (std::getenv("EIKON_NO_HUGE_PAGES")) return;
    const char* existing = std::getenv("GLIBC_TUNABLES");
    if (existing && std::strstr(existing, "glibc.malloc.hugetlb")) return;  // set, or the user's
    const std::string tunables =
        existing && *existing ? std::string(existing) + ":" + kTunable : std::string(kTunable);
    if (setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0) return;
    execv("/proc/self/exe", argv);
    // Still here: the exec failed (no /proc); go on with small pages, the tunable left set for
    // the children.
#else
    (void)argv;
#endif
}

}  // namespace eikon::app
