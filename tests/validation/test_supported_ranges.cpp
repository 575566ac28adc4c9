// R4 for DCX_range, the supported range of magnitudes (docs/design.md, "Supported ranges"):
// finite inputs whose products would overflow or underflow are rejected with a ValidationError
// naming the field, the value and the range, the world left bit-for-bit unchanged; a step
// starts only from a state within the headroom; and worlds built at the corners of the range
// stay finite, so that ray casts and energies never see NaN or infinity.
#include <boost/test/unit_test.hpp>

#include <array>
#include <cfloat>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "tamias2d/geometry/shape_factory.hpp"
#include "tamias2d/validation.hpp"
#include "validation_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::test;

namespace {

constexpr double big = supported::input_max;
constexpr double small = supported::input_min;
/// Just beyond the bound: the check is exact, not approximate.
const double above_big = std::nextafter(big, inf);
const double below_small = std::nextafter(small, 0.0);

bool finite(Vec2d v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

/// Every body's state, the energies and the momentum are finite.
void check_finite(const World& w) {
    for (const BodyId id : w.bodies()) {
        const BodyState s = w.state(id);
        BOOST_TEST(finite(s.position));
        BOOST_TEST(finite(s.velocity));
        BOOST_TEST(std::isfinite(s.orientation));
        BOOST_TEST(std::isfinite(s.angular_velocity));
    }
    BOOST_TEST(std::isfinite(w.kinetic_energy()));
    BOOST_TEST(std::isfinite(w.potential_energy()));
    BOOST_TEST(finite(w.linear_momentum()));
}

/// Ray casts across the supported range never answer NaN: a hit has a fraction in [0, 1] and
/// finite point and normal.
void check_ray_casts(const World& w) {
    const std::array<std::pair<Vec2d, Vec2d>, 5> rays{{{{-big, 0.0}, {big, 0.0}},
                                                       {{0.0, big}, {0.0, -big}},
                                                       {{-big, -big}, {big, big}},
                                                       {{0.0, 0.0}, {small, 0.0}},
                                                       {{big, big}, {-big, -big}}}};
    for (const auto& [origin, translation] : rays) {
        const auto hit = w.ray_cast(origin, translation);
        if (!hit)
            continue;
        BOOST_TEST((hit->fraction >= 0.0 && hit->fraction <= 1.0), "fraction " << hit->fraction);
        BOOST_TEST(finite(hit->point));
        BOOST_TEST(finite(hit->normal));
    }
}

/// Steps until the world refuses (a state beyond the headroom) or `steps` have run: every
/// accepted step leaves a finite world, and a refused one leaves it exactly as it was.
void step_to_the_limit(World& w, double dt, int steps) {
    for (int i = 0; i < steps; ++i) {
        const Snapshot before = snapshot(w);
        try {
            w.step(dt);
        } catch (const ValidationError& e) {
            BOOST_TEST(e.constraint == "DCX_range", e.what());
            check_unchanged(before, w);
            return;
        }
        check_finite(w);
        check_ray_casts(w);
    }
}

} // namespace

BOOST_AUTO_TEST_SUITE(supported_ranges)

// Oracle: the derivation's arithmetic (docs/design.md): with every input one factor within
// 10^(+-e), the largest product of a step is 10^(16 e + 12) and the smallest that must not
// vanish 10^(-5 e - 7); e = 12 keeps both inside the normal doubles with a margin of 10^100,
// e = 18 leaves none. The bounds in validation.hpp are the ones derived.
BOOST_AUTO_TEST_CASE(the_bounds_are_the_derived_ones, *utf::label("R4") * utf::label("DCX_range")) {
    const double e = std::log10(supported::input_max);
    BOOST_TEST(e == 12.0);
    BOOST_TEST(std::log10(supported::input_min) == -e);
    BOOST_TEST(supported::state_max == supported::input_max * supported::input_max);
    BOOST_TEST(supported::mass_max == std::pow(10.0, 3 * e));
    BOOST_TEST(supported::mass_min == std::pow(10.0, -3 * e));
    BOOST_TEST(supported::inertia_max == std::pow(10.0, 5 * e));
    BOOST_TEST(supported::inertia_min == std::pow(10.0, -5 * e));
    const double top = std::log10(DBL_MAX), bottom = std::log10(DBL_MIN);
    BOOST_TEST(16 * e + 12 + 100 <= top);
    BOOST_TEST(-5 * e - 7 - 100 >= bottom);
    BOOST_TEST(16 * 18.0 + 12 > top - 10); // e = 18: no margin left
}

// Oracle: DCX_range: each body field just beyond its bound is rejected, naming the field; the
// bound itself is accepted; the strong guarantee: state_hash unchanged after every rejection.
BOOST_AUTO_TEST_CASE(body_fields_beyond_the_range_are_rejected,
                     *utf::label("R4") * utf::label("DCX_range")) {
    MovingWorld m;
    const std::vector<std::pair<const char*, std::function<void(BodyDef&, double)>>> fields = {
        {"body.position.x", [](BodyDef& d, double v) { d.position.x = v; }},
        {"body.position.y", [](BodyDef& d, double v) { d.position.y = -v; }},
        {"body.angle", [](BodyDef& d, double v) { d.angle = v; }},
        {"body.linear_velocity.x", [](BodyDef& d, double v) { d.linear_velocity.x = v; }},
        {"body.angular_velocity", [](BodyDef& d, double v) { d.angular_velocity = -v; }},
        {"body.force.y", [](BodyDef& d, double v) { d.force.y = v; }},
        {"body.torque", [](BodyDef& d, double v) { d.torque = v; }},
        {"body.gravity_scale", [](BodyDef& d, double v) { d.gravity_scale = v; }},
        {"body.linear_damping", [](BodyDef& d, double v) { d.linear_damping = v; }},
    };
    for (const auto& [field, set] : fields) {
        BOOST_TEST_CONTEXT(field) {
            for (const double v : {above_big, 1e300, DBL_MAX}) {
                BodyDef d;
                set(d, v);
                expect_rejected(
                    m.world, [&] { m.world.create_body(d); }, field, "DCX_range");
            }
            BodyDef d;
            set(d, big);
            BOOST_CHECK_NO_THROW(m.world.create_body(d));
        }
    }
    // The body: velocity (1e300, 1e300) was accepted.
    BodyDef fast;
    fast.linear_velocity = {1e300, 1e300};
    expect_rejected_value(
        m.world, [&] { m.world.create_body(fast); }, "body.linear_velocity.x", "DCX_range", 1e300);
    // A force of 1e308 was accepted and turned non-finite at the first step.
    BodyDef pushed;
    pushed.force = {1e308, 0.0};
    expect_rejected_value(
        m.world, [&] { m.world.create_body(pushed); }, "body.force.x", "DCX_range", 1e308);
    // A given mass spans 3 factors, a given moment of inertia 5.
    for (const double mass : {supported::mass_max * 2.0, supported::mass_min / 2.0, 1e-300}) {
        BodyDef d;
        d.mass = mass;
        expect_rejected_value(
            m.world, [&] { m.world.create_body(d); }, "body.mass", "DCX_range", mass);
    }
    for (const double inertia : {supported::inertia_max * 2.0, supported::inertia_min / 2.0}) {
        BodyDef d;
        d.inertia = inertia;
        expect_rejected_value(
            m.world, [&] { m.world.create_body(d); }, "body.inertia", "DCX_range", inertia);
    }
    BodyDef extreme;
    extreme.mass = supported::mass_min;
    extreme.inertia = supported::inertia_max;
    BOOST_CHECK_NO_THROW(m.world.create_body(extreme));
}

// Oracle: DCX_range with the one sliver rule (DCX_shape): a box 1e300 m wide or 1e-300 m high,
// a circle of radius 1e-200, a density of 1e-320 are rejected naming the field (not "a normal
// of length 0", the message before); world unchanged. The bounds themselves are accepted.
BOOST_AUTO_TEST_CASE(shape_sizes_beyond_the_range_are_rejected,
                     *utf::label("R4") * utf::label("DCX_range")) {
    MovingWorld m;
    const auto rejected = [&](const ShapeDef& s, std::string_view field, std::string_view label) {
        expect_rejected(
            m.world, [&] { m.world.create_shape(m.box, s); }, field, label);
    };
    rejected(box_shape(1e300, 1.0), "polygon.vertices", "DCX_range");
    rejected(box_shape(2.0 * above_big, 1.0), "polygon.vertices", "DCX_range");
    rejected(box_shape(1e-300, 1e-300), "polygon.extent", "DCX_range");
    rejected(box_shape(1.0, 1e-300), "polygon.thickness", "DCX_shape"); // a sliver
    rejected(box_shape(1.0, 1.0, {}, {above_big, 0.0}), "polygon.vertices", "DCX_range");
    rejected(circle_shape(1e-200), "shape.radius", "DCX_range");
    rejected(circle_shape(below_small), "shape.radius", "DCX_range");
    rejected(circle_shape(1e300), "shape.radius", "DCX_range");
    rejected(circle_shape(1.0, {}, {0.0, 1e300}), "shape.center.y", "DCX_range");
    rejected(circle_shape(1.0, Material{1e-320, 0.0, 0.0}), "material.density", "DCX_range");
    rejected(circle_shape(1.0, Material{1e300, 0.0, 0.0}), "material.density", "DCX_range");
    rejected(circle_shape(1.0, Material{1.0, 0.0, 1e300}), "material.friction", "DCX_range");
    BOOST_CHECK_NO_THROW(m.world.create_shape(m.box, circle_shape(small)));
    BOOST_CHECK_NO_THROW(m.world.create_shape(m.box, box_shape(small, small)));
    BOOST_CHECK_NO_THROW(m.world.create_shape(m.box, circle_shape(big, Material{small})));
    BOOST_CHECK_NO_THROW(m.world.create_shape(m.box, box_shape(2.0 * big, 2.0 * big)));
}

// Oracle: the sliver rule is one criterion: a hand-made box (make_box) passes create_shape
// exactly when its vertices pass make_polygon, over aspect ratios around 1e-6 and angles.
BOOST_AUTO_TEST_CASE(boxes_and_polygons_share_one_sliver_rule,
                     *utf::label("R4") * utf::label("DCX_shape")) {
    int accepted = 0, rejected = 0;
    for (const double ratio : {1e-7, 5e-7, 9.9e-7, 1e-6, 1.0000001e-6, 1.01e-6, 2e-6, 1e-5}) {
        for (const double angle : {0.0, 0.1, 0.7853981633974483, 1.0, 2.5}) {
            BOOST_TEST_CONTEXT("ratio " << ratio << ", angle " << angle) {
                World w;
                const BodyId b = w.create_body(BodyDef{});
                const ShapeDef box = box_shape(3.0, 3.0 * ratio, {}, {0.5, -0.25}, angle);
                bool box_ok = true;
                try {
                    w.create_shape(b, box);
                } catch (const ValidationError& e) {
                    box_ok = false;
                    BOOST_TEST(e.constraint == "DCX_shape", e.what());
                }
                const Polygon& p = box.geometry.polygon;
                bool polygon_ok = true;
                try {
                    w.create_shape(b, polygon_shape(std::span(p.vertices.data(), 4)));
                } catch (const ValidationError&) {
                    polygon_ok = false;
                }
                BOOST_TEST(box_ok == polygon_ok);
                (box_ok ? accepted : rejected) += 1;
            }
        }
    }
    BOOST_TEST(accepted > 0); // the sweep crosses the boundary
    BOOST_TEST(rejected > 0);
}

// Oracle: DCX_range on every setter and query argument: just beyond the bound rejected naming
// the argument, the world unchanged; ray_cast of a 1e300 translation refused instead of
// answering NaN.
BOOST_AUTO_TEST_CASE(setters_beyond_the_range_are_rejected,
                     *utf::label("R4") * utf::label("DCX_range")) {
    MovingWorld m;
    World& w = m.world;
    for (const double v : {above_big, 1e300}) {
        expect_rejected(
            w,
            [&] {
                w.set_transform(m.box, {v, 0.0}, 0.0);
            },
            "origin.x", "DCX_range");
        expect_rejected(
            w, [&] { w.set_transform(m.box, {}, -v); }, "angle", "DCX_range");
        expect_rejected(
            w,
            [&] {
                w.set_velocity(m.ball, {0.0, v});
            },
            "velocity.y", "DCX_range");
        expect_rejected(
            w, [&] { w.set_angular_velocity(m.ball, v); }, "angular_velocity", "DCX_range");
        expect_rejected(
            w,
            [&] {
                w.set_force(m.ball, {v, 0.0});
            },
            "force.x", "DCX_range");
        expect_rejected(
            w, [&] { w.set_torque(m.ball, v); }, "torque", "DCX_range");
        expect_rejected(
            w,
            [&] {
                w.apply_force(m.ball, {v, 0.0}, {});
            },
            "force.x", "DCX_range");
        expect_rejected(
            w,
            [&] {
                w.apply_force(m.ball, {}, {0.0, v});
            },
            "world_point.y", "DCX_range");
        expect_rejected(
            w, [&] { w.apply_torque(m.ball, v); }, "torque", "DCX_range");
        expect_rejected(
            w,
            [&] {
                w.apply_impulse(m.ball, {v, 0.0}, {});
            },
            "impulse.x", "DCX_range");
        expect_rejected(
            w,
            [&] {
                w.set_gravity({0.0, -v});
            },
            "gravity.y", "DCX_range");
        expect_rejected(
            w, [&] { w.set_damping(m.ball, v, 0.0); }, "linear_damping", "DCX_range");
        expect_rejected(
            w,
            [&] {
                (void)w.ray_cast({v, 0.0}, {1.0, 0.0});
            },
            "origin.x", "DCX_range");
        expect_rejected(
            w,
            [&] {
                (void)w.ray_cast({}, {1e300, 1e300});
            },
            "translation.x", "DCX_range");
        expect_rejected(
            w, [&] { w.step(v); }, "dt", "DCX_range");
    }
    expect_rejected(
        w, [&] { w.step(below_small); }, "dt", "DCX_range");
    expect_rejected(
        w, [&] { w.step(1e-300); }, "dt", "DCX_range");
    BOOST_CHECK_NO_THROW(w.set_velocity(m.ball, {big, -big}));
    BOOST_CHECK_NO_THROW(w.apply_force(m.ball, {big, 0.0}, {0.0, big}));
}

// Oracle: DCX_range's stated bound (docs/design.md, "Supported ranges"): the one-step loads add
// up until the next step: their sum is held within the state's
// headroom (1e24), and an impulse that would take a light body beyond it is refused; both
// leave the world unchanged, the impulse's body not even woken.
BOOST_AUTO_TEST_CASE(accumulated_loads_and_impulses_stay_within_the_headroom,
                     *utf::label("R4") * utf::label("DCX_range")) {
    WorldDef def;
    def.enable_sleep = true;
    World w(def);
    BodyDef d;
    d.mass = supported::mass_min;
    d.inertia = supported::inertia_min;
    const BodyId light = w.create_body(d);
    w.create_shape(light, circle_shape(1.0));
    w.set_awake(light, false);
    expect_rejected(
        w,
        [&] {
            w.apply_impulse(light, {big, 0.0}, {});
        },
        "impulse: the velocity", "DCX_range");
    BOOST_TEST(!w.is_awake(light));
    // r x F of the largest force at the farthest point is 1e24 N m: the bound, accepted once;
    // a second one would sum to 2e24.
    const BodyId other = w.create_body(BodyDef{});
    BOOST_CHECK_NO_THROW(w.apply_force(other, {0.0, big}, {big, 0.0}));
    expect_rejected(
        w,
        [&] {
            w.apply_force(other, {0.0, big}, {big, 0.0});
        },
        "torque (summed one-step torques)", "DCX_range");
}

// Oracle: the sequence: a body at the largest speed stepped with the largest time step
// leaves the range; the next step refuses (DCX_range naming the body and the field) and leaves
// the world exactly as it was; states, energies and ray casts are finite throughout.
BOOST_AUTO_TEST_CASE(a_step_never_produces_a_non_finite_state,
                     *utf::label("R4") * utf::label("DCX_range") * utf::label("DCO_p") *
                         utf::label("DCO_v")) {
    World w;
    BodyDef d;
    d.name = "runaway";
    d.linear_velocity = {big, big};
    d.force = {big, 0.0};
    const BodyId b = w.create_body(d);
    w.create_shape(b, circle_shape(1.0));
    w.step(big); // x = 1e24 + ...: beyond the headroom after one step
    check_finite(w);
    check_ray_casts(w);
    BOOST_TEST(w.position(b).x > supported::state_max);
    const auto e = expect_rejected(
        w, [&] { w.step(big); }, "position.x", "DCX_range");
    if (e)
        BOOST_TEST(std::string(e->what()).find("runaway") != std::string::npos, e->what());
    check_ray_casts(w);
    // Back within range, it steps again.
    w.set_transform(b, {}, 0.0);
    w.set_velocity(b, {});
    BOOST_CHECK_NO_THROW(w.step(1.0 / 60.0));
}

// Oracle: the derivation's corners (docs/design.md): the lightest slivers and the heaviest
// boxes, driven by the largest forces at the farthest points, the largest time step and
// gravity, in contact with each other, stay finite until the step refuses a state beyond the
// headroom, which it does without changing anything.
BOOST_AUTO_TEST_CASE(the_corners_of_the_range_stay_finite,
                     *utf::label("R4") * utf::label("DCX_range") * utf::label("DCO_p") *
                         utf::label("DCO_v") * utf::label("DCO_omega")) {
    for (const double dt : {big, 1.0 / 60.0, small}) {
        for (const double g : {big, 0.0}) {
            BOOST_TEST_CONTEXT("dt " << dt << ", g " << g) {
                WorldDef def;
                def.gravity = {0.0, -g};
                def.contact_hertz = big;
                def.joint_hertz = small;
                def.joint_damping_ratio = small;
                World w(def);
                const Material light{small, 1.0, big};
                const Material heavy{big, 0.0, 0.0};
                BodyDef ground;
                ground.type = BodyType::static_body;
                ground.position = {0.0, -big};
                const BodyId floor = w.create_body(ground);
                w.create_shape(floor, box_shape(2.0 * big, 2.0 * big, heavy));
                // A sliver of the smallest extent: the smallest mass and moment of inertia.
                BodyDef s;
                s.force = {big, -big};
                s.torque = big;
                s.angular_velocity = big;
                s.linear_velocity = {-big, big};
                const BodyId sliver = w.create_body(s);
                w.create_shape(sliver, box_shape(small, 1.01e-6 * small, light));
                w.apply_force(sliver, {big, big}, {-big, 0.0}); // r x F = -1e24 N m
                // The heaviest box, overlapping the ground and the sliver.
                BodyDef h;
                h.position = {0.0, 0.5 * big};
                h.linear_velocity = {0.0, -big};
                h.angular_velocity = -big;
                const BodyId boulder = w.create_body(h);
                w.create_shape(boulder, box_shape(2.0 * big, 2.0 * big, heavy));
                // Given extremes, jointed to the boulder with the softest spring.
                BodyDef given;
                given.mass = supported::mass_min;
                given.inertia = supported::inertia_min;
                given.position = {big, big};
                const BodyId tiny = w.create_body(given);
                w.create_shape(tiny, circle_shape(small, light));
                DistanceJointDef spring;
                spring.body_a = boulder;
                spring.body_b = tiny;
                spring.anchor_a = {0.0, 0.5 * big};
                spring.anchor_b = {big, big};
                spring.hertz = small;
                w.create_joint(spring);
                RevoluteJointDef pin;
                pin.body_a = floor;
                pin.body_b = sliver;
                pin.enable_limit = true;
                pin.lower_angle = -big;
                pin.upper_angle = big;
                pin.enable_spring = true;
                pin.hertz = small;
                w.create_joint(pin);
                check_finite(w);
                check_ray_casts(w);
                step_to_the_limit(w, dt, 20);
            }
        }
    }
}

// Oracle: DCX_range for joint definitions and setters: a spring of 1e-300 Hz with no damping
// would divide by zero in the soft step (h omega underflows), limits, axes and anchors beyond
// the range would overflow their products; each rejected naming the field, world unchanged.
BOOST_AUTO_TEST_CASE(joint_values_beyond_the_range_are_rejected,
                     *utf::label("R4") * utf::label("DCX_range")) {
    MovingWorld m;
    World& w = m.world;
    RevoluteJointDef r;
    r.body_a = m.ground;
    r.body_b = m.box;
    r.enable_spring = true;
    r.hertz = 1e-300;
    expect_rejected(
        w, [&] { w.create_joint(r); }, "joint.hertz", "DCX_range");
    r.hertz = 1.0;
    r.lower_angle = -1e300;
    expect_rejected(
        w, [&] { w.create_joint(r); }, "joint.lower_angle", "DCX_range");
    r.lower_angle = 0.0;
    r.anchor = {0.0, 1e300};
    expect_rejected(
        w, [&] { w.create_joint(r); }, "joint.anchor.y", "DCX_range");
    PrismaticJointDef p;
    p.body_a = m.ground;
    p.body_b = m.box;
    p.axis = {1e200, 0.0}; // its squared length overflows: normalised to (0, 0) before
    expect_rejected(
        w, [&] { w.create_joint(p); }, "joint.axis.x", "DCX_range");
    p.axis = {1e-200, 0.0};
    expect_rejected(
        w, [&] { w.create_joint(p); }, "joint.axis", "DCX_range");
    DistanceJointDef dj;
    dj.body_a = m.ground;
    dj.body_b = m.ball;
    dj.anchor_b = {3.0, 2.0};
    dj.enable_limit = true;
    dj.max_length = 1e300; // finite: the limit multiplies its error (infinite: no limit)
    expect_rejected(
        w, [&] { w.create_joint(dj); }, "joint.max_length", "DCX_range");
    dj.max_length = inf;
    BOOST_CHECK_NO_THROW(w.create_joint(dj));
    TargetJointDef t;
    t.body = m.ball;
    t.hertz = 1e-300;
    expect_rejected(
        w, [&] { w.create_joint(t); }, "joint.hertz", "DCX_range");
    t.hertz = 5.0;
    const JointId tj = w.create_joint(t);
    expect_rejected(
        w,
        [&] {
            w.set_joint_target(tj, {1e300, 0.0});
        },
        "joint.target.x", "DCX_range");
    WorldDef soft;
    soft.contact_hertz = 1e-300;
    expect_validation_error([&] { World x(soft); }, "world.contact_hertz", "DCX_range");
    soft.contact_hertz = 45.0;
    soft.gravity = {0.0, -1e300};
    expect_validation_error([&] { World x(soft); }, "world.gravity.y", "DCX_range");
}

// Oracle: a load function's value is an input too: 1e300 N refused by the step, which then
// leaves the world exactly as it was.
BOOST_AUTO_TEST_CASE(load_values_beyond_the_range_are_rejected,
                     *utf::label("R4") * utf::label("DCX_range")) {
    MovingWorld m;
    m.world.set_load(m.ball, [](double) { return Load{{0.0, 1e300}, 0.0}; });
    expect_rejected(
        m.world, [&] { m.world.step(1.0 / 60.0); }, "load(t).force.y", "DCX_range");
    m.world.set_load(m.ball, [](double) { return Load{{}, -1e300}; });
    expect_rejected(
        m.world, [&] { m.world.step(1.0 / 60.0); }, "load(t).torque", "DCX_range");
}

BOOST_AUTO_TEST_SUITE_END()
