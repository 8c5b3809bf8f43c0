#pragma once
// Parallel loops whose results do not depend on the thread count (docs/architecture.md,
// "Determinism"): cells are split into z-slabs where each cell's result is independent, and sums
// are taken per fixed-size block and then added serially in block order, so that the rounding is
// the same whatever TBB's partitioner chooses.
#include <algorithm>
#include <cstddef>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace eikon::sim {

// Calls fn(k) for every slab k in [0, nz), in parallel. fn must only write to its own slab.
template <typename Fn>
void forEachSlab(int nz, const Fn& fn) {
    tbb::parallel_for(tbb::blocked_range<int>(0, nz), [&](const tbb::blocked_range<int>& r) {
        for (int k = r.begin(); k != r.end(); ++k) fn(k);
    });
}

// Calls fn(i) for every i in [0, n), in parallel; each i must be independent of the others.
template <typename Fn>
void forEachIndex(std::size_t n, const Fn& fn) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) fn(i);
                      });
}

// Σ term(i) for i in [0, n), in double, with a fixed summation order.
template <typename Term>
double deterministicSum(std::size_t n, const Term& term) {
    // 4096 terms per block: enough work per task, few enough blocks that the serial pass is cheap.
    constexpr std::size_t kBlock = 4096;
    const std::size_t blocks = (n + kBlock - 1) / kBlock;
    std::vector<double> partial(blocks, 0.0);
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
        const std::size_t end = std::min(n, (b + 1) * kBlock);
        double s = 0.0;
        for (std::size_t i = b * kBlock; i < end; ++i) s += term(i);
        partial[b] = s;
    });
    double total = 0.0;
    for (double s : partial) total += s;
    return total;
}

}  // namespace eikon::sim
