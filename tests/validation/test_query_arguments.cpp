// The queries refuse a region that can hold nothing instead of answering it with no shapes: a
// box upside down (min > max on an axis) and a box side or point that is not a number.
#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

#include "validation_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::test;

BOOST_AUTO_TEST_SUITE(query_arguments)

// Oracle: Aabb's definition (aabb.hpp: a box has min_x <= max_x and min_y <= max_y) and
// World::query_aabb's contract: a box upside down is refused, naming the side and the rule,
// with the world's complete state hash unchanged; a box of zero width and height (a point) is
// a box; the same box with its corners in order finds the ground and the box that rests on it
// (MovingWorld: the ground spans x in [-10, 10], the box of 1 m sits at x = 0 on it).
BOOST_AUTO_TEST_CASE(a_box_upside_down_is_refused, *utf::label("reliability")) {
    MovingWorld m;
    const auto expect_refused = [&](const Aabb& box, const std::string& field,
                                    const std::string& what) {
        const auto e = expect_rejected(
            m.world, [&] { (void)m.world.query_aabb(box); }, field, "query");
        if (e) {
            BOOST_TEST(e->field == field);
            BOOST_TEST(std::string(e->what()) == what);
        }
    };
    expect_refused(Aabb{1.0, -1.0, -1.0, 1.0}, "box.max_x",
                   "box.max_x = -1: must be >= box.min_x (1 m) (query)");
    expect_refused(Aabb{-1.0, 2.0, 1.0, 0.5}, "box.max_y",
                   "box.max_y = 0.5: must be >= box.min_y (2 m) (query)");
    const std::vector<ShapeId> found = m.world.query_aabb(Aabb{-1.0, -1.0, 1.0, 1.0});
    BOOST_TEST(found.size() == 2u); // the ground and the box
    BOOST_CHECK_NO_THROW((void)m.world.query_aabb(Aabb{0.0, 0.5, 0.0, 0.5}));
    BOOST_TEST(m.world.query_aabb(Aabb{0.0, 0.5, 0.0, 0.5}).size() == 1u); // inside the box
}

// Oracle: DCX_finite (srs/data_constraints.yaml: every real input is finite): a box side or a
// query point that is NaN or infinite is refused, naming it, with the world unchanged.
BOOST_AUTO_TEST_CASE(a_query_that_is_not_a_number_is_refused,
                     *utf::label("R4") * utf::label("DCX_finite")) {
    MovingWorld m;
    for (const double bad : non_finite) {
        BOOST_TEST_CONTEXT("value " << bad) {
            expect_rejected_value(
                m.world,
                [&] {
                    (void)m.world.query_aabb(Aabb{bad, -1.0, 1.0, 1.0});
                },
                "box.min_x", "DCX_finite", bad);
            expect_rejected_value(
                m.world,
                [&] {
                    (void)m.world.query_aabb(Aabb{-1.0, -1.0, 1.0, bad});
                },
                "box.max_y", "DCX_finite", bad);
            expect_rejected_value(
                m.world,
                [&] {
                    (void)m.world.query_point({0.0, bad});
                },
                "point.y", "DCX_finite", bad);
        }
    }
    BOOST_TEST(m.world.query_point({0.0, 0.5}).size() == 1u); // the box
}

BOOST_AUTO_TEST_SUITE_END()
