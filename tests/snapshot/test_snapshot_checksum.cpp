// The snapshot's checksum is XXH64 as its published specification defines it.
//
// Oracle: the xxHash project's own implementation (libxxhash, loaded at run time:
// tests/support/reference_xxh64.hpp) on seeded random byte strings of every length from 0 to
// 300 (every tail the algorithm distinguishes: below 32 bytes, whole stripes, 8-, 4- and 1-byte
// tails) and a 1 MiB one, with seed 0 and random seeds; and the specification's value for the
// empty input with seed 0, 0xEF46DB3751D8E999. A guarantee of the format, not an SRS item: the
// `reliability` tag.
#include <boost/test/unit_test.hpp>

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "support/reference_xxh64.hpp"
#include "tamias2d/math/xxh64.hpp"

namespace utf = boost::unit_test;

BOOST_AUTO_TEST_SUITE(snapshot_checksum)

// Oracle: an independent implementation, the xxHash project's own XXH64 (libxxhash, loaded at
// run time), on seeded random byte strings of every length from 0 to 300, with seed 0 and
// random seeds, and on a 1 MiB one; and the specification's value for the empty input with
// seed 0, 0xEF46DB3751D8E999.
BOOST_AUTO_TEST_CASE(checksum_is_xxh64, *utf::label("reliability")) {
    BOOST_TEST(tamias2d::xxh64({}, 0) == 0xEF46DB3751D8E999ull);
    std::mt19937_64 rng(47);
    int checked = 0;
    for (std::size_t n = 0; n <= 300; ++n) {
        for (int rep = 0; rep < 4; ++rep) {
            std::vector<std::byte> b(n);
            for (std::byte& x : b)
                x = std::byte(rng());
            const std::uint64_t seed = rep == 0 ? 0 : rng();
            BOOST_TEST_INFO("length " << n << ", seed " << seed);
            BOOST_TEST(tamias2d::xxh64(b, seed) == tamias_test::reference_xxh64(b, seed));
            ++checked;
        }
    }
    std::vector<std::byte> big(std::size_t{1} << 20);
    for (std::byte& x : big)
        x = std::byte(rng());
    BOOST_TEST(tamias2d::xxh64(big, 7) == tamias_test::reference_xxh64(big, 7));
    BOOST_TEST(checked == 301 * 4);
}

BOOST_AUTO_TEST_SUITE_END()
