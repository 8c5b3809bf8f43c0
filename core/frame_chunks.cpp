#include "core/frame_chunks.h"

#include <cstdint>
#include <string>

#include "core/error.h"
#include "core/frame_list.h"

namespace eikon {
namespace {

const char* const kGrammar = "K/N (chunk K of N, 1 <= K <= N) or auto (from a Slurm job array)";

// A whole number in [lo, hi] from all of `text`, else nothing.
bool parseWhole(const std::string& text, long long lo, long long hi, long long& out) {
    if (text.empty() || text.size() > 10 ||
        text.find_first_not_of("0123456789") != std::string::npos)
        return false;
    out = std::stoll(text);
    return out >= lo && out <= hi;
}

long long slurmNumber(const std::function<const char*(const char*)>& env, const char* name,
                      bool required, long long fallback) {
    const char* value = env(name);
    if (!value || !*value) {
        if (!required) return fallback;
        throw Error("--chunk", std::string("auto reads a Slurm job array's ") + name +
                                   ", which is not set (not in a job array: sbatch --array=...; "
                                   "or give K/N)");
    }
    long long n = 0;
    if (!parseWhole(value, 0, 2147483647LL, n))
        throw Error("--chunk",
                    std::string("auto: ") + name + " is '" + value + "', not a whole number");
    return n;
}

std::string rangeText(const std::vector<int>& frames) {
    if (frames.empty()) return "none";
    std::string text = std::to_string(frames.front());
    if (frames.size() > 1)
        text += (isContiguous(frames) ? "-" : "..") + std::to_string(frames.back());
    return text;
}

}  // namespace

FrameChunk parseFrameChunk(const std::string& text,
                           const std::function<const char*(const char*)>& env) {
    FrameChunk chunk;
    if (text == "auto") {
        const long long id = slurmNumber(env, "SLURM_ARRAY_TASK_ID", true, 0);
        const long long count = slurmNumber(env, "SLURM_ARRAY_TASK_COUNT", true, 0);
        const long long min = slurmNumber(env, "SLURM_ARRAY_TASK_MIN", false, 0);
        const long long step = slurmNumber(env, "SLURM_ARRAY_TASK_STEP", false, 1);
        if (count < 1 || count > kMaxChunks || step < 1 || id < min || (id - min) % step != 0 ||
            (id - min) / step >= count)
            throw Error("--chunk", "auto: SLURM_ARRAY_TASK_ID " + std::to_string(id) +
                                       " is not one of the " + std::to_string(count) +
                                       " tasks from " + std::to_string(min) + " in steps of " +
                                       std::to_string(step));
        chunk.index = int((id - min) / step + 1);
        chunk.count = int(count);
        return chunk;
    }
    const size_t slash = text.find('/');
    long long k = 0, n = 0;
    if (slash == std::string::npos || !parseWhole(text.substr(slash + 1), 1, kMaxChunks, n) ||
        !parseWhole(text.substr(0, slash), 1, n, k))
        throw Error("--chunk", "expected " + std::string(kGrammar) + ", got '" + text + "'");
    chunk.index = int(k);
    chunk.count = int(n);
    return chunk;
}

std::vector<int> framesOfChunk(const std::vector<int>& frames, FrameChunk chunk) {
    const auto boundary = [&](int k) {
        return size_t(std::uint64_t(k) * frames.size() / std::uint64_t(chunk.count));
    };
    return std::vector<int>(frames.begin() + std::ptrdiff_t(boundary(chunk.index - 1)),
                            frames.begin() + std::ptrdiff_t(boundary(chunk.index)));
}

std::string describeChunk(const std::vector<int>& all, FrameChunk chunk) {
    const std::vector<int> mine = framesOfChunk(all, chunk);
    const std::string head =
        "chunk " + std::to_string(chunk.index) + "/" + std::to_string(chunk.count) + ": ";
    if (mine.empty())
        return head + "no frames (" + std::to_string(chunk.count) + " chunks of " +
               std::to_string(all.size()) + (all.size() == 1 ? " frame)" : " frames)");
    return head + (mine.size() == 1 ? "frame " : "frames ") + rangeText(mine) + " (" +
           std::to_string(mine.size()) + " of " + std::to_string(all.size()) + ")";
}

}  // namespace eikon
