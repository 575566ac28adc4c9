// Released large blocks kept mapped for the next ones, as malloc keeps freed heap memory for
// reuse (up to glibc's largest trim threshold, 64 MiB): a world built after another reuses its
// pages instead of faulting in fresh ones. Fresh pages are what costs where the kernel hands
// freed memory back to a hypervisor (free page reporting): rain_16k's world took about 16
// huge-page faults and 50 ms of system time per build-and-run after a 3 s peer run, and none
// after its own previous run (docs/performance.md). Used by large_array.cpp only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>

namespace tamias2d::detail {

class RetainedBlocks {
  public:
    static constexpr std::size_t limit = std::size_t(64) << 20;

    /// A retained block of exactly `size` bytes, split from the smallest that holds it (sizes
    /// are whole huge pages, so the rest stays aligned), or nullptr.
    void* take(std::size_t size);
    /// Keeps the block if it fits under the limit; false: the caller returns it to the kernel.
    bool keep(void* p, std::size_t size);
    std::size_t bytes();
    /// Hands every retained block to `release`, and forgets them.
    void release_all(void (*release)(void* p, std::size_t size));

  private:
    struct Range {
        std::uintptr_t start;
        std::size_t size;
    };
    static constexpr int max_ranges = 64; ///< a fixed table: retaining never allocates
    std::mutex mutex_;                    ///< worlds may live in different threads
    Range ranges_[max_ranges]{};
    int count_ = 0;
    std::size_t total_ = 0;
};

/// The process's one instance: never destroyed (a world in static storage may release its
/// blocks after other statics are gone), and built without allocating.
RetainedBlocks& retained_blocks();

} // namespace tamias2d::detail
