// Churn: 100 000 worlds, each with a few bodies, shapes and a joint, stepped and destroyed, must
// leave the process's memory where it was. A game that loads and unloads levels for hours
// relies on this.
//
// Bound: the resident set after the last world may exceed its value after the first 1000
// (the warm-up: allocator arenas and the test framework settle) by at most 1 MiB. A leak of
// one allocation per world (malloc's smallest chunk is 32 bytes) would add 3 MiB over the
// remaining 99 000 worlds, so any per-world leak fails. The library's large blocks in use
// (large_array_stats().mapped_bytes) must be back to their value before the first world.
// Under AddressSanitizer (quarantine) or ThreadSanitizer the resident set is not the library's;
// there LeakSanitizer, which the sanitizer build runs with, reports any leak instead, and the
// count is cut to 10 000 to keep the run short.
#include <boost/test/unit_test.hpp>

#include <cstddef>
#include <cstdio>

#include "support/reliability_support.hpp"
#include "tamias2d/memory.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

/// One short-lived world: two bodies on a ground, one pinned to the other, one step.
void live_and_die() {
    World world;
    BodyDef ground;
    ground.type = BodyType::static_body;
    world.create_shape(world.create_body(ground), box_shape(10.0, 1.0));
    BodyDef d;
    d.position = {0.0, 1.0};
    const BodyId a = world.create_body(d);
    world.create_shape(a, box_shape(1.0, 1.0));
    d.position = {1.2, 1.0};
    const BodyId b = world.create_body(d);
    world.create_shape(b, circle_shape(0.5));
    RevoluteJointDef pin;
    pin.body_a = a;
    pin.body_b = b;
    pin.anchor = {0.6, 1.0};
    world.create_joint(pin);
    world.step(1.0 / 60.0);
}

} // namespace

BOOST_AUTO_TEST_SUITE(churn)

// Oracle: a bound on the kernel's count of resident pages (/proc/self/statm): after the last
// world the resident set exceeds its value after the first 1000 by at most 1 MiB, where a leak
// of one 32-byte chunk per world would add 3 MiB; and the library's large blocks in use
// (large_array_stats().mapped_bytes) come back to their value before the first world. Under
// AddressSanitizer or ThreadSanitizer the resident set is not checked; LeakSanitizer reports
// any leak instead.
BOOST_AUTO_TEST_CASE(hundred_thousand_worlds_leave_memory_flat, *utf::label("reliability")) {
    constexpr int warm_up = 1000;
    const int worlds = reliability::memory_sanitizer_build ? 10000 : 100000;
    const std::size_t blocks_before = large_array_stats().mapped_bytes;
    for (int i = 0; i < warm_up; ++i)
        live_and_die();
    const std::size_t rss_start = reliability::resident_bytes();
    for (int i = warm_up; i < worlds; ++i)
        live_and_die();
    const std::size_t rss_end = reliability::resident_bytes();
    BOOST_TEST_MESSAGE(worlds << " worlds: resident " << rss_start << " -> " << rss_end
                              << " bytes after the first " << warm_up);
    BOOST_TEST(large_array_stats().mapped_bytes == blocks_before);
    if (!reliability::memory_sanitizer_build) {
        BOOST_TEST(rss_start > 0u, "no /proc/self/statm");
        constexpr std::size_t bound = std::size_t(1) << 20;
        BOOST_TEST(rss_end <= rss_start + bound, "resident set grew by " << (rss_end - rss_start)
                                                                         << " bytes (bound "
                                                                         << bound << ")");
    }
}

BOOST_AUTO_TEST_SUITE_END()
