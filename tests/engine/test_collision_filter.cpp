// Collision filters (DD27, R7) in the world: which pairs collide, changes that take effect at
// the next step, and the game's own filter. Oracles: free fall in closed form (IM1: a body no
// shape may touch falls as if alone) and the rule's statement.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double g = 10.0, dt = 1.0 / 60.0;

/// A static ground (top at y = 0) and a 1 m box resting on it (centre at y = 0.5) or, when the
/// filters refuse the pair, free to fall through.
struct Ground {
    World world{WorldDef{.gravity = {0.0, -g}, .enable_sleep = false}};
    BodyId box;
    ShapeId ground_shape, box_shape_id;
    Ground(Filter ground_filter, Filter box_filter) {
        BodyDef gd;
        gd.type = BodyType::static_body;
        gd.position = {0.0, -0.5};
        const BodyId ground = world.create_body(gd);
        ShapeDef gs = box_shape(20.0, 1.0);
        gs.filter = ground_filter;
        ground_shape = world.create_shape(ground, gs);
        BodyDef bd;
        bd.position = {0.0, 0.5};
        box = world.create_body(bd);
        ShapeDef bs = box_shape(1.0, 1.0);
        bs.filter = box_filter;
        box_shape_id = world.create_shape(box, bs);
    }
    /// The box's height after n more steps, had nothing touched it: semi-implicit Euler from
    /// rest, h = dt / 4 (IM1's discrete closed form).
    static double free_fall(double y0, int substeps_done) {
        const double h = dt / WorldDef{}.substeps, n = substeps_done;
        return y0 - g * h * h * n * (n + 1.0) / 2.0;
    }
};

} // namespace

BOOST_AUTO_TEST_SUITE(collision_filter)

// Oracle: DD27 and IM1. With the default filters the box rests on the ground; with the box's
// mask refusing the ground's category, or both in one negative group, it falls through as if
// alone, exactly as free fall's discrete closed form; in one positive group it rests again
// although the masks refuse each other.
BOOST_AUTO_TEST_CASE(filters_decide_who_collides, *utf::label("DD27") * utf::label("R7")) {
    const Filter wall{.category_bits = 0x1}, ghost{.category_bits = 0x2, .mask_bits = ~0x1u};
    const Filter shy_a{.mask_bits = 0x0, .group_index = 4},
        shy_b{.mask_bits = 0x0, .group_index = 4};
    const Filter twin_a{.group_index = -1}, twin_b{.group_index = -1};
    struct Case {
        Filter ground, box;
        bool rests;
    };
    for (const auto& [fg, fb, rests] : {Case{Filter{}, Filter{}, true}, Case{wall, ghost, false},
                                        Case{twin_a, twin_b, false}, Case{shy_a, shy_b, true}}) {
        Ground s(fg, fb);
        for (int k = 1; k <= 30; ++k) {
            s.world.step(dt);
            if (!rests)
                BOOST_TEST_REQUIRE(s.world.position(s.box).y ==
                                       Ground::free_fall(0.5, k * WorldDef{}.substeps),
                                   boost::test_tools::tolerance(1e-12));
        }
        if (rests)
            BOOST_TEST(std::abs(s.world.position(s.box).y - 0.5) <= 0.01);
        BOOST_TEST(s.world.contacts().size() == (rests ? 1u : 0u));
    }
}

// Oracle: the stated timing (a change takes effect at the next step) and IM1. The filter of
// either shape of the resting pair (the box's, the contact's shape_b; the ground's, its
// shape_a) is changed to refuse the other: the contact is gone at once and the box falls from
// the next step as if alone; changed back, the pair is found again at the next step.
BOOST_AUTO_TEST_CASE(a_changed_filter_acts_at_the_next_step,
                     *utf::label("DD27") * utf::label("R7")) {
    for (const bool ground_changes : {false, true}) {
        BOOST_TEST_CONTEXT((ground_changes ? "the ground's filter" : "the box's filter")) {
            Ground s(Filter{}, Filter{});
            const ShapeId changed = ground_changes ? s.ground_shape : s.box_shape_id;
            for (int k = 0; k < 30; ++k)
                s.world.step(dt);
            BOOST_TEST_REQUIRE(s.world.contacts().size() == 1u);
            s.world.set_filter(changed, Filter{.mask_bits = 0x0});
            BOOST_TEST((s.world.filter(changed) == Filter{.mask_bits = 0x0}));
            BOOST_TEST(s.world.contacts().empty());
            BOOST_TEST(s.world.contact_end_events().size() == 1u);
            s.world.set_velocity(s.box, {0.0, 0.0});
            const double y0 = s.world.position(s.box).y;
            for (int k = 1; k <= 6; ++k) {
                s.world.step(dt);
                BOOST_TEST_REQUIRE(s.world.position(s.box).y ==
                                       Ground::free_fall(y0, k * WorldDef{}.substeps),
                                   boost::test_tools::tolerance(1e-12));
            }
            s.world.set_filter(changed, Filter{});
            s.world.step(dt);
            BOOST_TEST(s.world.contacts().size() == 1u);
        }
    }
}

// Oracle: the custom filter's stated contract: asked only for pairs the rules admit. It refuses
// the box against the ground: the box falls through as if alone (IM1); it is never asked about
// a pair the bits refuse.
BOOST_AUTO_TEST_CASE(the_games_own_filter, *utf::label("DD27") * utf::label("R7")) {
    Ground s(Filter{}, Filter{});
    BodyDef bd;
    bd.position = {5.0, 0.5};
    const BodyId masked = s.world.create_body(bd);
    ShapeDef ms = box_shape(1.0, 1.0);
    ms.filter.mask_bits = 0x0;
    const ShapeId masked_shape = s.world.create_shape(masked, ms);
    std::vector<std::pair<ShapeId, ShapeId>> asked;
    s.world.set_custom_filter([&](ShapeId a, ShapeId b) {
        asked.emplace_back(a, b);
        return a != s.box_shape_id && b != s.box_shape_id;
    });
    for (int k = 1; k <= 10; ++k) {
        s.world.step(dt);
        BOOST_TEST_REQUIRE(s.world.position(s.box).y ==
                               Ground::free_fall(0.5, k * WorldDef{}.substeps),
                           boost::test_tools::tolerance(1e-12));
    }
    // Only the box and the ground (again each time the box's moving box reports the pair).
    BOOST_TEST(!asked.empty());
    for (const auto& [a, b] : asked) {
        BOOST_TEST((a != masked_shape && b != masked_shape));
        BOOST_TEST(((a == s.box_shape_id && b == s.ground_shape) ||
                    (b == s.box_shape_id && a == s.ground_shape)));
    }
}

// Oracle: the custom filter's stated contract (World::set_custom_filter): a refused pair is
// asked again only when the broad phase reports it anew, that is when one of its shapes moves
// out of its fat box. Without gravity a box that overlaps the ground and is refused never
// moves: over 30 steps the filter is asked about the pair exactly once, at the first.
BOOST_AUTO_TEST_CASE(a_refused_pair_that_stays_put_is_asked_once,
                     *utf::label("DD27") * utf::label("R7")) {
    Ground s(Filter{}, Filter{});
    s.world.set_gravity({0.0, 0.0});
    int asked = 0;
    s.world.set_custom_filter([&](ShapeId, ShapeId) {
        ++asked;
        return false;
    });
    for (int k = 1; k <= 30; ++k) {
        s.world.step(dt);
        BOOST_TEST_REQUIRE(asked == 1, "step " << k);
    }
    BOOST_TEST(s.world.position(s.box).y == 0.5);
    BOOST_TEST(s.world.contacts().empty());
}

BOOST_AUTO_TEST_SUITE_END()
