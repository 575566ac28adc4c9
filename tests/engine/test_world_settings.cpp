// World settings changed between steps, and the maximum linear speed (DD40). Oracles: the
// closed form of a free fall under a speed limit; a world created with the setting from the
// start (a setting changed before the first step must give the same bits, and one changed later
// the same bits from then on as its own definition); the sleeping rule; the constructor's
// validation (a refused setter names the same field and changes nothing).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;
constexpr double inf = std::numeric_limits<double>::infinity();

/// A pile of boxes of two sizes on a ground, with some restitution and friction: every setting
/// below changes its history.
void pile(World& w) {
    BodyDef g;
    g.type = BodyType::static_body;
    g.position = {0.0, -0.5};
    w.create_shape(w.create_body(g), box_shape(40.0, 1.0, Material{1.0, 0.0, 0.5}));
    for (int i = 0; i < 12; ++i) {
        BodyDef d;
        d.position = {0.3 * (i % 3) - 0.3, 0.6 + 1.1 * i};
        d.linear_velocity = {0.0, -3.0};
        const BodyId b = w.create_body(d);
        w.create_shape(b, i % 2 ? box_shape(0.8, 0.6, Material{1.0, 0.4, 0.5})
                                : box_shape(1.0, 1.0, Material{1.0, 0.4, 0.5}));
    }
}

bool same_history(World& a, World& b, int n) {
    for (int i = 0; i < n; ++i) {
        a.step(dt);
        b.step(dt);
        if (a.state_hash() != b.state_hash())
            return false;
    }
    return true;
}

} // namespace

BOOST_AUTO_TEST_SUITE(world_settings)

// Oracle: DD40's closed form for a free fall from rest under IM1 per substep h: the speed after
// k substeps is min(k g h, v_max) (the limit applied before each position update), the
// position the sum of those speeds times h; the speed never exceeds v_max, and first equals it
// at the substep k* = ceil(v_max / (g h)).
BOOST_AUTO_TEST_CASE(a_falling_body_reaches_the_speed_limit_and_keeps_it,
                     *utf::label("DD40") * utf::label("IM1")) {
    const double g = 9.81, v_max = 2.5, h = dt / 4.0;
    World w(WorldDef{.gravity = {0.0, -g}, .maximum_linear_speed = v_max});
    const BodyId b = w.create_body(BodyDef{.position = {0.0, 100.0}});
    w.create_shape(b, circle_shape(0.5));
    double v = 0.0, y = 100.0;
    int k = 0, reached = -1;
    for (int n = 1; n <= 60; ++n) {
        w.step(dt);
        for (int s = 0; s < 4; ++s) {
            ++k;
            v = std::min(v + g * h, v_max);
            y -= v * h;
            if (reached < 0 && v == v_max)
                reached = k;
        }
        const double speed = -w.velocity(b).y;
        BOOST_TEST_REQUIRE(speed <= v_max * (1.0 + 4e-16));
        BOOST_TEST_REQUIRE(std::abs(speed - v) <= 1e-12 * v_max);
        BOOST_TEST_REQUIRE(std::abs(w.position(b).y - y) <= 1e-12 * 100.0);
    }
    BOOST_TEST(reached == static_cast<int>(std::ceil(v_max / (g * h))));
    BOOST_TEST(w.settings().maximum_linear_speed == v_max);
}

// Oracle: DD40 acts along the velocity's own direction: a body thrown at 10 m/s along (3, 4)
// without gravity under a 1 m/s limit moves at (0.6, 0.8) m/s.
BOOST_AUTO_TEST_CASE(the_speed_limit_keeps_the_direction, *utf::label("DD40")) {
    World w(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId b = w.create_body(BodyDef{.linear_velocity = {6.0, 8.0}});
    w.create_shape(b, circle_shape(0.5));
    w.set_maximum_linear_speed(1.0);
    w.step(dt);
    BOOST_TEST(w.velocity(b).x == 0.6, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(w.velocity(b).y == 0.8, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(w.position(b).x == 0.6 * dt, boost::test_tools::tolerance(1e-14));
    w.set_maximum_linear_speed(inf);
    w.set_velocity(b, {60.0, 80.0});
    w.step(dt);
    BOOST_TEST(w.velocity(b).x == 60.0); // no limit: IM1 as it is
}

// Oracle: the constructor's validation (the same field names) and R4's promise: a refused
// setter changes nothing.
BOOST_AUTO_TEST_CASE(setting_refusals_name_the_field_and_change_nothing, *utf::label("R4")) {
    World w;
    pile(w);
    w.step(dt);
    const std::uint64_t before = w.state_hash();
    const WorldDef settings = w.settings();
    struct Bad {
        void (*call)(World&);
        const char* field;
    };
    const Bad bad[] = {
        {[](World& x) { x.set_maximum_linear_speed(0.0); }, "world.maximum_linear_speed"},
        {[](World& x) { x.set_maximum_linear_speed(-1.0); }, "world.maximum_linear_speed"},
        {[](World& x) { x.set_maximum_linear_speed(std::nan("")); }, "world.maximum_linear_speed"},
        {[](World& x) { x.set_contact_tuning(0.0, 10.0, 3.0); }, "world.contact_hertz"},
        {[](World& x) { x.set_contact_tuning(30.0, -1.0, 3.0); }, "world.contact_damping_ratio"},
        {[](World& x) { x.set_contact_tuning(30.0, 1.0, inf); }, "world.contact_push_max_velocity"},
        {[](World& x) { x.set_joint_tuning(std::nan(""), 1.0); }, "world.joint_hertz"},
        {[](World& x) { x.set_joint_tuning(30.0, 0.0); }, "world.joint_damping_ratio"},
        {[](World& x) { x.set_restitution_threshold(-0.5); }, "world.restitution_threshold"},
        {[](World& x) { x.set_workers(0); }, "world.workers"},
        {[](World& x) { x.set_workers(257); }, "world.workers"},
    };
    for (const Bad& b : bad) {
        try {
            b.call(w);
            BOOST_ERROR("accepted: " << b.field);
        } catch (const ValidationError& e) {
            BOOST_TEST(e.field == b.field);
        }
        BOOST_TEST(w.state_hash() == before);
    }
    BOOST_TEST(w.settings().contact_hertz == settings.contact_hertz);
    BOOST_TEST(w.settings().joint_hertz == settings.joint_hertz);
    BOOST_TEST(w.settings().workers == settings.workers);
    BOOST_TEST(w.settings().maximum_linear_speed == inf);
}

// Oracle: a world created with the settings: every setter called before the first step gives
// the same bits as the definition, step by step; and the values it already has change none.
BOOST_AUTO_TEST_CASE(settings_set_at_run_time_equal_the_definition) {
    WorldDef d;
    d.enable_continuous = false;
    d.contact_hertz = 30.0;
    d.contact_damping_ratio = 3.0;
    d.contact_push_max_velocity = 1.0;
    d.joint_hertz = 20.0;
    d.joint_damping_ratio = 1.0;
    d.restitution_threshold = 2.0;
    d.maximum_linear_speed = 4.0;
    d.workers = 2;
    World by_definition(d);
    World by_setters;
    by_setters.set_continuous(false);
    by_setters.set_contact_tuning(30.0, 3.0, 1.0);
    by_setters.set_joint_tuning(20.0, 1.0);
    by_setters.set_restitution_threshold(2.0);
    by_setters.set_maximum_linear_speed(4.0);
    by_setters.set_workers(2);
    pile(by_definition);
    pile(by_setters);
    BOOST_TEST(same_history(by_definition, by_setters, 90));
    // The same values again, every step: no bit changes.
    for (int i = 0; i < 30; ++i) {
        by_setters.set_continuous(false);
        by_setters.set_contact_tuning(30.0, 3.0, 1.0);
        by_setters.set_restitution_threshold(2.0);
        by_setters.set_maximum_linear_speed(4.0);
        by_setters.set_workers(2);
        by_setters.set_sleeping(false);
        by_setters.step(dt);
        by_definition.step(dt);
        BOOST_TEST_REQUIRE(by_setters.state_hash() == by_definition.state_hash());
    }
}

// Oracle: the sleeping rule (sleep.hpp): with sleeping turned on at run time a settled pile
// falls asleep; turned off, every body is awake again (awake_body_count counts them).
BOOST_AUTO_TEST_CASE(sleeping_turned_on_and_off) {
    World w;
    pile(w);
    for (int i = 0; i < 240; ++i)
        w.step(dt);
    BOOST_TEST(w.awake_body_count() == 12u); // sleeping off: every movable body
    w.set_sleeping(true);
    BOOST_TEST(w.settings().enable_sleep);
    for (int i = 0; i < 240 && w.awake_body_count() > 0; ++i)
        w.step(dt);
    BOOST_TEST(w.awake_body_count() == 0u);
    w.set_sleeping(false);
    BOOST_TEST(w.awake_body_count() == 12u);
    for (const BodyId b : w.bodies())
        BOOST_TEST(w.is_awake(b) == (w.type(b) != BodyType::static_body));
}

// Oracle: determinism (docs/design.md): a world driven through the new calls gives the same
// bits on 1 to 4 workers, and switching workers mid-run changes no bit. Enough bodies (1500)
// that the step's parallel loops run in blocks.
BOOST_AUTO_TEST_CASE(run_time_changes_give_the_same_bits_on_any_worker_count,
                     *utf::label("determinism")) {
    auto run = [](int workers, bool switching) {
        World w(WorldDef{.gravity = {1.0, -10.0}, .workers = workers});
        BodyDef g;
        g.type = BodyType::static_body;
        g.position = {0.0, -0.5};
        w.create_shape(w.create_body(g), box_shape(200.0, 1.0, Material{1.0, 0.2, 0.5}));
        std::vector<BodyId> ids;
        for (int i = 0; i < 1500; ++i) {
            BodyDef d;
            d.position = {-60.0 + 0.8 * (i % 150), 0.5 + 0.8 * (i / 150)};
            const BodyId b = w.create_body(d);
            w.create_shape(b, circle_shape(0.35, Material{1.0, 0.2, 0.5}));
            ids.push_back(b);
        }
        w.set_maximum_linear_speed(3.0);
        for (int s = 0; s < 60; ++s) {
            if (switching)
                w.set_workers(1 + s % 4);
            if (s == 10) {
                for (std::size_t i = 0; i < ids.size(); i += 7)
                    w.set_motion_locks(ids[i], MotionLocks{.linear_x = true});
                for (std::size_t i = 3; i < ids.size(); i += 11)
                    w.set_motion_locks(ids[i], MotionLocks{.angular = true});
            }
            if (s == 15) {
                for (std::size_t i = 5; i < ids.size(); i += 19)
                    w.set_mass_data(ids[i], BodyMassData{3.0, {0.1, 0.0}, 0.5});
            }
            if (s == 20) {
                for (std::size_t i = 1; i < ids.size(); i += 13)
                    w.set_body_type(ids[i], BodyType::kinematic);
                for (std::size_t i = 2; i < ids.size(); i += 17)
                    w.set_enabled(ids[i], false);
            }
            if (s == 40) {
                for (std::size_t i = 2; i < ids.size(); i += 17)
                    w.set_enabled(ids[i], true);
                for (std::size_t i = 1; i < ids.size(); i += 13)
                    w.set_body_type(ids[i], BodyType::dynamic);
            }
            w.step(dt);
        }
        return w.state_hash();
    };
    const std::uint64_t one = run(1, false);
    for (int workers = 2; workers <= 4; ++workers)
        BOOST_TEST(run(workers, false) == one, "workers " << workers);
    BOOST_TEST(run(1, true) == one);
}

BOOST_AUTO_TEST_SUITE_END()
