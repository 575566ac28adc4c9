// R1: the world as a space for bodies: handles, creation and destruction, determinism.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <tuple>
#include <utility>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

/// A small pile: boxes and circles dropped on a static ground, with friction and restitution.
void build_pile(World& world) {
    BodyDef gd;
    gd.type = BodyType::static_body;
    const BodyId ground = world.create_body(gd);
    world.create_shape(ground, box_shape(20.0, 1.0, Material{1.0, 0.0, 0.6}));
    for (int i = 0; i < 24; ++i) {
        BodyDef bd;
        bd.position = {-3.0 + 0.55 * (i % 8) + 0.01 * i, 1.0 + 1.1 * (i / 8)};
        bd.angle = 0.1 * i;
        const BodyId b = world.create_body(bd);
        if (i % 3 == 0) {
            world.create_shape(b, circle_shape(0.25, Material{1.0, 0.3, 0.6}));
        } else {
            world.create_shape(b, box_shape(0.5, 0.5, Material{1.0, 0.1, 0.6}));
        }
    }
}

} // namespace

BOOST_AUTO_TEST_SUITE(world)

// Oracle: the handle contract (index + generation): a destroyed body's handle, and a handle
// never issued, are rejected with InvalidHandle; a recycled slot gets a new generation.
BOOST_AUTO_TEST_CASE(stale_handles_are_errors, *utf::label("R1")) {
    World world;
    const BodyId a = world.create_body({});
    world.destroy_body(a);
    BOOST_TEST(!world.is_valid(a));
    BOOST_CHECK_THROW(world.position(a), InvalidHandle);
    BOOST_CHECK_THROW(world.destroy_body(a), InvalidHandle);
    BOOST_CHECK_THROW(world.create_shape(a, circle_shape(1.0)), InvalidHandle);
    BOOST_CHECK_THROW(world.position(BodyId{42, 1, world.tag()}), InvalidHandle);
    BOOST_CHECK_THROW(world.position(BodyId{a.index + 1, 1, world.tag()}),
                      InvalidHandle); // one past the end
    BOOST_TEST(!world.is_valid(BodyId{a.index + 1, 1, world.tag()}));
    const BodyId b = world.create_body({});
    BOOST_TEST(b.index == a.index);
    BOOST_TEST(b.generation != a.generation);
    BOOST_TEST(world.is_valid(b));
    BOOST_TEST(world.body_count() == 1u);
}

// Oracle: bookkeeping identities: bodies() lists exactly the live bodies; destroying a body
// removes its shapes and contacts.
BOOST_AUTO_TEST_CASE(create_and_destroy, *utf::label("R1")) {
    World world;
    build_pile(world);
    for (int i = 0; i < 120; ++i)
        world.step(1.0 / 60.0);
    BOOST_TEST(world.body_count() == 25u);
    BOOST_TEST(!world.contacts().empty());
    for (BodyId b : world.bodies()) {
        if (world.type(b) == BodyType::static_body) {
            const ShapeId s = world.shapes(b).front();
            world.destroy_body(b);
            BOOST_TEST(!world.is_valid(s));
        }
    }
    world.step(1.0 / 60.0);
    for (const ContactInfo& c : world.contacts()) {
        BOOST_TEST(world.is_valid(c.body_a));
        BOOST_TEST(world.is_valid(c.body_b));
    }
    BOOST_TEST(world.body_count() == 24u);
}

// Oracle: R2's rule that a new body starts from the state its input gives, and nothing else:
// a body created in the slot of a destroyed one (spinning, damped, pushed by a one-step force
// and torque, with a shape) steps, with its own shape, to the bits of the same body created in
// a fresh world: its state, mass and inertia.
BOOST_AUTO_TEST_CASE(a_body_in_a_reused_slot_starts_afresh, *utf::label("R2")) {
    const BodyDef def{.position = {0.0, 1.0}, .linear_velocity = {0.5, 0.0}};
    const auto run = [&](bool reuse) {
        World world;
        if (reuse) {
            const BodyId old = world.create_body({.position = {5.0, 5.0},
                                                  .angle = 0.7,
                                                  .linear_velocity = {1.0, 2.0},
                                                  .angular_velocity = 3.0,
                                                  .linear_damping = 0.5,
                                                  .angular_damping = 0.25});
            world.create_shape(old, box_shape(1.0, 2.0, Material{3.0, 0.1, 0.5}, {0.3, 0.1}));
            world.apply_force(old, {10.0, 0.0}, {5.0, 6.0});
            world.apply_torque(old, 4.0);
            world.destroy_body(old);
        }
        const BodyId b = world.create_body(def);
        world.create_shape(b, circle_shape(0.5));
        for (int i = 0; i < 10; ++i)
            world.step(1.0 / 60.0);
        return std::tuple{world.state(b), world.mass(b), world.inertia(b)};
    };
    const auto [fresh, fresh_mass, fresh_inertia] = run(false);
    const auto [reused, reused_mass, reused_inertia] = run(true);
    BOOST_TEST(std::memcmp(&fresh, &reused, sizeof fresh) == 0);
    BOOST_TEST(fresh_mass == reused_mass);
    BOOST_TEST(fresh_inertia == reused_inertia);
}

// Oracle: the contact report's contract (world.hpp): after a destruction it lists no contact of
// the destroyed body, whether or not it was read before; it always names live bodies only.
BOOST_AUTO_TEST_CASE(contact_report_follows_destruction, *utf::label("R1") * utf::label("R7")) {
    for (const bool read_before : {false, true}) {
        World world;
        build_pile(world);
        for (int i = 0; i < 120; ++i)
            world.step(1.0 / 60.0);
        if (read_before)
            BOOST_TEST_REQUIRE(!world.contacts().empty());
        BodyId ground{};
        for (BodyId b : world.bodies()) {
            if (world.type(b) == BodyType::static_body)
                ground = b;
        }
        world.destroy_body(ground);
        for (const ContactInfo& c : world.contacts()) {
            BOOST_TEST(world.is_valid(c.body_a));
            BOOST_TEST(world.is_valid(c.body_b));
        }
    }
}

// Oracle: the stated contract of world.hpp, checked against the report before the destruction.
// Destroying a body removes its contacts (the last
// contact moves into each gap, with its impulses kept beside it); every other contact must
// still report the impulses of the last step, bit for bit, and the world must step on.
BOOST_AUTO_TEST_CASE(surviving_contacts_keep_their_impulses, *utf::label("R1") * utf::label("R7")) {
    World world;
    build_pile(world);
    for (int i = 0; i < 120; ++i)
        world.step(1.0 / 60.0);
    const std::vector<ContactInfo> before(world.contacts().begin(), world.contacts().end());
    BOOST_TEST_REQUIRE(before.size() > 20u);
    const BodyId doomed = before[before.size() / 3].body_b; // one with contacts on both sides
    BOOST_TEST_REQUIRE((world.type(doomed) == BodyType::dynamic));
    world.destroy_body(doomed);
    std::size_t kept = 0;
    for (const ContactInfo& b : before) {
        if (b.body_a == doomed || b.body_b == doomed)
            continue;
        ++kept;
        const ContactInfo* a = nullptr;
        for (const ContactInfo& c : world.contacts()) {
            if (c.shape_a == b.shape_a && c.shape_b == b.shape_b)
                a = &c;
        }
        BOOST_TEST_REQUIRE(a != nullptr);
        BOOST_TEST_REQUIRE(a->point_count == b.point_count);
        for (int j = 0; j < b.point_count; ++j) {
            BOOST_TEST(a->points[j].normal_impulse == b.points[j].normal_impulse);
            BOOST_TEST(a->points[j].tangent_impulse == b.points[j].tangent_impulse);
        }
    }
    BOOST_TEST(world.contacts().size() == kept);
    BOOST_TEST(kept < before.size());
    for (int i = 0; i < 60; ++i)
        world.step(1.0 / 60.0);
    for (BodyId b : world.bodies())
        BOOST_TEST(std::isfinite(world.position(b).y));
}

// Oracle: determinism by construction: the same input gives bitwise the same state (equal
// state hashes after every step of two independent runs).
BOOST_AUTO_TEST_CASE(bitwise_deterministic, *utf::label("determinism")) {
    World w1, w2;
    build_pile(w1);
    build_pile(w2);
    for (int i = 0; i < 240; ++i) {
        w1.step(1.0 / 60.0);
        w2.step(1.0 / 60.0);
        BOOST_TEST_REQUIRE(w1.state_hash() == w2.state_hash());
    }
}

// Oracle: the pile's own geometry: after settling on the ground (top at y = 0.5) every body
// rests above it, at rest, and nothing has fallen through (T5: no lasting overlap).
BOOST_AUTO_TEST_CASE(pile_settles_on_ground, *utf::label("R7") * utf::label("R8")) {
    World world;
    build_pile(world);
    for (int i = 0; i < 600; ++i)
        world.step(1.0 / 60.0);
    for (BodyId b : world.bodies()) {
        if (world.type(b) != BodyType::dynamic)
            continue;
        BOOST_TEST(world.position(b).y > 0.5 + 0.2);
        BOOST_TEST(length(world.velocity(b)) < 0.05);
    }
}

// Oracle: closed form: n steps of dt must read back as n dt (the double nearest to it), so that a
// load switching at t = n dt acts from step n on; plain summation gives 0.49999999999999994
// after 15 steps of 1/30 s.
BOOST_AUTO_TEST_CASE(simulated_time_is_n_dt, *utf::label("R5") * utf::label("IM1")) {
    World world;
    for (int i = 0; i < 15; ++i)
        world.step(1.0 / 30.0);
    BOOST_TEST(world.time() == 0.5);
    for (int i = 0; i < 3000; ++i)
        world.step(1.0 / 60.0);
    BOOST_TEST(world.time() == 50.5);
}

// Oracle: rigidity (A1) and Table 2: through a pile's collisions every box keeps its shape
// (the distances between its world-frame corners equal the side lengths to round-off), and
// every output p, v, phi, omega stays finite with phi in [0, 2 pi).
BOOST_AUTO_TEST_CASE(bodies_stay_rigid_and_outputs_valid,
                     *utf::label("A1") * utf::label("DCO_p") * utf::label("DCO_v") *
                         utf::label("DCO_omega") * utf::label("DCO_phi")) {
    World world;
    build_pile(world);
    for (int i = 0; i < 300; ++i) {
        world.step(1.0 / 60.0);
        for (BodyId b : world.bodies()) {
            const BodyState s = world.state(b);
            BOOST_TEST_REQUIRE(std::isfinite(s.position.x + s.position.y));
            BOOST_TEST_REQUIRE(std::isfinite(s.velocity.x + s.velocity.y + s.angular_velocity));
            BOOST_TEST_REQUIRE((s.orientation >= 0.0 && s.orientation < 2.0 * M_PI));
        }
    }
    for (BodyId b : world.bodies()) {
        // Boxes only: I / m = (0.5^2 + 0.5^2) / 12 for the 0.5 m boxes, r^2 / 2 for the circles.
        if (world.type(b) != BodyType::dynamic || world.inertia(b) / world.mass(b) < 0.04)
            continue;
        const double phi = world.orientation(b);
        const Vec2d o = world.origin(b);
        const Vec2d u{0.25 * std::cos(phi), 0.25 * std::sin(phi)};
        const Vec2d v{-u.y, u.x};
        // The shape is still the rigid 0.5 m square at the body's pose: points just inside
        // each of its four corners belong to it.
        for (const Vec2d corner : {u + v, u - v, -1.0 * u + v, -1.0 * u - v}) {
            bool found = false;
            for (ShapeId s : world.query_point(o + 0.98 * corner))
                found = found || s == world.shapes(b)[0];
            BOOST_TEST(found);
        }
    }
}

// Oracle: closed forms. A body's shapes are listed in creation order after one in the middle is
// destroyed, and its mass is the remaining shapes' (DD1: density x area, 1 kg m^-2 x 1 m^2 each).
BOOST_AUTO_TEST_CASE(shape_list_survives_destruction, *utf::label("R1") * utf::label("DD1")) {
    World world;
    const BodyId b = world.create_body({});
    std::vector<ShapeId> made;
    for (int k = 0; k < 4; ++k)
        made.push_back(world.create_shape(b, box_shape(1.0, 1.0, {}, {2.0 * k, 0.0})));
    world.destroy_shape(made[1]);
    const std::vector<ShapeId> left = world.shapes(b);
    BOOST_TEST_REQUIRE(left.size() == 3u);
    BOOST_TEST((left[0] == made[0] && left[1] == made[2] && left[2] == made[3]));
    BOOST_TEST(world.mass(b) == 3.0);
    // The centre of mass of unit boxes at x = 0, 4, 6: their mean.
    BOOST_TEST(world.local_center(b).x == 10.0 / 3.0, boost::test_tools::tolerance(1e-15));
    const ShapeId again = world.create_shape(b, box_shape(1.0, 1.0, {}, {8.0, 0.0}));
    BOOST_TEST((world.shapes(b).back() == again));
    BOOST_TEST(world.mass(b) == 4.0);
}

// Oracle: geometry. A box teleported (set_transform) onto a resting box between steps, and a
// shape added to a body between steps, collide in the very next step at their new places: the
// narrow phase must not use a pose or a fat box from before the change.
BOOST_AUTO_TEST_CASE(changes_between_steps_are_seen_by_the_next_step, *utf::label("R7")) {
    World world({.gravity = {0.0, 0.0}});
    BodyDef sd;
    sd.type = BodyType::static_body;
    const BodyId ground = world.create_body(sd);
    world.create_shape(ground, box_shape(4.0, 1.0));
    BodyDef bd;
    bd.position = {20.0, 20.0};
    const BodyId box = world.create_body(bd);
    world.create_shape(box, box_shape(1.0, 1.0));
    bd.position = {-20.0, 20.0};
    const BodyId bare = world.create_body(bd);
    world.step(1.0 / 60.0);
    BOOST_TEST(world.contacts().empty());
    // Resting on the ground's top face (y = 0.5), 1 cm deep.
    world.set_transform(box, {0.0, 0.99}, 0.0);
    world.set_transform(bare, {1.5, 0.99}, 0.0);
    world.create_shape(bare, box_shape(1.0, 1.0));
    world.step(1.0 / 60.0);
    BOOST_TEST_REQUIRE(world.contacts().size() == 2u);
    for (const ContactInfo& c : world.contacts()) {
        BOOST_TEST(c.point_count == 2);
        BOOST_TEST(std::abs(c.normal.y) == 1.0);
        BOOST_TEST(c.points[0].separation < 0.0);
    }
}

// Oracle: IM1 with a load. Bodies with a load function get its force; those without do not,
// also after the loaded ones are destroyed or their load removed (the world counts them).
BOOST_AUTO_TEST_CASE(loads_follow_their_bodies, *utf::label("R5") * utf::label("IM1")) {
    World world({.gravity = {0.0, 0.0}});
    BodyDef bd;
    bd.mass = 2.0;
    bd.load = [](double) { return Load{{4.0, 0.0}, 0.0}; };
    const BodyId a = world.create_body(bd);
    const BodyId b = world.create_body(bd);
    bd.load = nullptr;
    const BodyId c = world.create_body(bd);
    const double dt = 0.5;
    world.step(dt);
    // a = F / m = 2 m s^-2 for one step.
    BOOST_TEST(world.velocity(a).x == 1.0);
    BOOST_TEST(world.velocity(b).x == 1.0);
    BOOST_TEST(world.velocity(c).x == 0.0);
    world.destroy_body(a);
    world.step(dt);
    BOOST_TEST(world.velocity(b).x == 2.0);
    world.set_load(b, nullptr);
    world.set_load(c, [](double) { return Load{{-4.0, 0.0}, 0.0}; });
    world.step(dt);
    BOOST_TEST(world.velocity(b).x == 2.0);
    BOOST_TEST(world.velocity(c).x == -1.0);
}

// Oracle: brute force, IM4 written out here: a circle's box is its centre (read back from the
// world each step) plus and minus its radius, and two boxes overlap when their intervals
// overlap on both axes. query_aabb must name exactly the circles whose boxes meet the query
// box, step after step, while they fly across the world and leave their broad-phase boxes.
BOOST_AUTO_TEST_CASE(query_aabb_follows_moving_bodies, *utf::label("IM4")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    const double r = 0.3;
    std::vector<BodyId> bodies;
    std::vector<ShapeId> shapes;
    for (int i = 0; i < 12; ++i) {
        BodyDef bd;
        bd.position = {-4.0 + 0.8 * i, 0.9 * (i % 4) - 1.5};
        bd.linear_velocity = {std::cos(0.7 * i) * (2.0 + 0.5 * i), std::sin(0.7 * i) * 3.0};
        bodies.push_back(world.create_body(bd));
        shapes.push_back(world.create_shape(bodies.back(), circle_shape(r)));
    }
    int hits = 0;
    for (int step = 0; step < 60; ++step) {
        world.step(1.0 / 60.0);
        for (int qx = -3; qx <= 3; ++qx) {
            for (int qy = -2; qy <= 2; ++qy) {
                const Aabb q{1.5 * qx - 0.7, 1.5 * qy - 0.7, 1.5 * qx + 0.7, 1.5 * qy + 0.7};
                std::vector<std::uint32_t> want, got;
                for (std::size_t i = 0; i < bodies.size(); ++i) {
                    const Vec2d c = world.position(bodies[i]);
                    if (c.x - r <= q.max_x && q.min_x <= c.x + r && c.y - r <= q.max_y &&
                        q.min_y <= c.y + r)
                        want.push_back(shapes[i].index);
                }
                for (const ShapeId s : world.query_aabb(q))
                    got.push_back(s.index);
                std::sort(want.begin(), want.end());
                std::sort(got.begin(), got.end());
                BOOST_TEST(got == want, "step " << step << ", box at (" << qx << ", " << qy << ")");
                hits += int(want.size());
            }
        }
    }
    BOOST_TEST(hits > 100); // not vacuous: the boxes do meet the circles
}

// Oracle: the handle contract (index + generation) for shapes: a live shape's handle is valid,
// a destroyed shape's is not and is rejected with InvalidHandle, and a shape created in the
// recycled slot gets a handle of its own while the old one stays invalid.
BOOST_AUTO_TEST_CASE(stale_shape_handles_are_errors, *utf::label("R1")) {
    World world;
    const BodyId b = world.create_body({});
    const ShapeId s = world.create_shape(b, circle_shape(1.0));
    BOOST_TEST(world.is_valid(s));
    world.destroy_shape(s);
    BOOST_TEST(!world.is_valid(s));
    BOOST_CHECK_THROW(world.destroy_shape(s), InvalidHandle);
    const ShapeId t = world.create_shape(b, circle_shape(0.5));
    BOOST_TEST(t.index == s.index); // the slot is recycled...
    BOOST_TEST(t.generation != s.generation);
    BOOST_TEST(world.is_valid(t)); // ...under a new generation
    BOOST_TEST(!world.is_valid(s));
    BOOST_CHECK_THROW(world.destroy_shape(s), InvalidHandle);
    BOOST_TEST(!world.is_valid(ShapeId{42, 1, world.tag()}));
    BOOST_TEST(!world.is_valid(ShapeId{t.index + 1, 1, world.tag()})); // one past the last slot
}

// Oracle: the events' stated meaning (world.hpp): the begin events of a step are exactly the
// pairs touching after it that did not touch after the step before, the end events exactly
// those that touched before and no longer do; each once, none while a pair stays as it was.
// Bouncy boxes and discs dropped on the ground in a row, so that pairs begin, rest, bounce
// off and begin again over 3 s.
BOOST_AUTO_TEST_CASE(contact_events_are_the_changes_of_the_touching_pairs, *utf::label("R7")) {
    World world(WorldDef{.gravity = {0.0, -9.81}});
    BodyDef gd;
    gd.type = BodyType::static_body;
    world.create_shape(world.create_body(gd), box_shape(40.0, 1.0, Material{1.0, 0.5, 0.6}));
    for (int k = 0; k < 12; ++k) {
        BodyDef bd;
        bd.position = {-6.0 + 1.1 * k, 1.0 + 0.3 * k};
        const BodyId b = world.create_body(bd);
        world.create_shape(b, k % 2 == 0 ? box_shape(0.8, 0.8, Material{1.0, 0.5, 0.6})
                                         : circle_shape(0.4, Material{1.0, 0.5, 0.6}));
    }
    using Pair = std::pair<std::uint64_t, std::uint64_t>;
    const auto key = [](ShapeId a, ShapeId b) {
        const std::uint64_t x = std::uint64_t(a.index) << 32 | a.generation;
        const std::uint64_t y = std::uint64_t(b.index) << 32 | b.generation;
        return Pair{std::min(x, y), std::max(x, y)};
    };
    std::vector<Pair> before;
    int begins = 0, ends = 0;
    for (int step = 0; step < 180; ++step) {
        world.step(1.0 / 60.0);
        std::vector<Pair> now, begun, ended;
        for (const ContactInfo& c : world.contacts())
            now.push_back(key(c.shape_a, c.shape_b));
        for (const ContactEvent& e : world.contact_begin_events())
            begun.push_back(key(e.shape_a, e.shape_b));
        for (const ContactEvent& e : world.contact_end_events())
            ended.push_back(key(e.shape_a, e.shape_b));
        for (std::vector<Pair>* v : {&now, &begun, &ended})
            std::sort(v->begin(), v->end());
        std::vector<Pair> expect_begun, expect_ended;
        std::set_difference(now.begin(), now.end(), before.begin(), before.end(),
                            std::back_inserter(expect_begun));
        std::set_difference(before.begin(), before.end(), now.begin(), now.end(),
                            std::back_inserter(expect_ended));
        BOOST_TEST(begun == expect_begun, "step " << step);
        BOOST_TEST(ended == expect_ended, "step " << step);
        begins += int(begun.size());
        ends += int(ended.size());
        before = now;
    }
    BOOST_TEST_MESSAGE("contact events: " << begins << " begins, " << ends << " ends");
    BOOST_TEST(ends > 0); // some pairs did part again: the test sees both kinds
}

BOOST_AUTO_TEST_SUITE_END()
