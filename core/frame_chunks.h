#pragma once
// Splitting the frames of a render into chunks, one per farm task (`eikon render --chunk K/N`):
// contiguous runs of the ordered frame list, as even as possible (sizes differ by at most one), so
// that N tasks together render every frame exactly once. A chunk may be empty when there are more
// chunks than frames.
#include <functional>
#include <string>
#include <vector>

namespace eikon {

constexpr int kMaxChunks = 1000000;

struct FrameChunk {
    int index = 1;  // 1..count
    int count = 1;
};

// "K/N" (1 <= K <= N <= kMaxChunks), or "auto": K and N from a Slurm job array's environment,
// read through `env` (std::getenv in the program): K = (SLURM_ARRAY_TASK_ID −
// SLURM_ARRAY_TASK_MIN) / SLURM_ARRAY_TASK_STEP + 1 (step 1 when unset), N =
// SLURM_ARRAY_TASK_COUNT. Throws eikon::Error at "--chunk" naming what is wrong or missing.
FrameChunk parseFrameChunk(const std::string& text,
                           const std::function<const char*(const char*)>& env);

// Chunk `chunk` of `frames`: frames[floor((K−1)·F/N) .. floor(K·F/N)), F = frames.size().
std::vector<int> framesOfChunk(const std::vector<int>& frames, FrameChunk chunk);

// "chunk 2/3: frames 4-6" or "chunk 4/5: no frames (5 chunks of 3 frames)", for the log.
std::string describeChunk(const std::vector<int>& all, FrameChunk chunk);

}  // namespace eikon
