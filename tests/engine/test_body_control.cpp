// A body's definition changed at run time: type, enabled state, gravity scale, bullet flag,
// motion locks (DD39), mass data (DD41), sleep threshold and wake_touching. Each call is tested
// for its effect against a closed form, the rule it states or a world built with the setting
// from the start, and for its strong guarantee (a refused call leaves state_hash() unchanged;
// a value the body already has changes no bit of what follows).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;
constexpr int substeps = 4; // WorldDef's default
constexpr double h = dt / substeps;

double rel_err(double got, double want) {
    return std::abs(got - want) / std::max(1.0, std::abs(want));
}

/// The symplectic Euler free fall from rest that IM1 integrates per substep: after k substeps
/// of h under acceleration a, v = k a h and the displacement is a h^2 k (k + 1) / 2.
double fall_velocity(double a, int k) {
    return k * a * h;
}
double fall_displacement(double a, int k) {
    return a * h * h * k * (k + 1) / 2.0;
}

/// A static ground 40 m wide whose top face is y = 0.
BodyId ground(World& w, Material m = {}) {
    BodyDef g;
    g.type = BodyType::static_body;
    g.position = {0.0, -0.5};
    g.name = "ground";
    const BodyId id = w.create_body(g);
    w.create_shape(id, box_shape(40.0, 1.0, m));
    return id;
}

/// A unit box (1 kg) with its centre at (x, y).
BodyId box(World& w, double x, double y, BodyDef d = {}) {
    d.position = {x, y};
    const BodyId id = w.create_body(d);
    w.create_shape(id, box_shape(1.0, 1.0));
    return id;
}

/// Runs `n` steps of two worlds side by side; whether their hashes stayed equal.
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

BOOST_AUTO_TEST_SUITE(body_control)

// ----------------------------------------------------------------------------- body type

// Oracle: R2 (a static body does not move and has no mass; a kinematic body moves with its
// velocity and is not pushed; a dynamic body's mass is its shapes', 1 kg for a unit box of
// density 1), IM1's free fall from rest per substep and IM2 without torque: a body at rest
// that no torque turns keeps its orientation.
BOOST_AUTO_TEST_CASE(type_changes_follow_r2,
                     *utf::label("R2") * utf::label("IM1") * utf::label("IM2")) {
    World w(WorldDef{.gravity = {0.0, -10.0}});
    const BodyId b =
        box(w, 0.0, 10.0, BodyDef{.linear_velocity = {2.0, 0.0}, .angular_velocity = 1.5});
    for (int i = 0; i < 10; ++i)
        w.step(dt);
    // Static: stopped, massless, and still for good.
    w.set_body_type(b, BodyType::static_body);
    BOOST_TEST((w.type(b) == BodyType::static_body));
    BOOST_TEST(w.mass(b) == 0.0);
    BOOST_TEST(w.velocity(b).x == 0.0);
    BOOST_TEST(w.velocity(b).y == 0.0);
    BOOST_TEST(w.angular_velocity(b) == 0.0);
    BOOST_TEST(!w.is_awake(b));
    const Vec2d held = w.position(b);
    const double held_angle = w.orientation(b);
    for (int i = 0; i < 30; ++i)
        w.step(dt);
    BOOST_TEST(w.position(b).x == held.x);
    BOOST_TEST(w.position(b).y == held.y);
    BOOST_TEST(w.orientation(b) == held_angle);
    // Dynamic again: its shapes' mass, and a free fall from rest, without turning.
    w.set_body_type(b, BodyType::dynamic);
    BOOST_TEST(w.mass(b) == 1.0);
    BOOST_TEST(w.inertia(b) == 1.0 / 6.0, boost::test_tools::tolerance(1e-15));
    for (int n = 1; n <= 30; ++n) {
        w.step(dt);
        BOOST_TEST(rel_err(w.velocity(b).y, fall_velocity(-10.0, n * substeps)) < 1e-12);
        BOOST_TEST(rel_err(w.position(b).y, held.y + fall_displacement(-10.0, n * substeps)) <
                   1e-12);
        BOOST_TEST(w.position(b).x == held.x);
        BOOST_TEST(w.angular_velocity(b) == 0.0);
        BOOST_TEST(w.orientation(b) == held_angle);
    }
    // Kinematic: keeps its velocity, ignores gravity, moves on a straight line.
    const Vec2d v = w.velocity(b);
    const Vec2d p = w.position(b);
    w.set_body_type(b, BodyType::kinematic);
    BOOST_TEST(w.mass(b) == 0.0);
    BOOST_TEST(w.velocity(b).y == v.y);
    for (int n = 1; n <= 30; ++n) {
        w.step(dt);
        BOOST_TEST(w.velocity(b).y == v.y);
        BOOST_TEST(rel_err(w.position(b).y, p.y + v.y * n * dt) < 1e-12);
    }
}

// Oracle: R2 and set_body_type's statement that the mass follows the new type: a body made
// kinematic has no mass, as one created kinematic, so its centre is its origin. A dynamic body
// whose box lies 1 m off its origin (its centre of mass there), made kinematic and set moving
// and turning, has the mass data and steps bit for bit as a body created kinematic with the
// same box, pose and velocities, in a world of its own.
BOOST_AUTO_TEST_CASE(a_body_made_kinematic_is_one_created_kinematic, *utf::label("R2")) {
    const ShapeDef offset = box_shape(1.0, 0.5, Material{}, {1.0, 0.0});
    const Vec2d v{1.0, -2.0};
    const double omega = 3.0;
    World made(WorldDef{.gravity = {0.0, 0.0}}), created(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId a = made.create_body(BodyDef{.position = {2.0, 1.0}, .angle = 0.5});
    made.create_shape(a, offset);
    BOOST_TEST_REQUIRE(made.local_center(a).x == 1.0); // the box's centre, off the origin
    made.set_body_type(a, BodyType::kinematic);
    const BodyId b = created.create_body(
        BodyDef{.type = BodyType::kinematic, .position = {2.0, 1.0}, .angle = 0.5});
    created.create_shape(b, offset);
    for (World* w : {&made, &created}) {
        const BodyId id = w == &made ? a : b;
        w->set_velocity(id, v);
        w->set_angular_velocity(id, omega);
    }
    BOOST_TEST(made.local_center(a).x == created.local_center(b).x);
    BOOST_TEST(made.local_center(a).y == created.local_center(b).y);
    BOOST_TEST(made.mass(a) == 0.0);
    for (int n = 1; n <= 30; ++n) {
        made.step(dt);
        created.step(dt);
        const BodyState s = made.state(a), r = created.state(b);
        BOOST_TEST_CONTEXT("step " << n) {
            BOOST_TEST(s.position.x == r.position.x);
            BOOST_TEST(s.position.y == r.position.y);
            BOOST_TEST(s.orientation == r.orientation);
            BOOST_TEST(s.velocity.x == r.velocity.x);
            BOOST_TEST(s.velocity.y == r.velocity.y);
        }
    }
}

// Oracle: IM5's closed form without applied forces (no gravity), per substep v_k = v_0 (1 + h
// c_v)^(-k) and omega_k = omega_0 (1 + h c_omega)^(-k), for a dynamic body; and R2's kinematic
// body, which keeps the velocity it is given (damping is IM5's, of dynamic bodies). A body with
// both damping coefficients, or either alone (each also a round 1 s^-1), created static, is damped
// once made dynamic and not while kinematic, and damped again once dynamic; a body created
// kinematic likewise.
BOOST_AUTO_TEST_CASE(damping_acts_on_a_body_while_it_is_dynamic,
                     *utf::label("IM5") * utf::label("R2")) {
    const std::pair<double, double> dampings[] = {
        {0.5, 0.25}, {0.5, 0.0}, {0.0, 0.25}, {1.0, 0.0}, {0.0, 1.0}};
    for (const auto& damping : dampings)
        for (const BodyType created : {BodyType::static_body, BodyType::kinematic}) {
            const double c_v = damping.first, c_w = damping.second; // (lambdas capture them)
            BOOST_TEST_CONTEXT(
                (created == BodyType::static_body ? "created static" : "created kinematic")
                << ", c_v " << c_v << ", c_w " << c_w) {
                World w(WorldDef{.gravity = {0.0, 0.0}});
                const BodyId b =
                    box(w, 0.0, 0.0,
                        BodyDef{.type = created, .linear_damping = c_v, .angular_damping = c_w});
                const auto dynamic_decays = [&] {
                    w.set_body_type(b, BodyType::dynamic);
                    w.set_velocity(b, {2.0, -1.0});
                    w.set_angular_velocity(b, 1.5);
                    for (int n = 1; n <= 20; ++n) {
                        w.step(dt);
                        const int k = n * substeps;
                        BOOST_TEST(rel_err(w.velocity(b).x, 2.0 * std::pow(1.0 + h * c_v, -k)) <
                                   1e-12);
                        BOOST_TEST(rel_err(w.velocity(b).y, -std::pow(1.0 + h * c_v, -k)) < 1e-12);
                        BOOST_TEST(rel_err(w.angular_velocity(b),
                                           1.5 * std::pow(1.0 + h * c_w, -k)) < 1e-12);
                    }
                };
                dynamic_decays();
                w.set_body_type(b, BodyType::kinematic);
                w.set_velocity(b, {2.0, -1.0});
                w.set_angular_velocity(b, 1.5);
                for (int n = 1; n <= 20; ++n) {
                    w.step(dt);
                    BOOST_TEST(w.velocity(b).x == 2.0);
                    BOOST_TEST(w.velocity(b).y == -1.0);
                    BOOST_TEST(w.angular_velocity(b) == 1.5);
                }
                dynamic_decays();
            }
        }
}

// Oracle: R7 (every collision detected) and statics: a box created static 2 m above a static
// ground and then made dynamic falls (IM1) and comes to rest on the ground, its centre half
// its height above the ground's top (0.5 m, within the soft contact's few millimetres), as a
// box created dynamic does; a shape of a static body is filed with the static ones, and the
// type change must file it with the moving ones, or no pair with the ground is ever found.
BOOST_AUTO_TEST_CASE(a_body_created_static_and_made_dynamic_lands_on_the_ground,
                     *utf::label("R7")) {
    World w(WorldDef{.gravity = {0.0, -10.0}});
    ground(w);
    const BodyId made = box(w, -2.0, 2.5, BodyDef{.type = BodyType::static_body});
    const BodyId born = box(w, 2.0, 2.5);
    w.set_body_type(made, BodyType::dynamic);
    for (int k = 0; k < 180; ++k)
        w.step(dt);
    for (const BodyId b : {made, born}) {
        BOOST_TEST(std::abs(w.position(b).y - 0.5) < 0.01, w.position(b).y);
        BOOST_TEST(std::abs(w.velocity(b).y) < 1e-3);
    }
}

// Oracle: R7 (every collision detected; the candidates are the pairs whose fat boxes overlap,
// IM4) and the scene's geometry. A type change gives the body's shapes new proxies, fattened
// about where the body is now; the step decides whether a shape left its proxy from the box the
// proxy holds. Without gravity a unit box rises 0.08 m inside its fat box (margin 0.1 m, so the
// broad phase does not move it), is made static and dynamic again there, then sinks at 0.3 m/s
// onto a static peg (a disc of radius 5 mm) whose top lies 0.145 m below the box's bottom: the
// peg's fat box (margin 0.02 m) is outside the box's new fat box but inside its old one. The
// peg holds the box up: its bottom never sinks into the peg by 5 mm (a pair found in time stops
// it at the peg's top), and it rests there.
BOOST_AUTO_TEST_CASE(a_body_made_dynamic_again_collides_below_its_old_fat_box,
                     *utf::label("IM4") * utf::label("R7")) {
    World w(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId b = box(w, 0.0, 0.0);
    const double peg_top = -0.565;
    BodyDef peg;
    peg.type = BodyType::static_body;
    peg.position = {0.0, peg_top - 0.005};
    w.create_shape(w.create_body(peg), circle_shape(0.005));
    w.set_velocity(b, {0.0, 0.08 / dt});
    w.step(dt);
    BOOST_TEST_REQUIRE(std::abs(w.position(b).y - 0.08) < 1e-12);
    w.set_body_type(b, BodyType::static_body);
    w.set_body_type(b, BodyType::dynamic);
    w.set_velocity(b, {0.0, -0.3});
    double deepest = 0.0;
    for (int i = 0; i < 120; ++i) {
        w.step(dt);
        deepest = std::max(deepest, peg_top - (w.position(b).y - 0.5));
    }
    BOOST_TEST_MESSAGE("deepest overlap with the peg: " << deepest << " m");
    BOOST_TEST(deepest < 0.005);
    BOOST_TEST(std::abs(w.position(b).y - 0.5 - peg_top) < 0.005); // resting on it
    BOOST_TEST(std::abs(w.velocity(b).y) < 1e-3);
}

// Oracle: set_body_type's statement that a body made static stops, its velocities and one-step
// loads zero: a body given a one-step force and torque, then made static, is in the state of
// the same body made static without them, so the two worlds write the same snapshot bytes.
// Made dynamic again at once, with or without them, it has no load left: its step moves it as
// gravity alone does, IM1's fall straight down and IM2 without torque, no turn at all.
BOOST_AUTO_TEST_CASE(a_body_made_static_keeps_no_one_step_load, *utf::label("reliability")) {
    const auto made_static = [](bool loaded, bool dynamic_again) {
        World w(WorldDef{.gravity = {0.0, -10.0}});
        const BodyId b = box(w, 0.0, 10.0);
        if (loaded) {
            w.apply_force(b, {3.0, -2.0}, {0.25, 10.0});
            w.apply_torque(b, 1.5);
        }
        w.set_body_type(b, BodyType::static_body);
        if (dynamic_again) {
            w.set_body_type(b, BodyType::dynamic);
            w.step(dt);
            BOOST_TEST(w.angular_velocity(b) == 0.0);
            BOOST_TEST(w.velocity(b).x == 0.0);
            BOOST_TEST(w.velocity(b).y < 0.0);
        }
        return w.snapshot();
    };
    const std::vector<std::byte> plain = made_static(false, false);
    BOOST_TEST((made_static(true, false) == plain));
    BOOST_TEST((made_static(true, true) == made_static(false, true)));
}

// Oracle: the handles, user data, joints and settings given before the change, and the rule
// that the body's contacts go (with an end event) and come back with the next step.
BOOST_AUTO_TEST_CASE(type_changes_keep_handles_joints_and_find_contacts_again) {
    World w(WorldDef{.gravity = {0.0, -10.0}});
    const BodyId g = ground(w);
    const BodyId b = box(w, 0.0, 0.5, BodyDef{.user_data = 42});
    const ShapeId s = w.shapes(b).front();
    const BodyId bob = w.create_body(BodyDef{.position = {5.0, 3.0}});
    w.create_shape(bob, circle_shape(0.25));
    RevoluteJointDef r;
    r.body_a = b;
    r.body_b = bob;
    r.anchor = {5.0, 3.0};
    const JointId j = w.create_joint(r);
    for (int i = 0; i < 10; ++i)
        w.step(dt);
    BOOST_TEST_REQUIRE(w.contacts(b).size() == 1u);
    w.set_body_type(b, BodyType::kinematic);
    BOOST_TEST(w.contacts(b).empty());
    BOOST_TEST_REQUIRE(w.contact_end_events().size() == 1u);
    BOOST_TEST((w.contact_end_events()[0].shape_b == s));
    w.step(dt);
    // Kinematic against static: no pair (R7 needs a dynamic body).
    BOOST_TEST(w.contacts(b).empty());
    w.set_body_type(b, BodyType::dynamic);
    w.step(dt);
    BOOST_TEST(w.contacts(b).size() == 1u);
    BOOST_TEST(w.contact_begin_events().size() == 1u);
    BOOST_TEST(w.is_valid(b));
    BOOST_TEST(w.is_valid(s));
    BOOST_TEST(w.is_valid(j));
    BOOST_TEST(w.user_data(b) == 42u);
    BOOST_TEST((w.joints(b) == std::vector<JointId>{j}));
    BOOST_TEST((w.body(s) == b));
    (void)g;
}

// Oracle: a joint none of whose bodies is dynamic is not solved: a kinematic body pinned to a
// static one moves on with its velocity (a straight line, no NaN); made dynamic again, the
// joint pulls its pin back together and the bob swings on its 1 m lever.
BOOST_AUTO_TEST_CASE(a_joint_without_a_dynamic_body_is_not_solved) {
    World w(WorldDef{.gravity = {0.0, -10.0}});
    const BodyId anchor = w.create_body(BodyDef{.type = BodyType::static_body});
    const BodyId bob = w.create_body(BodyDef{.position = {1.0, 0.0}});
    w.create_shape(bob, circle_shape(0.1));
    RevoluteJointDef r;
    r.body_a = anchor;
    r.body_b = bob;
    r.anchor = {0.0, 0.0};
    w.create_joint(r);
    w.set_body_type(bob, BodyType::kinematic);
    w.set_velocity(bob, {0.0, 1.0});
    for (int n = 1; n <= 60; ++n) {
        w.step(dt);
        BOOST_TEST_REQUIRE(rel_err(w.position(bob).y, n * dt) < 1e-12);
        BOOST_TEST_REQUIRE(w.position(bob).x == 1.0);
    }
    w.set_body_type(bob, BodyType::dynamic);
    for (int n = 1; n <= 120; ++n)
        w.step(dt);
    const Vec2d p = w.position(bob);
    // The pin holds the bob's point 1 m left of its centre at the origin again: the centre
    // swings on the circle of radius 1 m about it, within the joint's softness (1 cm).
    BOOST_TEST(std::abs(std::hypot(p.x, p.y) - 1.0) < 1e-2);
}

// Oracle: R4's strong guarantee (state_hash unchanged after a refusal); the same type changes
// no bit of the simulation (a twin world, step by step).
BOOST_AUTO_TEST_CASE(type_refusals_change_nothing_and_the_same_type_changes_no_bit) {
    World a(WorldDef{.gravity = {0.0, -10.0}, .enable_sleep = true});
    World b(WorldDef{.gravity = {0.0, -10.0}, .enable_sleep = true});
    for (World* w : {&a, &b}) {
        ground(*w);
        box(*w, 0.0, 0.5);
        box(*w, 0.2, 1.5);
    }
    const BodyId moving = a.bodies()[1];
    const std::uint64_t before = a.state_hash();
    BOOST_CHECK_THROW(a.set_body_type(moving, static_cast<BodyType>(7)), ValidationError);
    BOOST_CHECK_THROW(a.set_body_type(BodyId{9, 1}, BodyType::dynamic), InvalidHandle);
    BOOST_TEST(a.state_hash() == before);
    for (int i = 0; i < 120; ++i) {
        a.set_body_type(moving, BodyType::dynamic);
        a.set_body_type(a.bodies()[0], BodyType::static_body);
        a.set_enabled(moving, true);
        a.set_gravity_scale(moving, 1.0);
        a.set_bullet(moving, false);
        a.set_motion_locks(moving, MotionLocks{});
        a.reset_mass_data(moving);
        a.step(dt);
        b.step(dt);
        BOOST_TEST_REQUIRE(a.state_hash() == b.state_hash());
    }
    BOOST_TEST(!a.is_awake(moving)); // slept through all of it
}

// Oracle: DCX_joint's lever limit, judged with the new mass: a tiny disc pinned 1000 m from its
// centre may be static (no mass: no lever) but not dynamic; the refusal changes nothing.
BOOST_AUTO_TEST_CASE(a_type_change_that_breaks_a_joint_lever_is_refused) {
    World w;
    const BodyId tiny = w.create_body(BodyDef{.type = BodyType::static_body});
    w.create_shape(tiny, circle_shape(0.001));
    const BodyId far = w.create_body(BodyDef{.position = {1000.0, 0.0}});
    w.create_shape(far, box_shape(1.0, 1.0));
    RevoluteJointDef r;
    r.body_a = tiny;
    r.body_b = far;
    r.anchor = {1000.0, 0.0};
    w.create_joint(r);
    const std::uint64_t before = w.state_hash();
    try {
        w.set_body_type(tiny, BodyType::dynamic);
        BOOST_ERROR("accepted");
    } catch (const ValidationError& e) {
        BOOST_TEST(e.constraint == "DCX_joint");
    }
    BOOST_TEST(w.state_hash() == before);
    BOOST_TEST((w.type(tiny) == BodyType::static_body));
}

// ----------------------------------------------------------------------------- enabled

// Oracle: IM1's semi-implicit Euler fall in closed form (fall_displacement, an arithmetic
// series) and the documented rule of set_enabled: a disabled body keeps its state and does not
// move; nothing collides with it (a box falls through a disabled platform as in free fall), no
// query or ray finds it; enabled again, it moves on from the velocity it kept.
BOOST_AUTO_TEST_CASE(a_disabled_body_is_out_of_the_world, *utf::label("IM1")) {
    World w(WorldDef{.gravity = {0.0, -10.0}});
    BodyDef pd;
    pd.type = BodyType::static_body;
    pd.position = {0.0, 0.0};
    const BodyId platform = w.create_body(pd);
    w.create_shape(platform, box_shape(4.0, 0.2));
    const BodyId faller = box(w, 0.0, 3.0);
    const BodyId flyer = box(w, 10.0, 10.0, BodyDef{.linear_velocity = {1.0, 2.0}});
    w.set_enabled(platform, false);
    w.set_enabled(flyer, false);
    BOOST_TEST(!w.is_enabled(platform));
    BOOST_TEST(!w.is_awake(flyer));
    BOOST_TEST(w.query_point({0.0, 0.0}).empty());
    BOOST_TEST(w.query_aabb(Aabb{9.0, 9.0, 11.0, 11.0}).empty());
    BOOST_TEST(!w.ray_cast({0.0, 2.0}, {0.0, -10.0}).has_value()); // (below the faller)
    for (int n = 1; n <= 60; ++n) {
        w.step(dt);
        BOOST_TEST_REQUIRE(
            rel_err(w.position(faller).y, 3.0 + fall_displacement(-10.0, n * substeps)) < 1e-12);
        BOOST_TEST_REQUIRE(w.position(flyer).x == 10.0);
        BOOST_TEST_REQUIRE(w.position(flyer).y == 10.0);
    }
    BOOST_TEST(w.velocity(flyer).x == 1.0);
    BOOST_TEST(w.velocity(flyer).y == 2.0);
    BOOST_TEST(w.contacts().empty());
    w.set_enabled(flyer, true);
    BOOST_TEST(w.is_awake(flyer));
    w.step(dt);
    // One step from (10, 10) at (1, 2) under g: x + 1 dt, and the fall's share in y.
    BOOST_TEST(rel_err(w.position(flyer).x, 10.0 + dt) < 1e-12);
    BOOST_TEST(rel_err(w.position(flyer).y, 10.0 + 2.0 * dt + fall_displacement(-10.0, substeps)) <
               1e-12);
}

// Oracle: the documented rule, with IM1's fall in closed form (fall_displacement): disabling
// removes the body's contacts now (with their end events) and
// makes its joints inactive (a bob pinned to a disabled anchor falls freely); enabling finds
// its pairs at the next step and the joint holds again.
BOOST_AUTO_TEST_CASE(disabling_ends_contacts_and_deactivates_joints, *utf::label("IM1")) {
    World w(WorldDef{.gravity = {0.0, -10.0}});
    ground(w);
    const BodyId resting = box(w, 0.0, 0.5);
    for (int i = 0; i < 10; ++i)
        w.step(dt);
    BOOST_TEST_REQUIRE(w.contacts().size() == 1u);
    w.set_enabled(resting, false);
    BOOST_TEST(w.contacts().empty());
    BOOST_TEST(w.contact_end_events().size() == 1u);
    w.set_enabled(resting, true);
    w.step(dt);
    BOOST_TEST(w.contacts().size() == 1u);

    const BodyId anchor =
        w.create_body(BodyDef{.type = BodyType::static_body, .position = {10.0, 10.0}});
    const BodyId bob = w.create_body(BodyDef{.position = {11.0, 10.0}});
    w.create_shape(bob, circle_shape(0.1));
    RevoluteJointDef r;
    r.body_a = anchor;
    r.body_b = bob;
    r.anchor = {10.0, 10.0};
    w.create_joint(r);
    w.set_enabled(anchor, false);
    for (int n = 1; n <= 30; ++n) {
        w.step(dt);
        BOOST_TEST_REQUIRE(
            rel_err(w.position(bob).y, 10.0 + fall_displacement(-10.0, n * substeps)) < 1e-12);
        BOOST_TEST_REQUIRE(w.position(bob).x == 11.0);
    }
}

// Oracle: DD28's rule with the disabled body out of the world: a sensor reports a visitor
// that is disabled as leaving at the next step, and again as entering once it is enabled.
BOOST_AUTO_TEST_CASE(a_disabled_visitor_leaves_a_sensor, *utf::label("DD28")) {
    World w(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId zone = w.create_body(BodyDef{.type = BodyType::static_body});
    ShapeDef sensor = box_shape(4.0, 4.0);
    sensor.is_sensor = true;
    w.create_shape(zone, sensor);
    const BodyId visitor = box(w, 0.0, 0.0);
    w.step(dt);
    BOOST_TEST_REQUIRE(w.sensor_begin_events().size() == 1u);
    w.set_enabled(visitor, false);
    w.step(dt);
    BOOST_TEST(w.sensor_end_events().size() == 1u);
    w.set_enabled(visitor, true);
    w.step(dt);
    BOOST_TEST(w.sensor_begin_events().size() == 1u);
}

// ----------------------------------------------------------------------------- gravity scale

// Oracle: DD16 by hand, summed over the world's dynamic bodies (World::potential_energy: each
// body's share of gravity, the origin as the reference; static and kinematic bodies have no
// mass): under g = (0, -10), 2 kg at height 3 m and 0.5 kg with gravity scale 2 at height -4 m
// give 2 x 10 x 3 + 0.5 x 20 x (-4) = 60 - 40 = 20 J, wherever they are across x.
BOOST_AUTO_TEST_CASE(the_potential_energy_sums_dd16_over_the_dynamic_bodies, *utf::label("DD16")) {
    World w(WorldDef{.gravity = {0.0, -10.0}});
    BOOST_TEST(w.potential_energy() == 0.0);
    ground(w);
    box(w, 7.0, 3.0, BodyDef{.mass = 2.0});
    box(w, -5.0, -4.0, BodyDef{.mass = 0.5, .gravity_scale = 2.0});
    box(w, 0.0, 9.0, BodyDef{.type = BodyType::kinematic});
    BOOST_TEST(w.potential_energy() == 20.0, boost::test_tools::tolerance(1e-14));
}

// Oracle: IM1's free fall with the body's share of gravity, s g, per substep.
BOOST_AUTO_TEST_CASE(gravity_scale_scales_the_fall, *utf::label("IM1") * utf::label("GD2")) {
    World w(WorldDef{.gravity = {0.0, -10.0}});
    const BodyId b = box(w, 0.0, 100.0);
    w.set_gravity_scale(b, 0.25);
    BOOST_TEST(w.gravity_scale(b) == 0.25);
    for (int n = 1; n <= 60; ++n) {
        w.step(dt);
        BOOST_TEST_REQUIRE(rel_err(w.velocity(b).y, fall_velocity(-2.5, n * substeps)) < 1e-12);
        BOOST_TEST_REQUIRE(rel_err(w.position(b).y, 100.0 + fall_displacement(-2.5, n * substeps)) <
                           1e-12);
    }
    const std::uint64_t before = w.state_hash();
    BOOST_CHECK_THROW(w.set_gravity_scale(b, std::nan("")), ValidationError);
    BOOST_CHECK_THROW(w.set_gravity_scale(b, 1e13), ValidationError);
    BOOST_TEST(w.state_hash() == before);
    try {
        w.set_gravity_scale(b, std::numeric_limits<double>::infinity());
    } catch (const ValidationError& e) {
        BOOST_TEST(e.field == "gravity_scale");
    }
}

// ----------------------------------------------------------------------------- bullet

// Oracle: a world whose body was made a bullet by its definition (BodyDef::bullet): the same
// bits, step by step, for a fast box shot at a thin moving plate.
BOOST_AUTO_TEST_CASE(set_bullet_equals_a_bullet_definition, *utf::label("DD29")) {
    auto scene = [](bool by_definition) {
        World w(WorldDef{.gravity = {0.0, 0.0}});
        const BodyId plate = w.create_body(BodyDef{.position = {5.0, 0.0}});
        w.create_shape(plate, box_shape(0.05, 4.0));
        BodyDef shot;
        shot.position = {0.0, 0.0};
        shot.linear_velocity = {400.0, 0.0};
        shot.bullet = by_definition;
        const BodyId b = w.create_body(shot);
        w.create_shape(b, circle_shape(0.1));
        if (!by_definition)
            w.set_bullet(b, true);
        return w;
    };
    World a = scene(true);
    World b = scene(false);
    BOOST_TEST(b.is_bullet(b.bodies()[1]));
    BOOST_TEST(same_history(a, b, 30));
    // A bullet does not pass through the plate (DD29): it stays on the plate's left.
    BOOST_TEST(b.position(b.bodies()[1]).x < b.position(b.bodies()[0]).x);
}

BOOST_AUTO_TEST_SUITE_END()
