#include "render/transport/photons/deposit_buffers_cpu.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>

#include <sys/mman.h>

namespace eikon {

DepositBuffersCpu::DepositBuffersCpu(size_t sums, int threads, size_t ownBudgetBytes)
    : sums_(sums) {
    static_assert(std::atomic<int64_t>::is_always_lock_free &&
                  sizeof(std::atomic<int64_t>) == sizeof(int64_t));
    if (threads <= 0) threads = tbb::this_task_arena::max_concurrency();
    const size_t bytes = std::max<size_t>(sums_ * sizeof(int64_t), 1);
    own_.assign(std::min<size_t>(size_t(std::max(threads, 1)), ownBudgetBytes / bytes), nullptr);
}

DepositBuffersCpu::~DepositBuffersCpu() {
    for (uint64_t* own : own_) std::free(own);
    std::free(shared_);
}

// A volume, zeroed, on 2 MiB pages where the kernel gives them (transparent huge pages on
// request: `madvise` is Debian's default). Zeroing one on 4 KiB pages took 31-46 ms at 64³
// (12.6 MB, 3,000 page faults in this VM), a quarter of the photon stage at 64 photons a side; a
// huge page is one fault. Without them (another kernel setting) it is the same memory on small
// pages. A volume under one huge page stays on small pages: a huge page would be resident whole,
// most of it unused, once per thread. EIKON_NO_HUGE_PAGES keeps every volume on small pages, as it
// keeps malloc's (apps/huge_page_malloc.cpp). Zero bits are a zero std::atomic<int64_t>
// (lock-free) as well as a zero uint64_t.
void* DepositBuffersCpu::allocate() const {
    constexpr size_t kHugePage = size_t(2) << 20;
    const size_t bytes = std::max<size_t>(sums_ * sizeof(int64_t), 1);
    const bool huge = bytes >= kHugePage && !std::getenv("EIKON_NO_HUGE_PAGES");
    const size_t alignment = huge ? kHugePage : size_t(64);
    const size_t rounded = (bytes + alignment - 1) / alignment * alignment;
    void* memory = std::aligned_alloc(alignment, rounded);
    if (!memory) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    if (huge) madvise(memory, rounded, MADV_HUGEPAGE);  // advice: refused, small pages still work
#endif
    std::memset(memory, 0, bytes);
    return memory;
}

}  // namespace eikon
