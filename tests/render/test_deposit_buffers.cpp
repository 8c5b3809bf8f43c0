// The CPU particle traces' deposit volumes (render/transport/photons/deposit_buffers_cpu.h): a
// thread's own plain volume, the shared atomics past the memory budget, and their sums, which
// must equal one serial sum bit for bit however the deposits were split.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "render/transport/photons/deposit_buffers_cpu.h"

using namespace eikon;

namespace {

constexpr size_t kSums = 6 * 1000;
constexpr int kDeposits = 200000;

// Deposit k: 6 values at a cell drawn by a hash, some near the int64 limits so that partial sums
// wrap (the totals are still exact modulo 2^64, as std::atomic's are).
void depositValues(int k, size_t& first, int64_t (&values)[6]) {
    uint64_t h = uint64_t(k) * 0x9E3779B97F4A7C15ull;
    h ^= h >> 29;
    first = size_t(h % (kSums / 6)) * 6;
    for (int c = 0; c < 6; ++c) {
        h = h * 6364136223846793005ull + 1442695040888963407ull;
        values[c] = (k % 97 == 0) ? int64_t(h) : int64_t(h >> 40) - (int64_t(1) << 23);
    }
}

std::vector<uint64_t> serialSums() {
    std::vector<uint64_t> sums(kSums, 0);
    for (int k = 0; k < kDeposits; ++k) {
        size_t first;
        int64_t values[6];
        depositValues(k, first, values);
        for (int c = 0; c < 6; ++c) sums[first + size_t(c)] += uint64_t(values[c]);
    }
    return sums;
}

// The deposits in parallel in an arena of `threads`, into volumes with the given budget.
std::vector<uint64_t> parallelSums(int threads, size_t budget, int& ownVolumes) {
    std::vector<uint64_t> sums(kSums, 0);
    tbb::task_arena(threads).execute([&] {
        DepositBuffersCpu buffers(kSums, 0, budget);
        ownVolumes = buffers.ownVolumes();
        tbb::parallel_for(tbb::blocked_range<int>(0, kDeposits, 64),
                          [&](const tbb::blocked_range<int>& r) {
                              for (int k = r.begin(); k != r.end(); ++k) {
                                  size_t first;
                                  int64_t values[6];
                                  depositValues(k, first, values);
                                  buffers.add(first, values, 6);
                              }
                          });
        for (size_t i = 0; i < kSums; ++i) sums[i] = uint64_t(buffers.sum(i));
    });
    return sums;
}

}  // namespace

TEST_CASE("deposit volumes sum to the serial sums, own volumes, shared atomics or both",
          "[photons][deposits]") {
    const std::vector<uint64_t> expected = serialSums();
    const size_t volume = kSums * sizeof(int64_t);
    struct Case {
        int threads;
        size_t budget;
        int ownVolumes;
    };
    // Every thread its own volume; one of four (the rest share the atomics); none (all atomics).
    for (const Case& c :
         {Case{1, volume, 1}, Case{4, 4 * volume, 4}, Case{4, volume, 1}, Case{3, volume - 1, 0}}) {
        INFO(c.threads << " threads, a budget of " << c.budget << " bytes");
        int ownVolumes = -1;
        const std::vector<uint64_t> sums = parallelSums(c.threads, c.budget, ownVolumes);
        CHECK(ownVolumes == c.ownVolumes);
        CHECK(sums == expected);
    }
}

TEST_CASE("deposit volumes read zero where nothing was deposited", "[photons][deposits]") {
    DepositBuffersCpu buffers(12);
    for (size_t i = 0; i < 12; ++i) CHECK(buffers.sum(i) == 0);
    const int64_t one[2] = {1, -1};
    buffers.add(4, one, 2);  // from this thread: its own volume or, outside an arena, the shared
    CHECK(buffers.sum(4) == 1);
    CHECK(buffers.sum(5) == -1);
    CHECK(buffers.sum(3) == 0);
}
