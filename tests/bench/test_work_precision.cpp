// The work-precision diagrams' own measures (verification/bench/): the boxes' penetration from
// their poses, the scene's mechanical energy, and the Pareto frontier with the cheapest point at
// least as accurate. Each engine is judged by them, so each must be right on its own.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <vector>

#include "bench_joint_scenes.hpp"
#include "bench_scenes.hpp"
#include "box_penetration.hpp"
#include "pareto_frontier.hpp"
#include "scene_energy.hpp"

namespace tb = tamias_bench;

namespace {

/// The scene's bodies where it builds them, as an engine would report them before a step.
std::vector<tb::Probe> built_poses(const tb::SceneDesc& s) {
    std::vector<tb::Probe> out;
    for (const tb::BodyDesc& b : s.bodies)
        out.push_back({b.position, b.velocity, 0.0, b.angle});
    return out;
}

tb::PlacedBox unit_box(double x, double y, double angle) {
    return tb::place(tb::BoxPart{}, {x, y}, angle);
}

/// Every pair of boxes of different bodies, at least one dynamic: the definition the grid in
/// deepest_penetration must reproduce.
double deepest_by_every_pair(const tb::SceneDesc& s, const std::vector<tb::Probe>& poses) {
    double deepest = 0.0;
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        for (std::size_t j = i + 1; j < s.bodies.size(); ++j) {
            if (!s.bodies[i].dynamic && !s.bodies[j].dynamic)
                continue;
            const auto at = [&](std::size_t k) {
                return s.bodies[k].dynamic
                           ? poses[k]
                           : tb::Probe{s.bodies[k].position, {}, 0.0, s.bodies[k].angle};
            };
            for (const tb::BoxPart& a : s.bodies[i].boxes)
                for (const tb::BoxPart& b : s.bodies[j].boxes)
                    deepest =
                        std::max(deepest, tb::penetration(tb::place(a, at(i).p, at(i).angle),
                                                          tb::place(b, at(j).p, at(j).angle)));
        }
    }
    return deepest;
}

} // namespace

BOOST_AUTO_TEST_SUITE(work_precision_measures)

// Oracle: closed forms. Two axis-aligned unit boxes whose centres are 0.9 m apart in x and
// 0.3 m in y overlap by 0.1 m in x and 0.7 m in y: the shortest way out is 0.1 m; turning the
// whole pair changes nothing. A unit box turned by 45 degrees whose corner lies d below another's
// top face: its corner is 0.5 sqrt(2) from its centre, and the way out is d along the face normal.
BOOST_AUTO_TEST_CASE(penetration_of_two_boxes, *boost::unit_test::label("performance")) {
    BOOST_TEST(tb::penetration(unit_box(0, 0, 0), unit_box(0.9, 0.3, 0)) == 0.1,
               boost::test_tools::tolerance(1e-12));
    for (const double turn : {0.3, 1.0, 2.5}) {
        const double c = std::cos(turn), s = std::sin(turn);
        BOOST_TEST(tb::penetration(unit_box(0, 0, turn),
                                   unit_box(0.9 * c - 0.3 * s, 0.9 * s + 0.3 * c, turn)) == 0.1,
                   boost::test_tools::tolerance(1e-12));
    }
    for (const double d : {0.001, 0.02, 0.1}) {
        const double y = 0.5 + 0.5 * std::numbers::sqrt2 - d;
        BOOST_TEST(tb::penetration(unit_box(0, 0, 0), unit_box(0, y, std::numbers::pi / 4)) == d,
                   boost::test_tools::tolerance(1e-9));
    }
    // Apart, and exactly touching (the pyramids' boxes as built): no penetration.
    BOOST_TEST(tb::penetration(unit_box(0, 0, 0), unit_box(1.5, 0, 0)) == 0.0);
    BOOST_TEST(tb::penetration(unit_box(0, 0, 0), unit_box(1.0, 0, 0)) == 0.0);
    BOOST_TEST(tb::penetration(unit_box(0, 0, 0), unit_box(1.0, 1.0, std::numbers::pi / 4)) == 0.0);
}

// Oracle: a pyramid as built has every box exactly touching its neighbours and the ground (no
// penetration); one box pushed 0.05 m down overlaps the row below (or the ground) by exactly that.
// A NaN pose is no measure at all.
BOOST_AUTO_TEST_CASE(deepest_penetration_of_a_pyramid, *boost::unit_test::label("performance")) {
    const tb::SceneDesc s = tb::make_pyramid("p", 6);
    std::vector<tb::Probe> poses = built_poses(s);
    BOOST_TEST(tb::deepest_penetration(s, poses) == 0.0);
    for (const std::size_t k : {std::size_t(1), std::size_t(9), s.bodies.size() - 1}) {
        std::vector<tb::Probe> moved = poses;
        moved[k].p.y -= 0.05;
        BOOST_TEST(tb::deepest_penetration(s, moved) == 0.05, boost::test_tools::tolerance(1e-12));
    }
    poses[3].p.x = std::numeric_limits<double>::quiet_NaN();
    BOOST_TEST(std::isinf(tb::deepest_penetration(s, poses)));
}

// Oracle: every pair tested (deepest_by_every_pair above). The rain's boxes, shaken into one
// another and turned at random, must give the same deepest overlap through the grid.
BOOST_AUTO_TEST_CASE(grid_finds_every_overlap, *boost::unit_test::label("performance")) {
    const tb::SceneDesc s = tb::make_rain("r", 300, 6.0, 4.0, 0.25);
    tb::SplitMix64 rng{7};
    for (int trial = 0; trial < 5; ++trial) {
        std::vector<tb::Probe> poses = built_poses(s);
        for (std::size_t i = 1; i < poses.size(); ++i) {
            poses[i].p.x += 0.8 * (rng.uniform() - 0.5);
            poses[i].p.y += 0.8 * (rng.uniform() - 0.5) - 0.4 * trial;
            poses[i].angle = 6.3 * rng.uniform();
        }
        const double expected = deepest_by_every_pair(s, poses);
        BOOST_TEST(expected > 0.0);
        BOOST_TEST(tb::deepest_penetration(s, poses) == expected);
    }
}

// Oracle: E = m |v|^2 / 2 + I w^2 / 2 - m g . p, summed over the dynamic bodies (a chain's links
// carry the mass and inertia of a 1 m x 0.25 m box of density 1).
BOOST_AUTO_TEST_CASE(mechanical_energy_closed_form, *boost::unit_test::label("performance")) {
    const tb::SceneDesc s = tb::make_chain("c", 2);
    const double m = 0.25, inertia = m * (1.0 + 0.0625) / 12.0;
    BOOST_TEST(tb::mass_at_origin(s.bodies[1]).mass == m);
    BOOST_TEST(tb::mass_at_origin(s.bodies[1]).inertia == inertia);
    std::vector<tb::Probe> states = built_poses(s);
    // Released from rest at y = 0: no energy.
    BOOST_TEST(tb::initial_energy(s) == 0.0);
    BOOST_TEST(tb::total_weight(s) == 2 * m * 10.0);
    states[1] = {{0.5, -2.0}, {3.0, 4.0}, 2.0, 0.0};
    states[2] = {{1.5, 1.0}, {0.0, 0.0}, -1.0, 0.0};
    const double expected = 0.5 * m * 25.0 + 0.5 * inertia * 4.0 + m * 10.0 * -2.0 +
                            0.5 * inertia * 1.0 + m * 10.0 * 1.0;
    BOOST_TEST(tb::mechanical_energy(s, states) == expected, boost::test_tools::tolerance(1e-12));
    // A box body: its density times its area; an offset box has its centre of mass elsewhere.
    tb::BodyDesc box = tb::box_body({}, 2.0, true);
    BOOST_TEST(tb::mass_at_origin(box).mass == 4.0);
    BOOST_TEST(tb::mass_at_origin(box).inertia == 4.0 * 8.0 / 12.0,
               boost::test_tools::tolerance(1e-15));
    box.boxes[0].center = {0.5, 0.0};
    BOOST_CHECK_THROW(tb::mass_at_origin(box), std::invalid_argument);
}

// Oracle: the definition, by hand on a small set. (1, 10), (2, 5), (4, 1) are on the frontier;
// (3, 7) is beaten by (2, 5), the second (4, 1) equals the first, a point without a time or an
// error is not a point.
BOOST_AUTO_TEST_CASE(pareto_frontier_and_cheapest_match, *boost::unit_test::label("performance")) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<tb::WorkPoint> pts = {{3, 7}, {1, 10},    {4, 1},    {2, 5},
                                            {4, 1}, {0.5, nan}, {nan, 0.1}};
    BOOST_TEST(tb::pareto_frontier(pts) == (std::vector<std::size_t>{1, 3, 2}),
               boost::test_tools::per_element());
    BOOST_TEST(*tb::cheapest_as_accurate(pts, 6.0) == 3u);  // (2, 5)
    BOOST_TEST(*tb::cheapest_as_accurate(pts, 7.0) == 3u);  // (2, 5) beats (3, 7)
    BOOST_TEST(*tb::cheapest_as_accurate(pts, 10.0) == 1u); // (1, 10), as accurate
    BOOST_TEST(*tb::cheapest_as_accurate(pts, 1.0) == 2u);  // the first of the equal points
    BOOST_TEST(!tb::cheapest_as_accurate(pts, 0.5).has_value());
    BOOST_TEST(*tb::most_accurate(pts) == 2u);
    BOOST_TEST(!tb::most_accurate({{nan, 1.0}}).has_value());
}

BOOST_AUTO_TEST_SUITE_END()
