// Material mixing (DD42): the default rules and the game's mixing functions against the closed
// forms of a box sliding to rest and of a ball's rebound, the functions' refusals (a value that
// is no friction or restitution, named, the world unchanged), values equal to the current ones
// changing no bit, and equal results on 1 to 4 workers.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "support/pyramid.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;
namespace utf = boost::unit_test;

namespace {

constexpr double dt = 1.0 / 60.0;
constexpr double g = 9.81;

/// A 1 m box resting on a wide static floor (top face y = 0) and sliding along it at v0.
struct Slide {
    World world{WorldDef{.gravity = {0.0, -g}, .enable_sleep = false}};
    BodyId box;
    ShapeId floor_shape, box_shape_id;
    static constexpr double v0 = 4.0; // m s^-1
    Slide(double mu_floor, double mu_box, std::uint64_t id_floor = 0, std::uint64_t id_box = 0) {
        BodyDef fd;
        fd.type = BodyType::static_body;
        fd.position = {0.0, -0.5};
        Material mf{1.0, 0.0, mu_floor};
        mf.user_material_id = id_floor;
        floor_shape = world.create_shape(world.create_body(fd), box_shape(200.0, 1.0, mf));
        BodyDef bd;
        bd.position = {0.0, 0.5};
        bd.linear_velocity = {v0, 0.0};
        box = world.create_body(bd);
        Material mb{1.0, 0.0, mu_box};
        mb.user_material_id = id_box;
        box_shape_id = world.create_shape(box, box_shape(1.0, 1.0, mb));
    }
    /// The distance slid until the box stops (4 s is ample for mu >= 0.1: v0 / (mu g) < 4.1 s).
    double distance() {
        for (int i = 0; i < 600 && world.velocity(box).x > 0.0; ++i)
            world.step(dt);
        BOOST_TEST(world.velocity(box).x <= 1e-9); // it stopped
        return world.position(box).x;
    }
};

/// v0^2 / (2 mu g): the closed form of a box decelerated by Coulomb friction mu g. The substeps
/// (h = dt / 4) cut it short by about v0 h / 2; one substep's travel at v0 bounds that.
double sliding_distance(double mu) {
    return Slide::v0 * Slide::v0 / (2.0 * mu * g);
}
constexpr double substep_travel = Slide::v0 * dt / 4.0;

/// A ball flying at 3 m/s onto a static floor without gravity: the speed it leaves with.
double rebound_speed(double e_ball, double e_floor, const MaterialMixFunction& mix = {}) {
    World world{WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false}};
    if (mix)
        world.set_restitution_mixing(mix);
    BodyDef fd;
    fd.type = BodyType::static_body;
    fd.position = {0.0, -0.5};
    world.create_shape(world.create_body(fd), box_shape(10.0, 1.0, Material{1.0, e_floor, 0.0}));
    BodyDef bd;
    bd.position = {0.0, 1.0};
    bd.linear_velocity = {0.0, -3.0};
    const BodyId ball = world.create_body(bd);
    world.create_shape(ball, circle_shape(0.25, Material{1.0, e_ball, 0.0}));
    for (int i = 0; i < 60; ++i)
        world.step(dt);
    BOOST_TEST(world.velocity(ball).y > 0.0);
    return world.velocity(ball).y;
}

double min_mix(double a, std::uint64_t, double b, std::uint64_t) {
    return std::min(a, b);
}

/// A pyramid with a mixing function on the ice (user material 7) and the rest as DD42.
void icy_pyramid(World& w) {
    test::build_pyramid(w, 8);
    int k = 0;
    for (const BodyId b : w.bodies())
        for (const ShapeId s : w.shapes(b))
            if (k++ % 3 == 1)
                w.set_user_material(s, 7);
    w.set_friction_mixing([](double a, std::uint64_t ia, double b, std::uint64_t ib) {
        return ia == 7 || ib == 7 ? 0.05 : std::sqrt(a * b);
    });
    w.set_restitution_mixing([](double, std::uint64_t ia, double, std::uint64_t ib) {
        return ia == 7 && ib == 7 ? 0.5 : 0.0;
    });
}

} // namespace

BOOST_AUTO_TEST_SUITE(contact_hooks_mixing)

// Oracle: closed form, d = v0^2 / (2 mu g) with DD42's default mu = sqrt(mu_a mu_b): 0.8 and
// 0.2 give 0.4 (1.019 m), within one substep's travel (the integration's start-up error).
BOOST_AUTO_TEST_CASE(default_friction_is_the_geometric_mean, *utf::label("DD42")) {
    Slide s(0.8, 0.2);
    const double d = s.distance();
    BOOST_TEST(std::abs(d - sliding_distance(0.4)) <= substep_travel);
    // Not the arithmetic mean's 0.5 (0.815 m) nor either coefficient's: the test can tell.
    BOOST_TEST(std::abs(d - sliding_distance(0.5)) > 10.0 * substep_travel);
}

// Oracle: closed form, d = v0^2 / (2 mu g) with the function's mu = min(mu_a, mu_b) = 0.2
// (4.077 m), set before the contact exists and, on a second world, while the box slides.
BOOST_AUTO_TEST_CASE(friction_mixing_function_replaces_the_rule, *utf::label("DD42")) {
    {
        Slide s(0.8, 0.2);
        s.world.set_friction_mixing(min_mix);
        BOOST_TEST(std::abs(s.distance() - sliding_distance(0.2)) <= substep_travel);
    }
    {
        Slide s(0.8, 0.2);
        s.world.step(dt); // the contact exists, with DD42's 0.4
        const double x1 = s.world.position(s.box).x, v1 = s.world.velocity(s.box).x;
        s.world.set_friction_mixing(min_mix); // applies to it now
        const double rest = v1 * v1 / (2.0 * 0.2 * g);
        BOOST_TEST(std::abs(s.distance() - x1 - rest) <= substep_travel);
    }
}

// Oracle: closed form with the friction the function gives for the pair of user material ids
// (ice 7 on anything: 0.1, 2.039 m); the ids reach it in the order of the shapes' materials.
BOOST_AUTO_TEST_CASE(user_material_ids_reach_the_function, *utf::label("DD42")) {
    Slide s(0.8, 0.8, 3, 0);
    std::uint64_t seen_a = 99, seen_b = 99;
    s.world.set_friction_mixing([&](double, std::uint64_t ia, double, std::uint64_t ib) {
        seen_a = ia;
        seen_b = ib;
        return ia == 7 || ib == 7 ? 0.1 : 0.8;
    });
    s.world.set_user_material(s.box_shape_id, 7);
    BOOST_TEST(s.world.user_material(s.box_shape_id) == 7u);
    BOOST_TEST(std::abs(s.distance() - sliding_distance(0.1)) <= substep_travel);
    BOOST_TEST((seen_a == 3 && seen_b == 7)); // the floor was created first: shape_a
}

// Oracle: DD12 with DD42's default C_R = max(0.8, 0.1) = 0.8: a ball at 3 m/s onto the floor
// leaves at 2.4 m/s (no gravity: nothing else changes its speed); with a function taking the
// smaller, 0.1 gives 0.3 m/s. The restitution pass sets the separating velocity exactly (DD12's
// target), to round-off.
BOOST_AUTO_TEST_CASE(restitution_default_and_function, *utf::label("DD42")) {
    BOOST_TEST(std::abs(rebound_speed(0.8, 0.1) - 2.4) <= 1e-9);
    BOOST_TEST(std::abs(rebound_speed(0.1, 0.8) - 2.4) <= 1e-9);
    BOOST_TEST(std::abs(rebound_speed(0.8, 0.1, min_mix) - 0.3) <= 1e-9);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(contact_hooks_mixing_refusals, *utf::label("reliability"))

// Oracle: the calls' stated contract: a mixed value that is no friction (finite, >= 0) or
// restitution ([0, 1]) throws ValidationError naming the function and the constraint, the
// world bitwise unchanged and the old rule kept (the run that follows equals a twin's).
BOOST_AUTO_TEST_CASE(bad_values_are_refused_and_change_nothing) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    struct Case {
        bool friction;
        double value;
        const char* constraint;
    };
    for (const Case c : {Case{true, -0.1, "DCX_friction"}, Case{true, nan, "DCX_friction"},
                         Case{true, inf, "DCX_friction"}, Case{false, -0.5, "DCI_CR"},
                         Case{false, 1.5, "DCI_CR"}, Case{false, nan, "DCI_CR"}}) {
        Slide s(0.5, 0.5), twin(0.5, 0.5);
        s.world.step(dt);
        twin.world.step(dt);
        const std::uint64_t before = s.world.state_hash();
        const auto bad = [v = c.value](double, std::uint64_t, double, std::uint64_t) { return v; };
        try {
            if (c.friction)
                s.world.set_friction_mixing(bad);
            else
                s.world.set_restitution_mixing(bad);
            BOOST_FAIL("accepted a mixed value of " << c.value);
        } catch (const ValidationError& e) {
            BOOST_TEST(e.field == (c.friction ? "friction_mixing" : "restitution_mixing"));
            BOOST_TEST(e.constraint == c.constraint);
        }
        BOOST_TEST(s.world.state_hash() == before);
        for (int i = 0; i < 30; ++i) {
            s.world.step(dt);
            twin.world.step(dt);
        }
        BOOST_TEST(s.world.state_hash() == twin.world.state_hash());
    }
}

// Oracle: the contract of set_friction and set_user_material under a mixing function: a value
// it refuses throws ValidationError naming the function, and the shape keeps its material.
BOOST_AUTO_TEST_CASE(shape_changes_refused_by_the_function_change_nothing) {
    Slide s(0.5, 0.5);
    s.world.set_friction_mixing([](double a, std::uint64_t ia, double b, std::uint64_t) {
        return ia == 13 ? -1.0 : a + b > 1.5 ? nan("") : std::sqrt(a * b);
    });
    s.world.step(dt);
    const std::uint64_t before = s.world.state_hash();
    BOOST_CHECK_THROW(s.world.set_friction(s.box_shape_id, 1.2), ValidationError);
    BOOST_TEST(s.world.friction(s.box_shape_id) == 0.5);
    BOOST_CHECK_THROW(s.world.set_user_material(s.floor_shape, 13), ValidationError);
    BOOST_TEST(s.world.user_material(s.floor_shape) == 0u);
    BOOST_TEST(s.world.state_hash() == before);
    // What the function throws passes through, the world unchanged too.
    BOOST_CHECK_THROW(
        s.world.set_restitution_mixing([](double, std::uint64_t, double, std::uint64_t) -> double {
            throw std::runtime_error("no such material");
        }),
        std::runtime_error);
    BOOST_TEST(s.world.state_hash() == before);
    BOOST_CHECK_THROW(s.world.set_user_material(ShapeId{}, 1), InvalidHandle);
}

// Oracle: the documented behaviour of a refusal during a step: a new pair whose mixed value is
// refused makes no contact, the step finishes (time advances) and then throws the
// ValidationError naming the function; the box, never held, falls into the floor.
BOOST_AUTO_TEST_CASE(refusal_during_a_step_is_rethrown_after_it) {
    World world{WorldDef{.gravity = {0.0, -g}, .enable_sleep = false}};
    world.set_friction_mixing([](double, std::uint64_t, double, std::uint64_t) { return -1.0; });
    BodyDef fd;
    fd.type = BodyType::static_body;
    fd.position = {0.0, -0.5};
    world.create_shape(world.create_body(fd), box_shape(20.0, 1.0));
    BodyDef bd;
    bd.position = {0.0, 0.5};
    const BodyId box = world.create_body(bd);
    world.create_shape(box, box_shape(1.0, 1.0));
    try {
        world.step(dt);
        BOOST_FAIL("the step accepted a friction of -1");
    } catch (const ValidationError& e) {
        BOOST_TEST(e.field == "friction_mixing");
    }
    BOOST_TEST(world.time() == dt);
    BOOST_TEST(world.contacts().empty());
    BOOST_TEST(world.velocity(box).y < 0.0); // in free fall: nothing holds it
}

// Oracle: the guarantee that a value equal to the current one changes no bit: the same user
// material id, and a function that computes DD42's own rules, leave the run's hashes equal to
// those of a twin without the calls (200 steps of a pyramid).
BOOST_AUTO_TEST_CASE(same_values_change_no_bit) {
    World a{WorldDef{}}, b{WorldDef{}};
    test::build_pyramid(a, 8);
    test::build_pyramid(b, 8);
    for (int i = 0; i < 100; ++i) {
        a.step(dt);
        b.step(dt);
    }
    for (const BodyId body : a.bodies())
        for (const ShapeId s : a.shapes(body))
            a.set_user_material(s, 0);
    a.set_friction_mixing(
        [](double x, std::uint64_t, double y, std::uint64_t) { return std::sqrt(x * y); });
    a.set_restitution_mixing(
        [](double x, std::uint64_t, double y, std::uint64_t) { return std::max(x, y); });
    BOOST_TEST(a.state_hash() == b.state_hash());
    for (int i = 0; i < 100; ++i) {
        a.step(dt);
        b.step(dt);
        BOOST_TEST_REQUIRE(a.state_hash() == b.state_hash());
    }
    a.set_friction_mixing({}); // back to the rule itself
    for (int i = 0; i < 20; ++i) {
        a.step(dt);
        b.step(dt);
    }
    BOOST_TEST(a.state_hash() == b.state_hash());
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(contact_hooks_mixing_workers, *utf::label("determinism"))

// Oracle: the determinism requirement: the same scene with mixing functions gives the same
// state hash on 1, 2, 3 and 4 workers, step by step; and the functions change the run (the
// hash differs from the pyramid without them).
BOOST_AUTO_TEST_CASE(equal_on_one_to_four_workers) {
    std::uint64_t reference[120];
    for (int workers = 1; workers <= 4; ++workers) {
        World w{WorldDef{.workers = workers}};
        icy_pyramid(w);
        for (int i = 0; i < 120; ++i) {
            w.step(dt);
            if (workers == 1)
                reference[i] = w.state_hash();
            else
                BOOST_TEST_REQUIRE(w.state_hash() == reference[i]);
        }
    }
    World plain{WorldDef{}};
    test::build_pyramid(plain, 8);
    for (int i = 0; i < 120; ++i)
        plain.step(dt);
    BOOST_TEST(plain.state_hash() != reference[119]);
}

BOOST_AUTO_TEST_SUITE_END()
