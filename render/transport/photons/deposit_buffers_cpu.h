#pragma once
// Where a CPU particle trace's voxel deposits go: one plain 64-bit integer volume per thread,
// summed when the trace is read, and a shared volume of atomics for the threads beyond the memory
// budget. Integer addition is exact and commutes, so any split of the deposits among the volumes
// gives the same sums, bit for bit, as one shared volume did.
//
// Why not only the shared atomics: the photon march at 128³ spent 43 % of its time in the
// deposits, three quarters of that stalled on the first `lock add` of a cell. A locked
// instruction on x86 waits for its cache line and holds every later load behind it, so no
// deposit's miss overlaps the march's other work. A thread's own volume takes plain adds, whose
// misses the processor overlaps (BENCHMARKS.md, "Deposits per thread").
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include <tbb/task_arena.h>

#include "core/memory_limit.h"

namespace eikon {

class DepositBuffersCpu {
public:
    // The threads' own volumes may take this much memory together; the threads beyond it add
    // into the shared atomics. At 128³ a volume is 100 MB (6 sums a voxel): ten threads. The
    // memory check counts them (core/memory_limit.h, renderVolumeBytes).
    static constexpr size_t kOwnBudgetBytes = size_t(kThreadDepositBudget);

    // `sums`: the int64 sums of one volume (voxels × channels). `threads`: how many threads may
    // deposit at once (the calling arena's concurrency when 0). `ownBudgetBytes`: what the
    // threads' own volumes may take together.
    explicit DepositBuffersCpu(size_t sums, int threads = 0,
                               size_t ownBudgetBytes = kOwnBudgetBytes);
    ~DepositBuffersCpu();
    DepositBuffersCpu(const DepositBuffersCpu&) = delete;
    DepositBuffersCpu& operator=(const DepositBuffersCpu&) = delete;

    // Adds `count` values at sum index `first`: plain adds into the calling thread's own volume
    // (made, zeroed, on its first deposit), or atomic adds into the shared one. Unsigned
    // arithmetic, as std::atomic's: a sum wraps instead of being undefined, the same on both paths.
    void add(size_t first, const int64_t* values, int count) {
        if (uint64_t* own = threadVolume()) {
            for (int c = 0; c < count; ++c) own[first + size_t(c)] += uint64_t(values[c]);
            return;
        }
        std::atomic<int64_t>* cell = sharedVolume() + first;
        for (int c = 0; c < count; ++c) cell[c].fetch_add(values[c], std::memory_order_relaxed);
    }

    // Sum index i over every volume; call when no thread deposits any more.
    int64_t sum(size_t i) const {
        uint64_t total = shared_ ? uint64_t(shared_[i].load(std::memory_order_relaxed)) : 0;
        for (const uint64_t* own : own_)
            if (own) total += own[i];
        return int64_t(total);
    }

    // How many threads may have a volume of their own (the budget's share; the rest share the
    // atomics). Each is made on its thread's first deposit.
    int ownVolumes() const { return int(own_.size()); }

private:
    // The calling thread's volume, by its slot in the task arena (unique among the threads in it
    // at any moment, and a slot is held for a whole task); null past the budget or outside TBB.
    uint64_t* threadVolume() {
        const int slot = tbb::this_task_arena::current_thread_index();
        if (slot < 0 || slot >= int(own_.size())) return nullptr;
        uint64_t*& volume = own_[size_t(slot)];
        if (!volume) volume = static_cast<uint64_t*>(allocate());
        return volume;
    }
    std::atomic<int64_t>* sharedVolume() {
        std::call_once(sharedOnce_,
                       [this] { shared_ = static_cast<std::atomic<int64_t>*>(allocate()); });
        return shared_;
    }
    void* allocate() const;  // sums_ int64s, zeroed

    size_t sums_ = 0;
    std::vector<uint64_t*> own_;  // one slot per thread within the budget; null until it deposits
    std::atomic<int64_t>* shared_ = nullptr;
    std::once_flag sharedOnce_;
};

}  // namespace eikon
