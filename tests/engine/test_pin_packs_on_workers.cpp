// Plain pins packed four at once and filled in blocks on workers: a world with at least two
// blocks of packs (StepSolver::each_pack: 64 packs a block, blocks from 128 packs) and of
// jointed bodies (StepSolver::turn_joints: 512 a block, blocks from 1024) fills and turns them
// on several threads, and must step to the bits of one thread. The thread-count cases of
// tests/reliability cover the world's other passes; this one has enough of both for the blocks.
#include <boost/test/unit_test.hpp>

#include <cstring>
#include <vector>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr int columns = 36, rows = 30;

/// A net hanging from a static bar under a slanted gravity, so that it swings sideways and its
/// boxes turn: rows x columns small boxes 1 m apart (1080),
/// each pinned to its right and lower neighbours at their midpoints, the top row pinned to the
/// bar (2130 plain revolute joints, whose levels are wide: about 530 packs). The states after
/// `steps` steps on `workers` threads.
std::vector<BodyState> hang_net(int workers, int steps) {
    World world(WorldDef{.gravity = {3.0, -10.0}, .workers = workers});
    const BodyId bar = world.create_body({.type = BodyType::static_body});
    world.create_shape(bar, box_shape(double(columns), 0.2));
    std::vector<BodyId> ids;
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            const Vec2d at{double(c), -1.0 - double(r)};
            ids.push_back(world.create_body({.position = at}));
            world.create_shape(ids.back(), box_shape(0.3, 0.3));
            const BodyId self = ids.back();
            const BodyId above = r == 0 ? bar : ids[std::size_t((r - 1) * columns + c)];
            world.create_joint(
                RevoluteJointDef{.body_a = above, .body_b = self, .anchor = {at.x, at.y + 0.5}});
            if (c > 0)
                world.create_joint(RevoluteJointDef{
                    .body_a = ids[ids.size() - 2], .body_b = self, .anchor = {at.x - 0.5, at.y}});
        }
    }
    for (int k = 0; k < steps; ++k)
        world.step(1.0 / 60.0);
    std::vector<BodyState> states;
    for (const BodyId b : ids)
        states.push_back(world.state(b));
    return states;
}

} // namespace

BOOST_AUTO_TEST_SUITE(pin_packs_on_workers)

// Oracle: the determinism rule, the same bits on any number of workers. The net swings and
// stretches under gravity for 30 steps on one thread, then on two and three.
BOOST_AUTO_TEST_CASE(a_net_of_many_packs_gives_one_threads_bits, *utf::label("determinism")) {
    const std::vector<BodyState> one = hang_net(1, 30);
    BOOST_TEST_REQUIRE(one.back().position.y < -1.0 - (rows - 1)); // it has sagged
    BOOST_TEST_REQUIRE(one.back().orientation != 0.0);             // and its boxes turn
    for (const int workers : {2, 3}) {
        const std::vector<BodyState> many = hang_net(workers, 30);
        BOOST_TEST(std::memcmp(one.data(), many.data(), one.size() * sizeof(BodyState)) == 0,
                   workers << " workers");
    }
}

BOOST_AUTO_TEST_SUITE_END()
