// World::snapshot(bytes) writes the bytes World::snapshot() returns, whatever `bytes` held
// before: empty, a larger snapshot, a smaller one, junk with spare capacity.
//
// Oracle: World::snapshot() of the same world (a new vector each time). A guarantee of the
// library's API, not an SRS item: the `reliability` tag.
#include <boost/test/unit_test.hpp>

#include <cstddef>
#include <vector>

#include "snapshot/snapshot_worlds.hpp"

namespace utf = boost::unit_test;
using namespace snapshot_test;

BOOST_AUTO_TEST_SUITE(snapshot_buffer)

// Oracle: the contract of World::snapshot(bytes) in world.hpp (the same bytes as snapshot(),
// whatever `bytes` held), checked against snapshot() of the same world into a new vector while
// the reused vector holds nothing, a smaller snapshot, a larger one or junk with spare capacity;
// the bytes read back restore a world with the original's state hash.
BOOST_AUTO_TEST_CASE(a_reused_vector_gets_the_same_bytes, *utf::label("reliability")) {
    World small = random_world(3);
    World large = random_world(4);
    for (int k = 0; k < 10; ++k) {
        small.step(1.0 / 60.0);
        large.step(1.0 / 60.0);
    }
    const std::vector<std::byte> small_bytes = small.snapshot();
    const std::vector<std::byte> large_bytes = large.snapshot();
    BOOST_TEST_REQUIRE(small_bytes.size() != large_bytes.size());

    std::vector<std::byte> reused;
    small.snapshot(reused);
    BOOST_TEST((reused == small_bytes));
    large.snapshot(reused); // grows
    BOOST_TEST((reused == large_bytes));
    small.snapshot(reused); // shrinks, capacity kept
    BOOST_TEST((reused == small_bytes));
    std::vector<std::byte> junk = large_bytes;
    junk.insert(junk.end(), large_bytes.begin(), large_bytes.end()); // other bytes, then ...
    junk.resize(5);                                                  // ... spare capacity
    large.snapshot(junk); // spare capacity holding other bytes
    BOOST_TEST((junk == large_bytes));
    // What was read back from a reused vector is a snapshot of the world.
    World copy = World::from_snapshot(junk);
    BOOST_TEST(copy.state_hash() == large.state_hash());
}

BOOST_AUTO_TEST_SUITE_END()
