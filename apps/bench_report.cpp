#include "apps/bench_report.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <thread>

#include <tbb/info.h>

#include "core/error.h"

#ifndef EIKON_BUILD_TYPE
#define EIKON_BUILD_TYPE "unknown"
#endif

namespace eikon::app {
namespace {

std::string& commandLineStore() {
    static std::string line;
    return line;
}

std::string firstLineWith(const char* path, const std::string& key) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line))
        if (line.compare(0, key.size(), key) == 0) return line;
    return "";
}

std::string afterColon(const std::string& line) {
    const auto colon = line.find(':');
    if (colon == std::string::npos) return line;
    std::size_t start = colon + 1;
    while (start < line.size() && line[start] == ' ') ++start;
    return line.substr(start);
}

}  // namespace

std::string joinCommandLine(int argc, char** argv) {
    std::string out;
    for (int i = 0; i < argc; ++i) {
        const std::string arg = argv[i];
        if (i > 0) out += ' ';
        if (arg.find_first_of(" '\"\t") == std::string::npos && !arg.empty()) {
            out += arg;
            continue;
        }
        out += '\'';
        for (char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
        out += '\'';
    }
    return out;
}

const std::string& benchCommandLine() {
    return commandLineStore();
}

void setBenchCommandLine(std::string line) {
    commandLineStore() = std::move(line);
}

void printBenchHeader(std::FILE* out, int threads) {
    std::fprintf(out, "# command: %s\n", benchCommandLine().c_str());
    const std::string model = afterColon(firstLineWith("/proc/cpuinfo", "model name"));
    std::fprintf(out, "# machine: %u hardware threads, %s\n", std::thread::hardware_concurrency(),
                 model.empty() ? "unknown CPU" : model.c_str());
    std::ifstream loadavg("/proc/loadavg");
    std::string l1, l5, l15;
    if (loadavg >> l1 >> l5 >> l15)
        std::fprintf(out, "# load average at start: %s %s %s (1, 5, 15 min)\n", l1.c_str(),
                     l5.c_str(), l15.c_str());
    std::fprintf(out, "# build: %s%s\n", EIKON_BUILD_TYPE,
#ifdef NDEBUG
                 ""
#else
                 " (assertions on: not for timing)"
#endif
    );
    std::fprintf(out, "# threads: %d (TBB)%s\n",
                 threads > 0 ? threads : tbb::info::default_concurrency(),
                 threads > 0 ? ", capped by --threads" : "");
}

std::unique_ptr<tbb::global_control> limitThreads(int threads) {
    if (threads <= 0) return nullptr;
    return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                 std::size_t(threads));
}

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ','))
        if (!item.empty()) out.push_back(item);
    return out;
}

std::vector<int> parseSizeList(const std::string& text, const char* option) {
    std::vector<int> values;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        std::size_t used = 0;
        int v = 0;
        try {
            v = std::stoi(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != item.size() || v < 1)
            throw Error(option,
                        "expected positive integers separated by commas, got '" + text + "'");
        values.push_back(v);
    }
    if (values.empty()) throw Error(option, "expected at least one value");
    return values;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t m = values.size() / 2;
    return values.size() % 2 ? values[m] : 0.5 * (values[m - 1] + values[m]);
}

}  // namespace eikon::app
