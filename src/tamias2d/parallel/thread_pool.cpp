#include "tamias2d/parallel/thread_pool.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace tamias2d {

namespace {

// claim_: generation (20 bits) | item count (22 bits) | next item (22 bits).
constexpr int item_bits = 22;
constexpr std::uint64_t item_mask = (std::uint64_t{1} << item_bits) - 1;

std::uint64_t next_of(std::uint64_t c) {
    return c & item_mask;
}
std::uint64_t count_of(std::uint64_t c) {
    return (c >> item_bits) & item_mask;
}
std::uint64_t generation_of(std::uint64_t c) {
    return c >> (2 * item_bits);
}

void relax() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#endif
}

// A step's parallel loops come a few microseconds to a few hundred apart: a thread spins that
// long before it sleeps (a futex wake-up costs tens of microseconds on a virtual machine).
constexpr int spins_before_sleep = 4000;

} // namespace

ThreadPool::ThreadPool(int workers) {
    threads_.reserve(std::size_t(workers - 1));
    // Each thread starts from the bell as it is now, not as it finds it once running: a loop or
    // the destructor may ring before a new thread first reads it, and a thread that took that
    // ring for its starting point would sleep through it (the destructor's join then waits
    // forever).
    const std::uint32_t start = bell_.load();
    for (int k = 1; k < workers; ++k)
        threads_.emplace_back([this, k, start] { serve(k, start); });
}

ThreadPool::~ThreadPool() {
    stopping_.store(true);
    bell_.fetch_add(1);
    bell_.notify_all();
    for (std::thread& t : threads_)
        t.join();
}

void ThreadPool::run(TaskCallback task, int item_count, void* context) {
    if (item_count <= 0)
        return;
    task_ = task;
    context_ = context;
    remaining_.store(item_count, std::memory_order_relaxed);
    const std::uint64_t generation = generation_of(claim_.load(std::memory_order_relaxed)) + 1;
    claim_.store((generation << (2 * item_bits)) | (std::uint64_t(item_count) << item_bits),
                 std::memory_order_release);
    bell_.fetch_add(1, std::memory_order_release);
    bell_.notify_all();
    take_items(0);
    // The other threads' last items: spin, then sleep.
    for (int spin = 0; spin < spins_before_sleep; ++spin) {
        if (remaining_.load(std::memory_order_acquire) == 0)
            return;
        relax();
    }
    for (int left = remaining_.load(std::memory_order_acquire); left != 0;
         left = remaining_.load(std::memory_order_acquire))
        remaining_.wait(left, std::memory_order_acquire);
}

void ThreadPool::take_items(int worker) {
    std::uint64_t c = claim_.load(std::memory_order_acquire);
    while (next_of(c) < count_of(c)) {
        if (!claim_.compare_exchange_weak(c, c + 1, std::memory_order_acq_rel,
                                          std::memory_order_acquire))
            continue; // c now holds the current word
        const int item = int(next_of(c));
        task_(item, item + 1, worker, context_);
        if (remaining_.fetch_sub(1, std::memory_order_acq_rel) == 1)
            remaining_.notify_all();
        c = claim_.load(std::memory_order_acquire);
    }
}

void ThreadPool::serve(int worker, std::uint32_t heard) {
    for (;;) {
        int spin = 0;
        while (bell_.load(std::memory_order_acquire) == heard && spin++ < spins_before_sleep)
            relax();
        bell_.wait(heard, std::memory_order_acquire);
        heard = bell_.load(std::memory_order_acquire);
        if (stopping_.load())
            return;
        take_items(worker);
    }
}

} // namespace tamias2d
