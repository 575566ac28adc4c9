// A joint's step state (JointStepState, joint.hpp): what forgetting its impulses leaves. The
// world forgets them where its rules say a solve starts cold: every step with warm starting off
// (World::set_warm_starting: "each step's solve starts from zero impulses") and the next solve
// of a body's joints after its type changes or it is disabled (World::set_body_type).
#include <boost/test/unit_test.hpp>

#include "tamias2d/dynamics/joints/joint.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

BOOST_AUTO_TEST_SUITE(joint_step_state)

// Oracle: those rules, and forget_impulses' own (the axis of the last solve is kept, for it is
// no impulse): a state whose every field is non-zero keeps only its axis, and every kind's
// impulse (pin, rod, motor, limits, spring, angle, line) reads zero.
BOOST_AUTO_TEST_CASE(forgetting_the_impulses_zeroes_every_one_and_keeps_the_axis,
                     *utf::label("internals")) {
    JointStepState st;
    st.linear_impulse = {1.0, -2.0};
    st.axial_impulse = 3.0;
    st.axis = {0.6, 0.8};
    st.motor_impulse = 4.0;
    st.lower_impulse = 5.0;
    st.upper_impulse = 6.0;
    st.spring_impulse = 7.0;
    st.angular_impulse = 8.0;
    st.perp_impulse = 9.0;
    forget_impulses(st);
    BOOST_TEST(st.linear_impulse.x == 0.0);
    BOOST_TEST(st.linear_impulse.y == 0.0);
    BOOST_TEST(st.axial_impulse == 0.0);
    BOOST_TEST(st.motor_impulse == 0.0);
    BOOST_TEST(st.lower_impulse == 0.0);
    BOOST_TEST(st.upper_impulse == 0.0);
    BOOST_TEST(st.spring_impulse == 0.0);
    BOOST_TEST(st.angular_impulse == 0.0);
    BOOST_TEST(st.perp_impulse == 0.0);
    BOOST_TEST(st.axis.x == 0.6);
    BOOST_TEST(st.axis.y == 0.8);
    // Every field is named above: a new one must be added here and to forget_impulses.
    static_assert(sizeof(JointStepState) == 11 * sizeof(double));
}

BOOST_AUTO_TEST_SUITE_END()
