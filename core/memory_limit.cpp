#include "core/memory_limit.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mutex>

#include <tbb/task_arena.h>

#include "core/error.h"
#include "core/printable.h"

namespace eikon {
namespace {

std::mutex g_mutex;
std::optional<MemoryLimit> g_set;  // setMemoryLimit's, which wins over the environment

// The memory this process may use: physical memory, or less under a cgroup's memory.max or an
// address-space rlimit.
MemoryLimit defaultLimit() {
    double usable = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
    std::string what = "this machine's " + formatBytes(usable);
    std::ifstream cgroup("/sys/fs/cgroup/memory.max");
    std::string word;
    if (cgroup >> word && word != "max") {
        const double bytes = std::strtod(word.c_str(), nullptr);
        if (bytes > 0.0 && bytes < usable) {
            usable = bytes;
            what = "this cgroup's memory.max " + formatBytes(usable);
        }
    }
    rlimit as{};
    if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY &&
        double(as.rlim_cur) < usable) {
        usable = double(as.rlim_cur);
        what = "the address-space limit (ulimit -v) " + formatBytes(usable);
    }
    return {0.75 * usable, "3/4 of " + what};
}

}  // namespace

std::optional<double> parseByteSize(const std::string& text) {
    const char* begin = text.c_str();
    char* end = nullptr;
    const double number = std::strtod(begin, &end);
    if (end == begin || !std::isfinite(number) || number <= 0.0) return std::nullopt;
    std::string unit(end);
    unit.erase(std::remove_if(unit.begin(), unit.end(), [](unsigned char c) { return c == ' '; }),
               unit.end());
    for (char& c : unit) c = char(std::toupper(static_cast<unsigned char>(c)));
    if (unit.size() > 1 && unit.back() == 'B') unit.pop_back();  // "GB", "GiB" -> "G", "GI"
    if (unit.size() == 2 && unit[1] == 'I') unit.pop_back();
    static const std::string kUnits = "KMGT";
    double scale = 1.0;
    if (!unit.empty() && unit != "B") {
        const std::size_t power = kUnits.find(unit);
        if (unit.size() != 1 || power == std::string::npos) return std::nullopt;
        scale = std::ldexp(1.0, 10 * int(power + 1));
    }
    const double bytes = number * scale;
    if (!std::isfinite(bytes) || bytes < 1.0) return std::nullopt;
    return bytes;
}

std::string formatBytes(double bytes) {
    static const char* const kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    int unit = 0;
    while (bytes >= 1024.0 && unit < 6) {
        bytes /= 1024.0;
        ++unit;
    }
    char text[48];
    std::snprintf(text, sizeof(text), unit == 0 || bytes >= 100.0 ? "%.0f %s" : "%.3g %s", bytes,
                  kUnits[unit]);
    return text;
}

MemoryLimit memoryLimit() {
    {
        std::lock_guard<std::mutex> lock(g_mutex);
        if (g_set) return *g_set;
    }
    if (const char* env = std::getenv("EIKON_MEMORY_LIMIT"); env && *env) {
        const std::optional<double> bytes = parseByteSize(env);
        if (!bytes)
            throw Error("EIKON_MEMORY_LIMIT",
                        "expected a size such as 512M, 8G or 8GiB, got \"" + printable(env) + "\"");
        return {*bytes, "EIKON_MEMORY_LIMIT"};
    }
    return defaultLimit();
}

void setMemoryLimit(double bytes, const std::string& origin) {
    std::lock_guard<std::mutex> lock(g_mutex);
    g_set = MemoryLimit{bytes, origin};
}

void resetMemoryLimit() {
    std::lock_guard<std::mutex> lock(g_mutex);
    g_set.reset();
}

void checkMemory(const std::string& where, double bytes, const std::string& what,
                 const std::string& advice) {
    const MemoryLimit limit = memoryLimit();
    if (bytes <= limit.bytes) return;
    throw Error(where, what + " needs about " + formatBytes(bytes) +
                           ", over eikon's memory limit of " + formatBytes(limit.bytes) + " (" +
                           limit.origin + "); " + advice +
                           ", or raise the limit with --memory-limit or EIKON_MEMORY_LIMIT");
}

double renderVolumeBytes(double voxels) {
    const double otherThreads = double(std::max(tbb::this_task_arena::max_concurrency() - 1, 0));
    return voxels * kRenderBytesPerVoxel +
           std::min(otherThreads * voxels * kDepositBytesPerVoxel, kThreadDepositBudget);
}

}  // namespace eikon
