// DD27 (the collision filter) checked against a truth table written from the rule's statement
// (srs/data_definitions.yaml): groups first, then categories and masks both ways.
#include <boost/test/unit_test.hpp>

#include "tamias2d/model/dd27_collision_filter.hpp"

namespace utf = boost::unit_test;
namespace dd27 = tamias2d::model::dd27;

BOOST_AUTO_TEST_SUITE(dd27_collision_filter)

// Oracle: hand truth table. Player 0x2 (collides with all but 0x4), its bullets 0x4 (collide
// with all but 0x2), walls 0x1 (with all), debris 0x8 (only with walls).
BOOST_AUTO_TEST_CASE(categories_and_masks_both_ways, *utf::label("DD27")) {
    const dd27::Filter player{0x2, ~0x4u, 0}, bullet{0x4, ~0x2u, 0}, wall{0x1, ~0u, 0},
        debris{0x8, 0x1, 0};
    BOOST_TEST(!dd27::should_collide(player, bullet));
    BOOST_TEST(!dd27::should_collide(bullet, player)); // symmetric
    BOOST_TEST(dd27::should_collide(player, wall));
    BOOST_TEST(dd27::should_collide(bullet, wall));
    BOOST_TEST(dd27::should_collide(debris, wall));
    BOOST_TEST(!dd27::should_collide(debris, player)); // debris's mask refuses the player
    BOOST_TEST(!dd27::should_collide(player, debris)); // however wide the player's mask
    BOOST_TEST(dd27::should_collide(bullet, bullet));
}

// Oracle: hand truth table. One positive group collides whatever the bits, one negative group
// never does; different groups, or group 0, fall back to the bits.
BOOST_AUTO_TEST_CASE(groups_override_the_bits, *utf::label("DD27")) {
    const dd27::Filter none_a{0x1, 0x0, 3}, none_b{0x1, 0x0, 3};
    BOOST_TEST(dd27::should_collide(none_a, none_b)); // group 3 > 0, masks 0
    const dd27::Filter all_a{0x1, ~0u, -2}, all_b{0x1, ~0u, -2};
    BOOST_TEST(!dd27::should_collide(all_a, all_b)); // group -2 < 0, masks accept
    const dd27::Filter other{0x1, ~0u, -5};
    BOOST_TEST(dd27::should_collide(all_a, other)); // different groups: the bits
    const dd27::Filter zero_a{0x1, 0x0, 0}, zero_b{0x1, ~0u, 0};
    BOOST_TEST(!dd27::should_collide(zero_a, zero_b)); // group 0 is no group: a's mask refuses
}

BOOST_AUTO_TEST_SUITE_END()
