// T4 (Newton's second law for rotation, tau = I alpha), checked against hand values and
// against T1 applied to a point mass on a massless arm (with DD13's torque and DD14's inertia).
#include <boost/test/unit_test.hpp>

#include "tamias2d/model/dd13_torque.hpp"
#include "tamias2d/model/dd14_moment_of_inertia.hpp"
#include "tamias2d/model/t1_newtons_second_law.hpp"
#include "tamias2d/model/t4_rotational_second_law.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace t1 = tamias2d::model::t1;
namespace t4 = tamias2d::model::t4;
namespace dd13 = tamias2d::model::dd13;
namespace dd14 = tamias2d::model::dd14;

namespace {
const auto kg_m2 = kilogram * metre * metre / (radian * radian); // per-radian convention
const auto N_m = newton * metre / radian;
const auto rad_s2 = radian / (second * second);
constexpr double few_ulp = 1e-15;
} // namespace

BOOST_AUTO_TEST_SUITE(t4_rotational_second_law)

// Oracle: hand derivation. alpha = tau / I = 6 N m / 2 kg m^2 = 3 rad s^-2, and the
// clockwise torque -6 N m gives -3 rad s^-2 (sign convention A4).
BOOST_AUTO_TEST_CASE(angular_acceleration_hand_value, *utf::label("T4")) {
    const MomentOfInertia I = 2.0 * kg_m2;
    BOOST_TEST(t4::angular_acceleration(6.0 * N_m, I).value() == 3.0, tt::tolerance(few_ulp));
    BOOST_TEST(t4::angular_acceleration(-6.0 * N_m, I).value() == -3.0, tt::tolerance(few_ulp));
}

// Oracle: hand derivation. tau = I alpha = 74.5 kg m^2 (SRS typical I) x 0.4 rad s^-2 =
// 29.8 N m; and the two forms are inverse (tau = I (tau / I), two roundings).
BOOST_AUTO_TEST_CASE(torque_hand_value_and_inverse, *utf::label("T4")) {
    const MomentOfInertia I = 74.5 * kg_m2;
    BOOST_TEST(t4::torque(I, 0.4 * rad_s2).value() == 29.8, tt::tolerance(few_ulp));
    const Torque tau = 200.0 * N_m; // SRS Table 1 typical torque
    BOOST_TEST(t4::torque(I, t4::angular_acceleration(tau, I)).value() == 200.0,
               tt::tolerance(few_ulp));
}

// Oracle: textbook equivalence with T1. A point mass m on a massless arm of length r, pushed by
// a tangential force F: DD13 gives tau = r F, DD14 gives I = m r^2, T4 gives alpha = F / (m r),
// so the tangential acceleration r alpha must equal T1's F / m. m = 2 kg, r = 0.5 m, F = 3 N:
// tau = 1.5 N m, I = 0.5 kg m^2, alpha = 3 rad s^-2, r alpha = 1.5 m s^-2 = F / m.
BOOST_AUTO_TEST_CASE(point_mass_on_arm_matches_t1, *utf::label("T4") * utf::label("T1") *
                                                       utf::label("DD13") * utf::label("DD14")) {
    const Mass m = 2.0 * kilogram;
    const Vec2<Length> r{0.5 * metre, 0.0 * metre};
    const Vec2<Force> F{0.0 * newton, 3.0 * newton};
    const Torque tau = dd13::torque(r, F);
    const dd14::Particle p[] = {{m, 0.5 * metre}};
    const MomentOfInertia I = dd14::moment_of_inertia(p);
    BOOST_TEST(tau.value() == 1.5, tt::tolerance(few_ulp));
    BOOST_TEST(I.value() == 0.5, tt::tolerance(few_ulp));
    const AngularAcceleration alpha = t4::angular_acceleration(tau, I);
    BOOST_TEST(alpha.value() == 3.0, tt::tolerance(few_ulp));
    const Acceleration tangential = r.x * alpha / (1.0 * radian); // a_t = r alpha (per radian)
    BOOST_TEST(tangential.value() == t1::acceleration(F, m).y.value(), tt::tolerance(few_ulp));
}

BOOST_AUTO_TEST_SUITE_END()
