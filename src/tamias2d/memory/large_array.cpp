#include "tamias2d/memory/large_array.hpp"

#include <algorithm>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace tamias2d::detail {

namespace {
constexpr std::size_t huge_page = std::size_t(2) << 20;
constexpr std::size_t large_from = std::size_t(1) << 20; ///< the rounding wastes under 2 MiB

bool is_large(std::size_t bytes) {
    return bytes >= large_from;
}
std::size_t rounded(std::size_t bytes) {
    return (bytes + huge_page - 1) / huge_page * huge_page;
}
std::align_val_t alignment(std::size_t bytes, std::size_t align) {
    return std::align_val_t(is_large(bytes) ? huge_page
                                            : std::max(align, alignof(std::max_align_t)));
}
} // namespace

void* allocate_large_array(std::size_t bytes, std::size_t align) {
    const std::size_t size = is_large(bytes) ? rounded(bytes) : bytes;
    void* p = ::operator new(size, alignment(bytes, align));
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // Only advice: without transparent huge pages (or with them off) this fails harmlessly.
    if (is_large(bytes))
        madvise(p, size, MADV_HUGEPAGE);
#endif
    return p;
}

void deallocate_large_array(void* p, std::size_t bytes, std::size_t align) noexcept {
    ::operator delete(p, is_large(bytes) ? rounded(bytes) : bytes, alignment(bytes, align));
}

} // namespace tamias2d::detail
