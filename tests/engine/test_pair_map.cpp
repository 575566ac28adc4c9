// The contact index's hash map (memory/pair_map.hpp) against std::unordered_map.
#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <random>
#include <unordered_map>
#include <vector>

#include "tamias2d/memory/pair_map.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

BOOST_AUTO_TEST_SUITE(pair_map)

namespace {
std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t(a < b ? a : b) << 32) | (a < b ? b : a);
}
} // namespace

// Oracle: std::unordered_map fed the same operations. Keys come from few shapes, so runs of
// colliding homes are long and erasure's backward shift is exercised, wrap-around included.
// R7: the map is the index through which detection finds a pair's contact; the standard
// library's map is independent of it.
BOOST_AUTO_TEST_CASE(agrees_with_unordered_map, *utf::label("internals")) {
    PairMap map;
    std::unordered_map<std::uint64_t, std::uint32_t> want;
    std::vector<std::uint64_t> keys;
    std::mt19937_64 rng(7);
    for (int op = 0; op < 200000; ++op) {
        const auto a = std::uint32_t(rng() % 300), b = std::uint32_t(rng() % 300);
        const std::uint64_t k = pair_key(a, b);
        const int kind = int(rng() % 4);
        if (kind <= 1 && !want.contains(k)) {
            map.insert(k, std::uint32_t(op));
            want[k] = std::uint32_t(op);
        } else if (kind == 2 && want.contains(k)) {
            map.assign(k, std::uint32_t(op) + 1);
            want[k] = std::uint32_t(op) + 1;
        } else if (kind == 3) {
            map.erase(k);
            want.erase(k);
        }
        if (op % 1000 == 0) {
            BOOST_TEST_REQUIRE(map.size() == want.size());
            for (std::uint32_t x = 0; x < 300; x += 7) {
                for (std::uint32_t y = x; y < 300; y += 3) {
                    const std::uint64_t q = pair_key(x, y);
                    const auto it = want.find(q);
                    BOOST_TEST_REQUIRE(map.find(q) ==
                                       (it == want.end() ? PairMap::npos : it->second));
                }
            }
        }
    }
    for (const auto& [k, v] : want)
        BOOST_TEST_REQUIRE(map.find(k) == v);
}

// Oracle: the contract of an empty map (no slots yet): nothing is found, erasing is harmless.
BOOST_AUTO_TEST_CASE(empty_map_finds_nothing) {
    PairMap map;
    BOOST_TEST(map.find(pair_key(1, 2)) == PairMap::npos);
    map.erase(pair_key(1, 2));
    BOOST_TEST(map.size() == 0u);
}

BOOST_AUTO_TEST_SUITE_END()
