#include "tamias2d/memory/retained_blocks.hpp"

#include <new>

namespace tamias2d::detail {

void* RetainedBlocks::take(std::size_t size) {
    const std::lock_guard lock(mutex_);
    int best = -1;
    for (int i = 0; i < count_; ++i)
        if (ranges_[i].size >= size && (best < 0 || ranges_[i].size < ranges_[best].size))
            best = i;
    if (best < 0)
        return nullptr;
    Range& r = ranges_[best];
    void* p = reinterpret_cast<void*>(r.start);
    total_ -= size;
    if (r.size == size) {
        r = ranges_[--count_];
    } else {
        r.start += size;
        r.size -= size;
    }
    return p;
}

bool RetainedBlocks::keep(void* p, std::size_t size) {
    const std::lock_guard lock(mutex_);
    if (count_ == max_ranges || total_ + size > limit)
        return false;
    ranges_[count_++] = {reinterpret_cast<std::uintptr_t>(p), size};
    total_ += size;
    return true;
}

std::size_t RetainedBlocks::bytes() {
    const std::lock_guard lock(mutex_);
    return total_;
}

void RetainedBlocks::release_all(void (*release)(void* p, std::size_t size)) {
    const std::lock_guard lock(mutex_);
    for (int i = 0; i < count_; ++i)
        release(reinterpret_cast<void*>(ranges_[i].start), ranges_[i].size);
    count_ = 0;
    total_ = 0;
}

RetainedBlocks& retained_blocks() {
    alignas(RetainedBlocks) static unsigned char storage[sizeof(RetainedBlocks)];
    static RetainedBlocks* const r = ::new (static_cast<void*>(storage)) RetainedBlocks();
    return *r;
}

} // namespace tamias2d::detail
