// A contact world large enough for every pass of the step to run in blocks on workers (bodies
// prepared in blocks from 1024, manifolds prepared and stored in blocks, the streams of the
// contact regions), small enough to run for every mutant of the dynamics: the thorough
// thread-count cases (every worker count, scrambling task systems, sleeping, joints of every
// kind) are tests/reliability's, which the mutation tool does not pick for these files.
#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <vector>

#include "support/pyramid.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

/// The state hash after each of 12 steps of a pyramid of 48 rows (1176 boxes) with a damped
/// box thrown into its side, on `workers` threads with `regions` contact regions.
std::vector<std::uint64_t> hashes(int workers, int regions, Vec2d gravity = {0.0, -10.0}) {
    World world(WorldDef{.gravity = gravity, .contact_regions = regions, .workers = workers});
    test::build_pyramid(world, 48);
    BodyDef thrown;
    thrown.position = {-30.0, 3.0};
    thrown.linear_velocity = {40.0, 0.0};
    thrown.linear_damping = 0.5;
    world.create_shape(world.create_body(thrown), box_shape(1.0, 1.0));
    std::vector<std::uint64_t> out;
    for (int k = 0; k < 12; ++k) {
        world.step(1.0 / 60.0);
        out.push_back(world.state_hash());
    }
    return out;
}

/// The state hash after each step of a row of 200 boxes resting 2 m apart on the ground, with
/// sleeping on: a ball on the ground (made before the boxes) is thrown up once every box
/// sleeps, so that its contact is destroyed and the last one, a sleeping box's, moves into its
/// slot while neither of that pair's bodies moves.
std::vector<std::uint64_t> sleeping_row_hashes(int workers) {
    World world(WorldDef{
        .gravity = {0.0, -10.0}, .enable_sleep = true, .time_to_sleep = 0.1, .workers = workers});
    const BodyId ground = world.create_body(BodyDef{.type = BodyType::static_body});
    world.create_shape(ground, box_shape(500.0, 1.0, {}, {200.0, -0.5}));
    const BodyId ball = world.create_body(BodyDef{.position = {-2.0, 0.25}});
    world.create_shape(ball, circle_shape(0.25));
    for (int k = 0; k < 200; ++k)
        world.create_shape(world.create_body(BodyDef{.position = {2.0 * k, 0.5}}),
                           box_shape(1.0, 1.0));
    std::vector<std::uint64_t> out;
    for (int k = 0; k < 90; ++k) {
        if (k == 60)
            world.set_velocity(ball, {0.0, 20.0});
        world.step(1.0 / 60.0);
        out.push_back(world.state_hash());
    }
    return out;
}

} // namespace

BOOST_AUTO_TEST_SUITE(contacts_on_workers)

// Oracle: the determinism rule, the same bits on any number of workers, step by step.
BOOST_AUTO_TEST_CASE(a_large_pile_gives_one_threads_bits, *utf::label("determinism")) {
    for (const int regions : {1, 2}) {
        const std::vector<std::uint64_t> one = hashes(1, regions);
        for (const int workers : {2, 3}) {
            BOOST_TEST_CONTEXT("contact_regions = " << regions << ", " << workers << " workers") {
                BOOST_TEST(hashes(workers, regions) == one, boost::test_tools::per_element());
            }
        }
    }
}

// Oracle: the determinism rule under a gravity along neither axis, where the regions' cut
// (across gravity) weighs both coordinates: one thread prepares the bodies in sequence, two in
// blocks, and both must place every body at the same cut.
BOOST_AUTO_TEST_CASE(a_pile_under_a_slanted_gravity_gives_one_threads_bits,
                     *utf::label("determinism")) {
    const Vec2d slanted{-3.0, -10.0};
    BOOST_TEST(hashes(2, 2, slanted) == hashes(1, 2, slanted), boost::test_tools::per_element());
}

// Oracle: the determinism rule, the same bits on any number of workers, step by step, where a
// contact between sleeping bodies takes the slot of one just destroyed: the narrow phase in
// blocks must treat it as kept, as the serial loop does, whatever the slot held before.
BOOST_AUTO_TEST_CASE(a_sleeping_contact_moved_into_a_destroyed_ones_slot_gives_one_threads_bits,
                     *utf::label("determinism")) {
    BOOST_TEST(sleeping_row_hashes(2) == sleeping_row_hashes(1), boost::test_tools::per_element());
}

BOOST_AUTO_TEST_SUITE_END()
