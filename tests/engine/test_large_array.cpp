// The world's large arrays (memory/large_array.hpp): a LargeArray behaves as a std::vector, its
// large blocks start on a 2 MiB boundary, so that the kernel can back them with huge pages, and
// they grow by remapping their pages.
#include <boost/test/unit_test.hpp>

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

#include "tamias2d/memory/large_array.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

BOOST_AUTO_TEST_SUITE(large_array)

// Oracle: std::vector fed the same values (the allocator must not change what a vector holds).
BOOST_AUTO_TEST_CASE(holds_what_a_vector_holds, *utf::label("performance")) {
    LargeArray<std::uint64_t> a;
    std::vector<std::uint64_t> want;
    for (std::uint64_t i = 0; i < 400000; ++i) { // grows through small and large blocks
        a.push_back(i * 2654435761u);
        want.push_back(i * 2654435761u);
    }
    BOOST_TEST((std::vector<std::uint64_t>(a.begin(), a.end()) == want));
    a.resize(10);
    a.shrink_to_fit(); // back to a small block
    BOOST_TEST((std::vector<std::uint64_t>(a.begin(), a.end()) ==
                std::vector<std::uint64_t>(want.begin(), want.begin() + 10)));
}

// Oracle: the address arithmetic (a huge page is 2 MiB on x86-64 and arm64 Linux).
BOOST_AUTO_TEST_CASE(large_blocks_start_on_a_huge_page, *utf::label("performance")) {
    const LargeArray<double> big(std::size_t(3) << 17); // 3 MiB
    BOOST_TEST(reinterpret_cast<std::uintptr_t>(big.data()) % (std::uintptr_t(2) << 20) == 0u);
    struct alignas(64) Line {
        char bytes[64];
    };
    const LargeArray<Line> small(10); // small blocks keep the type's own alignment
    BOOST_TEST(reinterpret_cast<std::uintptr_t>(small.data()) % 64 == 0u);
}

// Oracle: the block's own first bytes, written before the growth, and the mapping counters
// (a growth past the block's huge pages remaps it; within them it needs nothing).
BOOST_AUTO_TEST_CASE(large_blocks_grow_without_a_new_mapping, *utf::label("performance")) {
    LargeArray<std::uint64_t> a;
    a.reserve(std::size_t(3) << 17); // 3 MiB: mapped as 4
    for (std::uint64_t i = 0; i < (std::uint64_t(3) << 17); ++i)
        a.push_back(i ^ 0x9e3779b97f4a7c15u);
    const LargeArrayStats filled = large_array_stats();
    a.reserve(std::size_t(1) << 19); // 4 MiB: within the mapping
    BOOST_TEST(large_array_stats().remaps == filled.remaps);
    a.reserve(std::size_t(5) << 17); // 5 MiB: past it
    const LargeArrayStats grown = large_array_stats();
    BOOST_TEST(grown.remaps == filled.remaps + 1);
    BOOST_TEST(grown.maps == filled.maps); // the same block, grown
    BOOST_TEST(reinterpret_cast<std::uintptr_t>(a.data()) % (std::uintptr_t(2) << 20) == 0u);
    bool same = a.size() == (std::size_t(3) << 17);
    for (std::uint64_t i = 0; i < a.size(); ++i)
        same = same && a[i] == (i ^ 0x9e3779b97f4a7c15u);
    BOOST_TEST(same);
}

// Oracle: std::vector's semantics (a copy is equal and independent; a move leaves the source
// empty; an argument that is an element survives the growth it causes).
BOOST_AUTO_TEST_CASE(copies_moves_and_self_references, *utf::label("performance")) {
    LargeArray<std::uint64_t> a(std::size_t(3) << 17);
    for (std::size_t i = 0; i < a.size(); ++i)
        a[i] = i;
    LargeArray<std::uint64_t> b = a;
    b[5] = 99;
    BOOST_TEST(a[5] == 5u);
    BOOST_TEST((std::vector<std::uint64_t>(b.begin(), b.begin() + 4) ==
                std::vector<std::uint64_t>{0, 1, 2, 3}));
    const LargeArrayStats before_move = large_array_stats();
    LargeArray<std::uint64_t> c = std::move(b);
    BOOST_TEST(b.empty());
    BOOST_TEST(c[5] == 99u);
    BOOST_TEST(large_array_stats().maps == before_move.maps);
    LargeArray<std::uint64_t> d;
    d.push_back(41);
    while (d.size() < (std::size_t(1) << 18)) // each growth copies or remaps under the argument
        d.push_back(d[d.size() - 1] + 1);
    BOOST_TEST(d.back() == 41u + (std::size_t(1) << 18) - 1);
    d.assign(3, d[7]);
    BOOST_TEST(
        (std::vector<std::uint64_t>(d.begin(), d.end()) == std::vector<std::uint64_t>{48, 48, 48}));
}

// Oracle: the block's address (a released block is retained and handed out again whole, as
// malloc hands out a freed chunk) and the retention limit, 64 MiB (glibc's largest trim
// threshold). Blocks are only reserved here: their pages are never touched.
BOOST_AUTO_TEST_CASE(released_blocks_are_retained_for_the_next, *utf::label("performance")) {
    release_retained_memory();
    BOOST_TEST(large_array_stats().retained_bytes == 0u);
    const void* first = nullptr;
    {
        LargeArray<std::uint64_t> a;
        a.reserve(std::size_t(3) << 17); // 3 MiB, mapped as 4
        first = a.data();
    }
    BOOST_TEST(large_array_stats().retained_bytes == std::size_t(4) << 20);
    {
        LargeArray<std::uint64_t> b;
        b.reserve(std::size_t(3) << 17);
        BOOST_TEST(static_cast<const void*>(b.data()) == first);
        BOOST_TEST(large_array_stats().retained_bytes == 0u);
    }
    {
        LargeArray<std::uint64_t> x, y, z; // 30 MiB each: the third does not fit under 64
        for (LargeArray<std::uint64_t>* a : {&x, &y, &z})
            a->reserve(std::size_t(30) << 17);
    }
    BOOST_TEST(large_array_stats().retained_bytes <= std::size_t(64) << 20);
    BOOST_TEST(large_array_stats().retained_bytes >= std::size_t(60) << 20);
    const std::size_t in_use = large_array_stats().mapped_bytes;
    release_retained_memory();
    BOOST_TEST(large_array_stats().retained_bytes == 0u);
    BOOST_TEST(large_array_stats().mapped_bytes == in_use);
}

// Oracle: each thread's own pattern, read back after the other thread has had the chance to
// write: a block handed to both (the retained table is shared by the process) would mix them.
BOOST_AUTO_TEST_CASE(threads_share_the_retained_blocks_safely, *utf::label("performance")) {
    std::atomic<int> wrong{0};
    auto work = [&wrong](std::uint64_t tag) {
        for (int round = 0; round < 40; ++round) {
            LargeArray<std::uint64_t> a(std::size_t(3) << 17); // 3 MiB: a large block
            for (std::size_t i = 0; i < a.size(); i += 512)
                a[i] = tag << 32 | i;
            std::this_thread::yield();
            for (std::size_t i = 0; i < a.size(); i += 512)
                if (a[i] != (tag << 32 | i))
                    wrong.fetch_add(1);
        }
    };
    std::thread first(work, 1u), second(work, 2u);
    first.join();
    second.join();
    BOOST_TEST(wrong.load() == 0);
}

BOOST_AUTO_TEST_SUITE_END()
