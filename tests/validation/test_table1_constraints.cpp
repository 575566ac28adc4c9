// R4 for the rows of SRS Table 1 (section 5.2.6): each input variable's physical constraint is
// enforced with a ValidationError naming the field and the row's label, and a rejected call
// leaves the world bit-for-bit unchanged. Rows whose constraint is "None" accept any finite
// value and reject NaN and infinities (DCX_finite, the project's correction, srs/errata E31).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "validation_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::test;

namespace {
constexpr double two_pi = 2.0 * std::numbers::pi;
} // namespace

BOOST_AUTO_TEST_SUITE(table1_constraints)

// Oracle: SRS Table 1, row C_R: 0 <= C_R <= 1 (closed interval: both end points are valid).
BOOST_AUTO_TEST_CASE(restitution_outside_0_1_is_rejected,
                     *utf::label("R4") * utf::label("DCI_CR")) {
    MovingWorld m;
    for (const double cr : {-0.1, -1e-12, 1.0 + 1e-12, 1.5, 1e9}) {
        BOOST_TEST_CONTEXT("C_R = " << cr) {
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.create_shape(m.box, circle_shape(0.25, Material{1.0, cr, 0.0}));
                },
                "restitution", "DCI_CR", cr);
        }
    }
    for (const double cr : {0.0, 1.0}) {
        BOOST_TEST_CONTEXT("C_R = " << cr) {
            BOOST_CHECK_NO_THROW(
                m.world.create_shape(m.ball, circle_shape(0.1, Material{1.0, cr, 0.0})));
        }
    }
}

// Oracle: SRS Table 1, row I (I >= 0), corrected to I > 0 (srs/data_constraints.yaml DCI_I):
// IM2 and DD8 divide by I, so a given moment of inertia of 0 or less is rejected.
BOOST_AUTO_TEST_CASE(non_positive_moment_of_inertia_is_rejected,
                     *utf::label("R4") * utf::label("DCI_I")) {
    MovingWorld m;
    for (const double I : {0.0, -0.0, -1e-300, -74.5}) {
        BOOST_TEST_CONTEXT("I = " << I) {
            BodyDef d;
            d.inertia = I;
            expect_rejected_value(
                m.world, [&] { m.world.create_body(d); }, "inertia", "DCI_I", I);
        }
    }
    BodyDef d; // Table 1's typical value is accepted and used as given
    d.inertia = 74.5;
    const BodyId id = m.world.create_body(d);
    m.world.create_shape(id, box_shape(1.0, 1.0));
    BOOST_TEST(m.world.inertia(id) == 74.5);
}

// Oracle: SRS Table 1, row L (L >= 0), corrected to "a shape dimension is > 0" and enforced as
// DCX_shape (srs/data_constraints.yaml DCI_L): box width and height, circle radius.
BOOST_AUTO_TEST_CASE(non_positive_lengths_are_rejected,
                     *utf::label("R4") * utf::label("DCI_L") * utf::label("DCX_shape")) {
    MovingWorld m;
    for (const double L : {0.0, -0.0, -1e-300, -44.2}) {
        BOOST_TEST_CONTEXT("L = " << L) {
            // The shape factories reject it before any world is involved ...
            expect_validation_error([&] { (void)box_shape(L, 1.0); }, "shape.width", "DCX_shape");
            expect_validation_error([&] { (void)box_shape(1.0, L); }, "shape.height", "DCX_shape");
            expect_validation_error([&] { (void)circle_shape(L); }, "radius", "DCX_shape");
            // ... and the world rejects a hand-made shape that bypassed them.
            ShapeDef bad;
            bad.geometry.type = ShapeType::circle;
            bad.geometry.circle.radius = L;
            expect_rejected_value(
                m.world, [&] { m.world.create_shape(m.box, bad); }, "radius", "DCX_shape", L);
        }
    }
    BOOST_CHECK_NO_THROW(m.world.create_shape(m.box, circle_shape(1e-3)));
}

// Oracle: SRS Table 1, row m (m >= 0), corrected to m > 0 (srs/data_constraints.yaml DCI_m):
// IM1 divides by m, so a given mass of 0 or less is rejected.
BOOST_AUTO_TEST_CASE(non_positive_mass_is_rejected, *utf::label("R4") * utf::label("DCI_m")) {
    MovingWorld m;
    for (const double mass : {0.0, -0.0, -1e-300, -56.2}) {
        BOOST_TEST_CONTEXT("m = " << mass) {
            BodyDef d;
            d.mass = mass;
            expect_rejected_value(
                m.world, [&] { m.world.create_body(d); }, "mass", "DCI_m", mass);
        }
    }
    BodyDef d; // Table 1's typical value is accepted and used as given
    d.mass = 56.2;
    const BodyId id = m.world.create_body(d);
    m.world.create_shape(id, box_shape(1.0, 1.0));
    BOOST_TEST(m.world.mass(id) == 56.2);
}

// Oracle: the project's reading of Table 1 row phi (srs/data_constraints.yaml DCI_phi, DCO_phi,
// errata E64): any finite input angle is accepted and read back reduced into [0, 2 pi); the
// reduction is checked by trigonometry (cos and sin of the output equal those of the input)
// and by the half-open interval, including -1e-300, whose naive wrap rounds to exactly 2 pi.
BOOST_AUTO_TEST_CASE(any_finite_orientation_is_accepted_and_read_back_wrapped,
                     *utf::label("R4") * utf::label("DCI_phi") * utf::label("DCO_phi")) {
    MovingWorld m;
    const std::vector<double> angles = {
        0.0, std::numbers::pi / 2, -1.0, 7.0, two_pi, -two_pi, 100.0, -1e6, 1e6, -1e-300, 1e-300,
        -0.0};
    for (const double a : angles) {
        BOOST_TEST_CONTEXT("phi_in = " << a) {
            BodyDef d;
            d.angle = a;
            const BodyId id = m.world.create_body(d);
            m.world.create_shape(id, box_shape(1.0, 1.0));
            const double phi = m.world.orientation(id);
            BOOST_TEST(phi >= 0.0);
            BOOST_TEST(phi < two_pi);
            BOOST_TEST(std::abs(std::cos(phi) - std::cos(a)) < 1e-9);
            BOOST_TEST(std::abs(std::sin(phi) - std::sin(a)) < 1e-9);
            BOOST_TEST(m.world.state(id).orientation == phi);

            m.world.set_transform(id, {10.0, 10.0}, a); // the same through set_transform
            BOOST_TEST(m.world.orientation(id) == phi);
            m.world.destroy_body(id);
        }
    }
    // A spinning body's output stays in [0, 2 pi) while its angle grows without bound.
    for (int i = 0; i < 600; ++i) {
        m.world.step(1.0 / 60.0);
        const double phi = m.world.orientation(m.plate);
        BOOST_TEST_REQUIRE((phi >= 0.0 && phi < two_pi), "step " << i << ": phi = " << phi);
    }
    for (const double bad : non_finite) {
        BOOST_TEST_CONTEXT("phi_in = " << bad) {
            BodyDef d;
            d.angle = bad;
            expect_rejected_value(
                m.world, [&] { m.world.create_body(d); }, "angle", "DCX_finite", bad);
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.set_transform(m.box, {0.0, 0.5}, bad);
                },
                "angle", "DCX_finite", bad);
        }
    }
}

// Oracle: SRS Table 1, row p: "None" (any position), corrected to every component finite
// (DCX_finite): the body definition and set_transform accept far positions, reject NaN/Inf.
BOOST_AUTO_TEST_CASE(position_must_be_finite,
                     *utf::label("R4") * utf::label("DCI_p") * utf::label("DCX_finite")) {
    MovingWorld m;
    for (const Vec2d p : {Vec2d{0.412, 0.502}, Vec2d{-1e6, 1e6}}) {
        BodyDef d;
        d.position = p;
        const BodyId id = m.world.create_body(d);
        BOOST_TEST(m.world.origin(id).x == p.x);
        BOOST_TEST(m.world.origin(id).y == p.y);
    }
    for (const double bad : non_finite) {
        BOOST_TEST_CONTEXT("p component = " << bad) {
            BodyDef d;
            d.position = {bad, 0.0};
            expect_rejected_value(
                m.world, [&] { m.world.create_body(d); }, "position", "DCX_finite", bad);
            d.position = {0.0, bad};
            expect_rejected_value(
                m.world, [&] { m.world.create_body(d); }, "position", "DCX_finite", bad);
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.set_transform(m.box, {bad, 0.0}, 0.0);
                },
                "origin", "DCX_finite", bad);
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.set_transform(m.box, {0.0, bad}, 0.0);
                },
                "origin", "DCX_finite", bad);
        }
    }
}

// Oracle: SRS Table 1, row v: "None", corrected to every component finite (DCX_finite).
BOOST_AUTO_TEST_CASE(velocity_must_be_finite,
                     *utf::label("R4") * utf::label("DCI_v") * utf::label("DCX_finite")) {
    MovingWorld m;
    BodyDef ok;
    ok.linear_velocity = {2.51, -1e6};
    BOOST_TEST(m.world.velocity(m.world.create_body(ok)).y == -1e6);
    for (const double bad : non_finite) {
        BOOST_TEST_CONTEXT("v component = " << bad) {
            BodyDef d;
            d.linear_velocity = {bad, 0.0};
            expect_rejected_value(
                m.world, [&] { m.world.create_body(d); }, "velocity", "DCX_finite", bad);
            d.linear_velocity = {0.0, bad};
            expect_rejected_value(
                m.world, [&] { m.world.create_body(d); }, "velocity", "DCX_finite", bad);
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.set_velocity(m.ball, {bad, 0.0});
                },
                "velocity", "DCX_finite", bad);
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.set_velocity(m.ball, {0.0, bad});
                },
                "velocity", "DCX_finite", bad);
        }
    }
}

// Oracle: SRS Table 1, row omega: "None", corrected to finite (DCX_finite).
BOOST_AUTO_TEST_CASE(angular_velocity_must_be_finite,
                     *utf::label("R4") * utf::label("DCI_omega") * utf::label("DCX_finite")) {
    MovingWorld m;
    BodyDef ok;
    ok.angular_velocity = -2.1;
    BOOST_TEST(m.world.angular_velocity(m.world.create_body(ok)) == -2.1);
    for (const double bad : non_finite) {
        BOOST_TEST_CONTEXT("omega = " << bad) {
            BodyDef d;
            d.angular_velocity = bad;
            expect_rejected_value(
                m.world, [&] { m.world.create_body(d); }, "angular_velocity", "DCX_finite", bad);
            expect_rejected_value(
                m.world, [&] { m.world.set_angular_velocity(m.plate, bad); }, "angular_velocity",
                "DCX_finite", bad);
        }
    }
}

// Oracle: SRS Table 1, row F: "None", corrected to every component finite (DCX_finite), for
// every way a force enters: the body definition, set_force, apply_force (force and point of
// application) and a time-varying load F(t) evaluated by step().
BOOST_AUTO_TEST_CASE(force_must_be_finite,
                     *utf::label("R4") * utf::label("DCI_F") * utf::label("DCX_finite")) {
    MovingWorld m;
    BodyDef ok;
    ok.force = {98.1, -98.1};
    BOOST_CHECK_NO_THROW(m.world.create_body(ok));
    for (const double bad : non_finite) {
        BOOST_TEST_CONTEXT("F component = " << bad) {
            BodyDef d;
            d.force = {bad, 0.0};
            expect_rejected_value(
                m.world, [&] { m.world.create_body(d); }, "force", "DCX_finite", bad);
            d.force = {0.0, bad};
            expect_rejected_value(
                m.world, [&] { m.world.create_body(d); }, "force", "DCX_finite", bad);
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.set_force(m.box, {bad, 0.0});
                },
                "force", "DCX_finite", bad);
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.apply_force(m.box, {0.0, bad}, {0.0, 0.5});
                },
                "force", "DCX_finite", bad);
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.apply_force(m.box, {1.0, 0.0}, {bad, 0.5});
                },
                "world_point", "DCX_finite", bad);

            m.world.set_load(m.ball, [bad](double) { return Load{{0.0, bad}, 0.0}; });
            const Snapshot loaded = snapshot(m.world);
            expect_validation_error([&] { m.world.step(1.0 / 60.0); }, "force", "DCX_finite");
            check_unchanged(loaded, m.world);
            m.world.set_load(m.ball, {});
        }
    }
}

// Oracle: SRS Table 1, row tau: "None", corrected to finite (DCX_finite): body definition,
// set_torque, apply_torque and a time-varying load tau(t).
BOOST_AUTO_TEST_CASE(torque_must_be_finite,
                     *utf::label("R4") * utf::label("DCI_tau") * utf::label("DCX_finite")) {
    MovingWorld m;
    BodyDef ok;
    ok.torque = 200.0;
    BOOST_CHECK_NO_THROW(m.world.create_body(ok));
    for (const double bad : non_finite) {
        BOOST_TEST_CONTEXT("tau = " << bad) {
            BodyDef d;
            d.torque = bad;
            expect_rejected_value(
                m.world, [&] { m.world.create_body(d); }, "torque", "DCX_finite", bad);
            expect_rejected_value(
                m.world, [&] { m.world.set_torque(m.plate, bad); }, "torque", "DCX_finite", bad);
            expect_rejected_value(
                m.world, [&] { m.world.apply_torque(m.plate, bad); }, "torque", "DCX_finite", bad);

            m.world.set_load(m.plate, [bad](double) { return Load{{}, bad}; });
            const Snapshot loaded = snapshot(m.world);
            expect_validation_error([&] { m.world.step(1.0 / 60.0); }, "torque", "DCX_finite");
            check_unchanged(loaded, m.world);
            m.world.set_load(m.plate, {});
        }
    }
}

// Oracle: SRS Table 1, row g: "None", corrected to every component finite (DCX_finite): the
// world's settings and set_gravity; any finite vector (even pointing up) is accepted.
BOOST_AUTO_TEST_CASE(gravity_must_be_finite,
                     *utf::label("R4") * utf::label("DCI_g") * utf::label("DCX_finite")) {
    MovingWorld m;
    m.world.set_gravity({0.0, 9.8});
    BOOST_TEST(m.world.gravity().y == 9.8);
    m.world.set_gravity({0.0, -10.0});
    for (const double bad : non_finite) {
        BOOST_TEST_CONTEXT("g component = " << bad) {
            WorldDef def;
            def.gravity = {bad, 0.0};
            expect_validation_error([&] { World w(def); }, "gravity", "DCX_finite");
            def.gravity = {0.0, bad};
            expect_validation_error([&] { World w(def); }, "gravity", "DCX_finite");
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.set_gravity({bad, 0.0});
                },
                "gravity", "DCX_finite", bad);
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.set_gravity({0.0, bad});
                },
                "gravity", "DCX_finite", bad);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
