// The world's large arrays (memory/large_array.hpp): a LargeArray behaves as a std::vector, and
// its large blocks start on a 2 MiB boundary, so that the kernel can back them with huge pages.
#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <vector>

#include "tamias2d/memory/large_array.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

BOOST_AUTO_TEST_SUITE(large_array)

// Oracle: std::vector fed the same values (the allocator must not change what a vector holds).
BOOST_AUTO_TEST_CASE(holds_what_a_vector_holds, *utf::label("NFR1")) {
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
BOOST_AUTO_TEST_CASE(large_blocks_start_on_a_huge_page, *utf::label("NFR1")) {
    const LargeArray<double> big(std::size_t(3) << 17); // 3 MiB
    BOOST_TEST(reinterpret_cast<std::uintptr_t>(big.data()) % (std::uintptr_t(2) << 20) == 0u);
    struct alignas(64) Line {
        char bytes[64];
    };
    const LargeArray<Line> small(10); // small blocks keep the type's own alignment
    BOOST_TEST(reinterpret_cast<std::uintptr_t>(small.data()) % 64 == 0u);
}

BOOST_AUTO_TEST_SUITE_END()
