// The benchmark's memory probe (verification/bench/memory_probe.hpp): its chase must visit every
// line of the working set, in an order the hardware prefetcher cannot follow, or it reports the
// latency of a smaller set or of a stream instead of the set's.
#include <boost/test/unit_test.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "memory_probe.hpp"

BOOST_AUTO_TEST_SUITE(memory_probe)

// Oracle: the definition of a single cycle (a walk from 0 returns to 0 after exactly n steps,
// having seen every line once).
BOOST_AUTO_TEST_CASE(random_cycle_visits_every_line_once, *boost::unit_test::label("performance")) {
    for (const std::size_t n : {2u, 3u, 64u, 1000u, 16384u}) {
        const std::vector<std::uint32_t> next = tamias_bench::random_cycle(n, 2);
        BOOST_REQUIRE_EQUAL(next.size(), n);
        std::vector<bool> seen(n, false);
        std::uint32_t at = 0;
        std::size_t steps = 0;
        do {
            BOOST_REQUIRE_LT(at, n);
            BOOST_REQUIRE_MESSAGE(!seen[at], "line " << at << " visited twice (n = " << n << ")");
            seen[at] = true;
            at = next[at];
            ++steps;
        } while (at != 0 && steps <= n);
        BOOST_TEST(steps == n);
    }
}

// Oracle: a uniformly random successor is the next line with probability 1/n; a chase in
// ascending order (or mostly so) would measure a prefetched stream. Also: the same seed gives the
// same cycle (the benchmark is deterministic), another seed another one.
BOOST_AUTO_TEST_CASE(random_cycle_is_not_a_stream, *boost::unit_test::label("performance")) {
    const std::size_t n = 16384;
    const std::vector<std::uint32_t> next = tamias_bench::random_cycle(n, 2);
    std::size_t sequential = 0;
    for (std::size_t i = 0; i < n; ++i)
        sequential += next[i] == (i + 1) % n ? 1 : 0;
    BOOST_TEST(sequential < 20u); // expected 1
    BOOST_TEST(tamias_bench::random_cycle(n, 2) == next);
    BOOST_TEST(tamias_bench::random_cycle(n, 3) != next);
}

BOOST_AUTO_TEST_SUITE_END()
