// T1 (Newton's second law of motion, F = m a), checked against hand-derived values.
#include <boost/test/unit_test.hpp>

#include "tamias2d/model/t1_newtons_second_law.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace t1 = tamias2d::model::t1;

namespace {
// One multiplication or division: the result is the correctly rounded value, within 1 ulp of
// the hand value (2.2e-16 relative); 1e-15 leaves room for the hand value's own rounding.
constexpr double few_ulp = 1e-15;
} // namespace

BOOST_AUTO_TEST_SUITE(t1_newtons_second_law)

// Oracle: hand derivation. a = F / m = (6, -9) N / 3 kg = (2, -3) m s^-2.
BOOST_AUTO_TEST_CASE(acceleration_hand_value, *utf::label("T1")) {
    const Vec2<Force> F{6.0 * newton, -9.0 * newton};
    const Vec2<Acceleration> a = t1::acceleration(F, 3.0 * kilogram);
    BOOST_TEST(a.x.value() == 2.0, tt::tolerance(few_ulp));
    BOOST_TEST(a.y.value() == -3.0, tt::tolerance(few_ulp));
}

// Oracle: hand derivation. F = m a = 2.5 kg (4, -0.8) m s^-2 = (10, -2) N.
BOOST_AUTO_TEST_CASE(force_hand_value, *utf::label("T1")) {
    const Vec2<Acceleration> a{4.0 * metre / (second * second), -0.8 * metre / (second * second)};
    const Vec2<Force> F = t1::force(2.5 * kilogram, a);
    BOOST_TEST(F.x.value() == 10.0, tt::tolerance(few_ulp));
    BOOST_TEST(F.y.value() == -2.0, tt::tolerance(few_ulp));
}

// Oracle: textbook identity. The two forms of T1 are inverse to each other, F = m (F / m), and
// the law is linear (superposition): a(F1 + F2) = a(F1) + a(F2). Two or three roundings.
BOOST_AUTO_TEST_CASE(inverse_forms_and_superposition, *utf::label("T1")) {
    const Mass m = 0.7 * kilogram;
    const Vec2<Force> F1{1.3 * newton, -4.1 * newton};
    const Vec2<Force> F2{-0.6 * newton, 2.9 * newton};
    const Vec2<Force> back = t1::force(m, t1::acceleration(F1, m));
    BOOST_TEST(back.x.value() == F1.x.value(), tt::tolerance(few_ulp));
    BOOST_TEST(back.y.value() == F1.y.value(), tt::tolerance(few_ulp));
    const Vec2<Acceleration> sum = t1::acceleration(F1 + F2, m);
    const Vec2<Acceleration> parts = t1::acceleration(F1, m) + t1::acceleration(F2, m);
    BOOST_TEST(sum.x.value() == parts.x.value(), tt::tolerance(1e-14));
    BOOST_TEST(sum.y.value() == parts.y.value(), tt::tolerance(1e-14));
}

// Oracle: textbook identity (proportionality). Doubling the mass at the same force halves the
// acceleration; zero net force gives zero acceleration (first law as a special case).
BOOST_AUTO_TEST_CASE(acceleration_inversely_proportional_to_mass, *utf::label("T1")) {
    const Vec2<Force> F{3.0 * newton, 5.0 * newton};
    const Vec2<Acceleration> a1 = t1::acceleration(F, 1.5 * kilogram);
    const Vec2<Acceleration> a2 = t1::acceleration(F, 3.0 * kilogram);
    BOOST_TEST(a1.x.value() == 2.0 * a2.x.value(), tt::tolerance(few_ulp));
    BOOST_TEST(a1.y.value() == 2.0 * a2.y.value(), tt::tolerance(few_ulp));
    const Vec2<Acceleration> a0 = t1::acceleration(Vec2<Force>{}, 1.5 * kilogram);
    BOOST_TEST(a0.x.value() == 0.0);
    BOOST_TEST(a0.y.value() == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
