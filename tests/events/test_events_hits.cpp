// Contact hit events (World::contact_hit_events): the approach speed of a dropped ball against
// the closed-form impact speed, the threshold and the per-shape switch.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double g = 10.0, dt = 1.0 / 60.0, radius = 0.25;
constexpr int substeps = 4;

/// A ball of radius 0.25 m whose lowest point is `height` above a static ground (top face
/// y = 0), at rest, in gravity g, without sleeping.
struct Drop {
    World world{WorldDef{.gravity = {0.0, -g}, .substeps = substeps, .enable_sleep = false}};
    BodyId ground, ball;
    ShapeId ground_shape, ball_shape;
    explicit Drop(double height, bool ball_hits = true, bool ground_hits = false) {
        BodyDef gd;
        gd.type = BodyType::static_body;
        gd.position = {0.0, -0.5};
        ground = world.create_body(gd);
        ShapeDef floor = box_shape(20.0, 1.0);
        floor.enable_hit_events = ground_hits;
        ground_shape = world.create_shape(ground, floor);
        BodyDef bd;
        bd.position = {0.0, height + radius};
        ball = world.create_body(bd);
        ShapeDef disc = circle_shape(radius);
        disc.enable_hit_events = ball_hits;
        ball_shape = world.create_shape(ball, disc);
    }
    /// Steps until the first hit event (or `max_steps`); the number of hit events seen in all.
    int run(int max_steps, ContactHitEvent* first = nullptr, int* first_step = nullptr) {
        int seen = 0;
        for (int s = 1; s <= max_steps; ++s) {
            world.step(dt);
            const auto hits = world.contact_hit_events();
            if (!hits.empty() && seen == 0) {
                if (first)
                    *first = hits[0];
                if (first_step)
                    *first_step = s;
            }
            seen += int(hits.size());
        }
        return seen;
    }
};

/// A static ground 20 m wide whose top face is y = 0.
void ground(World& world) {
    BodyDef gd;
    gd.type = BodyType::static_body;
    gd.position = {0.0, -0.5};
    world.create_shape(world.create_body(gd), box_shape(20.0, 1.0));
}

} // namespace

BOOST_AUTO_TEST_SUITE(events_hits)

// Oracle: free fall, closed form. A ball whose lowest point falls from height h reaches the
// ground at v = sqrt(2 g h). The event reports the approach speed at the start of the step in
// which the contact pushed, before the solver acts, so it differs from v by what the steps'
// granularity allows. Below: the impact happens within the reporting step, in which gravity adds
// at most g dt; and the semi-implicit substeps (h_s = dt / 4) reach a given depth with at most
// g h_s less speed than the exact fall (after n substeps the speed is n g h_s, the distance
// fallen g h_s^2 n (n + 1) / 2). Above: the contact exists only within the speculative distance,
// so a ball may enter the ground by up to one step's travel before it is pushed, gaining at most
// g dt of speed (v dv = g ds over a depth of at most v dt). Hence
// |approach_speed - sqrt(2 g h)| <= g (dt + h_s). The normal points from the ground (shape_a,
// created first) up into the ball; the point lies at the ball's bottom.
BOOST_AUTO_TEST_CASE(approach_speed_of_a_dropped_ball_is_sqrt_2_g_h, *utf::label("DD11")) {
    for (const double h : {0.5, 1.0, 2.0, 5.0}) {
        Drop drop(h);
        ContactHitEvent hit{};
        int step = 0;
        const int count = drop.run(int(std::ceil(std::sqrt(2.0 * h / g) / dt)) + 10, &hit, &step);
        BOOST_TEST_REQUIRE(count >= 1);
        const double exact = std::sqrt(2.0 * g * h);
        const double slack = g * (dt + dt / substeps);
        BOOST_TEST_MESSAGE("h = " << h << " m: approach " << hit.approach_speed
                                  << " m/s, sqrt(2 g h) = " << exact << " m/s, at step " << step);
        BOOST_TEST(hit.approach_speed <= exact + slack);
        BOOST_TEST(hit.approach_speed >= exact - slack);
        BOOST_TEST((hit.shape_a == drop.ground_shape && hit.shape_b == drop.ball_shape));
        BOOST_TEST((hit.body_a == drop.ground && hit.body_b == drop.ball));
        BOOST_TEST(hit.normal.x == 0.0);
        BOOST_TEST(hit.normal.y == 1.0);
        BOOST_TEST(std::abs(hit.point.x) < 1e-9);
        BOOST_TEST(std::abs(hit.point.y) < 0.02); // the ground's face, within the speculative gap
        // A ball that does not bounce (restitution 0) hits once: afterwards it rests, its
        // approach below the 1 m s^-1 threshold.
        BOOST_TEST(count == 1);
    }
}

// Oracle: the threshold's definition. A drop from h hits at about sqrt(2 g h) (above): with the
// threshold above that speed there is no event, below it there is one; the threshold is changed
// at run time.
BOOST_AUTO_TEST_CASE(threshold_selects_the_hits) {
    const double h = 1.0, exact = std::sqrt(2.0 * g * h); // 4.47 m/s
    {
        Drop drop(h);
        drop.world.set_hit_event_threshold(exact + 0.5);
        BOOST_TEST(drop.world.settings().hit_event_threshold == exact + 0.5);
        BOOST_TEST(drop.run(60) == 0);
    }
    {
        Drop drop(h);
        drop.world.set_hit_event_threshold(exact - 1.0);
        BOOST_TEST(drop.run(60) == 1);
    }
    {
        World w(WorldDef{.hit_event_threshold = 3.0});
        BOOST_TEST(w.settings().hit_event_threshold == 3.0);
    }
}

// Oracle: the switch's rule (either shape asks). No shape asks: no event; the ground alone, or
// the ball alone (switched on at run time): one each.
BOOST_AUTO_TEST_CASE(hits_are_reported_when_either_shape_asks) {
    {
        Drop drop(1.0, false, false);
        BOOST_TEST(!drop.world.hit_events_enabled(drop.ball_shape));
        BOOST_TEST(drop.run(60) == 0);
    }
    {
        Drop drop(1.0, false, true);
        BOOST_TEST(drop.run(60) == 1);
    }
    {
        Drop drop(1.0, false, false);
        drop.world.set_hit_events_enabled(drop.ball_shape, true);
        BOOST_TEST(drop.world.hit_events_enabled(drop.ball_shape));
        BOOST_TEST(drop.run(60) == 1);
    }
    {
        Drop drop(1.0, true, false);
        drop.world.set_hit_events_enabled(drop.ball_shape, false);
        BOOST_TEST(drop.run(60) == 0);
    }
}

// Oracle: free fall again. A ball that bounces (restitution 0.5) hits again: each rebound
// leaves at C_R times the speed it came with (DD12), so each hit is slower than the last, the
// first within g (dt + h_s) of sqrt(2 g h) (above).
BOOST_AUTO_TEST_CASE(a_bouncing_ball_hits_ever_slower) {
    World world(WorldDef{.gravity = {0.0, -g}, .enable_sleep = false});
    ground(world);
    BodyDef bd;
    bd.position = {0.0, 2.0 + radius};
    const BodyId ball = world.create_body(bd);
    ShapeDef disc = circle_shape(radius, Material{1.0, 0.5, 0.0});
    disc.enable_hit_events = true;
    world.create_shape(ball, disc);
    std::vector<double> speeds;
    for (int s = 0; s < 300; ++s) {
        world.step(dt);
        for (const ContactHitEvent& e : world.contact_hit_events())
            speeds.push_back(e.approach_speed);
    }
    BOOST_TEST_REQUIRE(speeds.size() >= 2u);
    BOOST_TEST(std::abs(speeds[0] - std::sqrt(2.0 * g * 2.0)) <= g * (dt + dt / substeps));
    for (std::size_t k = 1; k < speeds.size(); ++k)
        BOOST_TEST(speeds[k] < speeds[k - 1]);
    BOOST_TEST(speeds.back() > 1.0); // the threshold
}

// Oracle: uniform motion, closed form, and the event's rule that a hit's point pushed. A ball
// without gravity whose lowest point is 0.019 m above the ground (inside the speculative
// distance, 0.02 m) approaches at 0.6 m/s (above a threshold of 0.5 m/s): it reaches the ground
// at t = 0.019 / 0.6 = 0.032 s, in the second step (dt = 0.0167 s). The first step's manifold
// already holds its point, fast, but the ball is still 0.009 m away at that step's end, so the
// point takes no impulse and no hit is reported; the second step reports the one hit, at 0.6
// m/s.
BOOST_AUTO_TEST_CASE(a_fast_point_that_does_not_arrive_within_the_step_is_no_hit,
                     *utf::label("DD11")) {
    World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false});
    world.set_hit_event_threshold(0.5);
    ground(world);
    const double gap = 0.019, speed = 0.6;
    BodyDef bd;
    bd.position = {0.0, gap + radius};
    bd.linear_velocity = {0.0, -speed};
    ShapeDef disc = circle_shape(radius);
    disc.enable_hit_events = true;
    world.create_shape(world.create_body(bd), disc);
    BOOST_TEST_REQUIRE(gap < WorldDef{}.speculative_distance);
    BOOST_TEST_REQUIRE(gap / speed > dt);
    BOOST_TEST_REQUIRE(gap / speed <= 2.0 * dt);
    world.step(dt);
    BOOST_TEST(world.contact_hit_events().empty());
    world.step(dt);
    BOOST_TEST_REQUIRE(world.contact_hit_events().size() == 1u);
    BOOST_TEST(world.contact_hit_events()[0].approach_speed == speed,
               boost::test_tools::tolerance(1e-12));
}

// Oracle: the threshold's definition at its boundary: a hit approaches *faster* than
// hit_event_threshold (world_def.hpp), strictly. The ball above (no gravity, 0.6 m/s) hits in
// its second step; the same ball with the threshold set to the approach speed that hit reported
// gives no event, and with the threshold one double below it gives the same hit again.
BOOST_AUTO_TEST_CASE(a_hit_at_exactly_the_threshold_is_no_hit, *utf::label("DD11")) {
    const auto hits = [](double threshold) {
        World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false});
        world.set_hit_event_threshold(threshold);
        ground(world);
        BodyDef bd;
        bd.position = {0.0, 0.019 + radius};
        bd.linear_velocity = {0.0, -0.6};
        ShapeDef disc = circle_shape(radius);
        disc.enable_hit_events = true;
        world.create_shape(world.create_body(bd), disc);
        std::vector<ContactHitEvent> out;
        for (int s = 0; s < 2; ++s) {
            world.step(dt);
            const auto step_hits = world.contact_hit_events();
            out.insert(out.end(), step_hits.begin(), step_hits.end());
        }
        return out;
    };
    const std::vector<ContactHitEvent> first = hits(0.5);
    BOOST_TEST_REQUIRE(first.size() == 1u);
    const double speed = first[0].approach_speed;
    BOOST_TEST(hits(speed).empty());
    const std::vector<ContactHitEvent> below = hits(std::nextafter(speed, 0.0));
    BOOST_TEST_REQUIRE(below.size() == 1u);
    BOOST_TEST(below[0].approach_speed == speed);
}

// Oracle: the event's rule, a hit is the fastest of the manifold's points that approached
// faster than the threshold and pushed, and DD11's approach speed in closed form. Without
// gravity a flat 1 m x 0.2 m box 5 mm above the ground falls at 1 m/s turning at 0.5 rad/s:
// its bottom corners (0.5 m either side of the centre) approach at 1 + 0.25 and 1 - 0.25 m/s
// (v + omega x r) and both land within the first step. The hit is the faster corner's, 1.25
// m/s, on its side; turning the other way, the other corner's, so that either point of the
// manifold is in turn the faster one. Falling at 0.5 m/s and turning at 0.6 rad/s, 2 mm above
// the ground, the corners approach at 0.8 and 0.2 m/s: only the first is faster than the
// threshold, and the hit is its 0.8 m/s, though the other corner pushes too.
BOOST_AUTO_TEST_CASE(a_hit_is_the_fastest_point_of_its_manifold, *utf::label("DD11")) {
    struct Fall {
        double gap, speed, spin, hit;
    };
    for (const Fall f : {Fall{0.005, 1.0, 0.5, 1.25}, Fall{0.005, 1.0, -0.5, 1.25},
                         Fall{0.002, 0.5, 0.6, 0.8}, Fall{0.002, 0.5, -0.6, 0.8}}) {
        const double spin = f.spin;
        World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false});
        world.set_hit_event_threshold(0.5);
        ground(world);
        BodyDef bd;
        bd.position = {0.0, f.gap + 0.1};
        bd.linear_velocity = {0.0, -f.speed};
        bd.angular_velocity = spin;
        ShapeDef bar = box_shape(1.0, 0.2);
        bar.enable_hit_events = true;
        world.create_shape(world.create_body(bd), bar);
        world.step(dt);
        BOOST_TEST_REQUIRE(world.contacts().size() == 1u);
        BOOST_TEST_REQUIRE(world.contacts()[0].point_count == 2);
        for (int j = 0; j < 2; ++j)
            BOOST_TEST_REQUIRE(world.contacts()[0].points[j].normal_impulse > 0.0, "corner " << j);
        BOOST_TEST_REQUIRE(world.contact_hit_events().size() == 1u);
        const ContactHitEvent& hit = world.contact_hit_events()[0];
        BOOST_TEST(hit.approach_speed == f.hit, boost::test_tools::tolerance(1e-12));
        BOOST_TEST(hit.point.x * spin < 0.0, "the faster corner's side, spin " << spin);
    }
}

// Oracle: the event's rule for a tie (events.hpp: of two points that approached equally fast,
// the first in the manifold's order) and DD11's approach speed. Without gravity a flat 1 m x
// 0.2 m box 5 mm above the ground falls at 1 m/s without turning: both bottom corners approach
// at exactly 1 m/s and both land and push within the first step. The hit is the manifold's
// first point, as contacts() lists it.
BOOST_AUTO_TEST_CASE(of_two_points_as_fast_the_hit_is_the_first, *utf::label("DD11")) {
    World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false});
    world.set_hit_event_threshold(0.5);
    ground(world);
    BodyDef bd;
    bd.position = {0.0, 0.005 + 0.1};
    bd.linear_velocity = {0.0, -1.0};
    ShapeDef bar = box_shape(1.0, 0.2);
    bar.enable_hit_events = true;
    world.create_shape(world.create_body(bd), bar);
    world.step(dt);
    BOOST_TEST_REQUIRE(world.contacts().size() == 1u);
    const ContactInfo& c = world.contacts()[0];
    BOOST_TEST_REQUIRE(c.point_count == 2);
    for (int j = 0; j < 2; ++j)
        BOOST_TEST_REQUIRE(c.points[j].normal_impulse > 0.0, "corner " << j);
    BOOST_TEST_REQUIRE(c.points[0].point.x != c.points[1].point.x);
    BOOST_TEST_REQUIRE(world.contact_hit_events().size() == 1u);
    const ContactHitEvent& hit = world.contact_hit_events()[0];
    BOOST_TEST(hit.approach_speed == 1.0);
    BOOST_TEST(hit.point.x == c.points[0].point.x);
    BOOST_TEST(hit.point.y == c.points[0].point.y);
}

// Oracle: the event's rule, a hit's point approached faster than the threshold and pushed, on a
// manifold of two points that each do one of the two. A 1 m x 0.2 m box stands on its left
// bottom corner, tilted so that its right one is 0.019 m up, and turns about the corner
// (gravity 10 m/s^2) with that corner at rest and the right one coming down at 0.6 m/s (a
// threshold of 0.5 m/s). The left corner pushes (it bears the weight) but does not approach;
// the right one approaches but, rigid-pivot closed form, is still up at the step's end (the
// weight's torque about the corner turns it at alpha = g 0.5 m / 0.347 m^2 = 14.4 rad/s^2, so
// theta = 0.019 - 0.6 dt - 14.4 dt^2 / 2 = 0.0070 rad): no hit in the first step. It lands in
// the second: one hit, at the right corner (x = 1 m), faster than it started.
BOOST_AUTO_TEST_CASE(a_point_that_pushes_without_approaching_is_no_hit, *utf::label("DD11")) {
    World world(WorldDef{.gravity = {0.0, -g}, .enable_sleep = false});
    world.set_hit_event_threshold(0.5);
    ground(world);
    const double lift = 0.019, angle = std::asin(lift), c = std::cos(angle);
    const double omega = -0.6 / c; // the right corner, 1 m from the left, comes down at 0.6 m/s
    const Vec2d corner{-0.5 * c + 0.1 * lift, -0.5 * lift - 0.1 * c}; // left corner from centre
    BodyDef bd;
    bd.position = {-corner.x, -corner.y}; // the left corner at the origin
    bd.angle = angle;
    bd.angular_velocity = omega;
    bd.linear_velocity = {omega * corner.y, -omega * corner.x}; // the left corner at rest
    ShapeDef box = box_shape(1.0, 0.2);
    box.enable_hit_events = true;
    const BodyId body = world.create_body(bd);
    world.create_shape(body, box);
    world.step(dt);
    BOOST_TEST_REQUIRE(world.contacts().size() == 1u);
    BOOST_TEST_REQUIRE(world.contacts()[0].point_count == 2);
    BOOST_TEST(world.orientation(body) > 0.0); // the right corner still up
    BOOST_TEST(world.contact_hit_events().empty());
    world.step(dt);
    BOOST_TEST_REQUIRE(world.contact_hit_events().size() == 1u);
    const ContactHitEvent& hit = world.contact_hit_events()[0];
    BOOST_TEST(hit.point.x == 1.0, boost::test_tools::tolerance(0.01));
    BOOST_TEST(hit.approach_speed > 0.6);
}

BOOST_AUTO_TEST_SUITE_END()
