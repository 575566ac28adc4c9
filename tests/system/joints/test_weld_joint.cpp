// Weld joints (LC3: DD24, IM6) in the engine, against independent oracles: the statics of a
// cantilever (the reaction force and torque that balance the weight) and the damped harmonic
// oscillator (a soft weld's angle).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "support/damped_oscillator.hpp"
#include "system/system_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::system_test;
using tamias2d::test::DampedOscillator;

namespace {

constexpr double g = 9.81;

/// `n` 1 m beams under gravity, each welded rigidly at its left end to one static wall, the
/// k-th at height 2k m (far apart: no beam touches another).
struct Cantilevers {
    World world{WorldDef{.gravity = {0.0, -g}, .enable_sleep = false}};
    std::vector<std::pair<BodyId, JointId>> beams;
    explicit Cantilevers(int n) {
        BodyDef wall_def;
        wall_def.type = BodyType::static_body;
        const BodyId wall = world.create_body(wall_def);
        for (int k = 0; k < n; ++k) {
            const double y = 2.0 * k;
            BodyDef beam_def;
            beam_def.position = {0.5, y};
            const BodyId beam = world.create_body(beam_def);
            world.create_shape(beam, box_shape(1.0, 0.1));
            beams.emplace_back(beam, world.create_joint(WeldJointDef{
                                         .body_a = wall, .body_b = beam, .anchor = {0.0, y}}));
        }
        for (int k = 0; k < 120; ++k)
            world.step(1.0 / 60.0);
    }
};

} // namespace

BOOST_AUTO_TEST_SUITE(weld_joint)

// Oracle: statics. A 1 m beam welded at its left end to a static wall holds still under
// gravity; the joint must then balance its weight at the anchor, force (0, m g), and the
// weight's moment about the beam's centre, which the force at the anchor (0.5 m to the left)
// does not: the angular reaction is m g 0.5 N m. The rigid weld lets the tip sag by the soft
// joint's compliance only (below 1 mm).
BOOST_AUTO_TEST_CASE(rigid_cantilever_balances_its_weight,
                     *utf::label("DD24") * utf::label("IM6") * utf::label("LC3")) {
    Cantilevers c(1);
    World& world = c.world;
    const auto [beam, j] = c.beams.front();
    const double m = world.mass(beam);
    const Vec2d F = world.joint_reaction_force(j);
    BOOST_TEST(F.y == m * g, boost::test_tools::tolerance(1e-6));
    BOOST_TEST(std::abs(F.x) <= 1e-9 * m * g);
    BOOST_TEST(world.joint_reaction_torque(j) == 0.5 * m * g, boost::test_tools::tolerance(1e-6));
    const double sag = std::abs(world.position(beam).y) + 0.5 * std::abs(world.joint_angle(j));
    BOOST_TEST_MESSAGE("cantilever tip sag " << sag << " m");
    BOOST_TEST(sag <= 1e-3);
}

// Oracle: statics, as above, for eight such beams side by side, each welded to the one wall:
// eight independent joints of one kind, which the solver may take in packs (as it packs plain
// revolute pins, DD19 alone): each weld still holds its beam's angle, balancing the torque
// m g 0.5 N m, and its tip sags by the joint's compliance only.
BOOST_AUTO_TEST_CASE(eight_cantilevers_side_by_side_each_balance_their_weight,
                     *utf::label("DD24") * utf::label("IM6") * utf::label("LC3")) {
    Cantilevers c(8);
    World& world = c.world;
    for (const auto& [beam, j] : c.beams) {
        const double m = world.mass(beam);
        BOOST_TEST(world.joint_reaction_torque(j) == 0.5 * m * g,
                   boost::test_tools::tolerance(1e-6));
        const double sag = std::abs(world.joint_angle(j));
        BOOST_TEST(0.5 * sag <= 1e-3);
    }
}

/// Which part of a weld is soft in soft_weld_error.
enum class SoftPart { angle, point };

/// A box welded at its centre to a static body with one soft part (the other rigid), set
/// turning (soft angle) or moving along x (soft point) at `speed`: the largest deviation over
/// 2 s of its angle or its centre's x from the oscillator.
double soft_weld_error(int steps_per_second, const DampedOscillator& osc, double speed,
                       SoftPart part) {
    World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false});
    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    const BodyId ground = world.create_body(ground_def);
    BodyDef box_def;
    WeldJointDef weld{.body_a = ground, .anchor = {0.0, 0.0}};
    if (part == SoftPart::angle) {
        box_def.angular_velocity = speed;
        weld.angular_hertz = osc.hertz;
        weld.angular_damping_ratio = osc.zeta;
    } else {
        box_def.linear_velocity = {speed, 0.0};
        weld.linear_hertz = osc.hertz;
        weld.linear_damping_ratio = osc.zeta;
    }
    const BodyId box = world.create_body(box_def);
    world.create_shape(box, box_shape(0.8, 0.3));
    weld.body_b = box;
    const JointId j = world.create_joint(weld);
    double worst = 0.0;
    for (int k = 1; k <= 2 * steps_per_second; ++k) {
        world.step(1.0 / steps_per_second);
        const double t = k * 1.0 / steps_per_second;
        const double x = part == SoftPart::angle ? world.joint_angle(j) : world.position(box).x;
        worst = std::max(worst, std::abs(x - osc.from_speed(speed, t)));
    }
    return worst;
}

// Oracle: the damped harmonic oscillator. With the anchor at the box's centre of mass and the
// other body static, the rigid point holds the centre still and the soft angle is a torsional
// spring of frequency f for the box's inertia: from theta = 0 at speed w0, theta(t) = w0 /
// omega_d e^(-zeta omega t) sin(omega_d t). At 1.5 Hz and at 0.8 Hz (a spring below 1 Hz is a
// spring too), zeta 0.2: first order, the error halves with the step (ratio >= 1.8) and is
// below 2 % of the amplitude w0 / omega at 1/480 s.
BOOST_AUTO_TEST_CASE(soft_angle_is_a_damped_oscillator,
                     *utf::label("DD24") * utf::label("IM6") * utf::label("LC3")) {
    for (const double hertz : {1.5, 0.8}) {
        const DampedOscillator osc{hertz, 0.2};
        const double w0 = 2.0;
        const double e240 = soft_weld_error(240, osc, w0, SoftPart::angle);
        const double e480 = soft_weld_error(480, osc, w0, SoftPart::angle);
        BOOST_TEST_MESSAGE("soft weld at " << hertz << " Hz: max deviation " << e240
                                           << " rad at 1/240 s, " << e480 << " rad at 1/480 s");
        BOOST_TEST(e480 <= 0.02 * w0 / osc.omega());
        BOOST_TEST(e240 / e480 >= 1.8);
    }
}

// Oracle: the damped harmonic oscillator, as above, for the soft point: with the anchor at the
// box's centre of mass and the other body static, the point is a linear spring of frequency f
// for the box's mass: from x = 0 at speed v0, x(t) = v0 / omega_d e^(-zeta omega t)
// sin(omega_d t). At 0.8 Hz (a spring below 1 Hz is a spring too), zeta 0.2: first order, the
// error halves with the step (ratio >= 1.8) and is below 2 % of the amplitude v0 / omega at
// 1/480 s.
BOOST_AUTO_TEST_CASE(soft_point_is_a_damped_oscillator,
                     *utf::label("DD24") * utf::label("IM6") * utf::label("LC3")) {
    const DampedOscillator osc{0.8, 0.2};
    const double v0 = 1.0;
    const double e240 = soft_weld_error(240, osc, v0, SoftPart::point);
    const double e480 = soft_weld_error(480, osc, v0, SoftPart::point);
    BOOST_TEST_MESSAGE("soft weld point: max deviation " << e240 << " m at 1/240 s, " << e480
                                                         << " m at 1/480 s");
    BOOST_TEST(e480 <= 0.02 * v0 / osc.omega());
    BOOST_TEST(e240 / e480 >= 1.8);
}

// Oracle: rigid-body kinematics (a weld's anchor moves with both bodies) and T4 (a body of
// infinite moment of inertia never turns). A fixed-rotation box welded to a kinematic carrier
// moving at (2, 0) m/s: neither can turn, so the weld's angle holds nothing (DD22's k = 0) and
// only its point acts. The carrier keeps its closed-form motion p0 + v t exactly (no joint
// moves a kinematic body), the box rides along at the carrier's velocity, holding up its own
// weight, and never turns. Found by the API fuzz target: the angle's -rhs / 0 made both
// bodies NaN (tests/fuzz/libfuzzer/regressions/api/weld_fixed_rotation_to_kinematic_body_nan).
BOOST_AUTO_TEST_CASE(fixed_rotation_body_welded_to_a_kinematic_carrier,
                     *utf::label("DD22") * utf::label("DD24") * utf::label("LC3")) {
    World world(WorldDef{.gravity = {0.0, -10.0}, .enable_sleep = false});
    BodyDef carrier_def;
    carrier_def.type = BodyType::kinematic;
    carrier_def.linear_velocity = {2.0, 0.0};
    const BodyId carrier = world.create_body(carrier_def);
    world.create_shape(carrier, box_shape(1.0, 1.0));
    BodyDef box_def;
    box_def.position = {1.5, 0.5};
    box_def.fixed_rotation = true;
    const BodyId box = world.create_body(box_def);
    world.create_shape(box, box_shape(0.5, 0.5));
    world.create_joint(WeldJointDef{.body_a = carrier, .body_b = box, .anchor = {1.0, 0.5}});
    const int steps = 120;
    for (int k = 0; k < steps; ++k)
        world.step(1.0 / 60.0);
    const double t = steps / 60.0;
    BOOST_TEST(world.position(carrier).x == 2.0 * t, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(world.position(carrier).y == 0.0);
    BOOST_TEST(world.angular_velocity(carrier) == 0.0);
    BOOST_TEST(world.orientation(box) == 0.0);
    BOOST_TEST(world.angular_velocity(box) == 0.0);
    BOOST_TEST(std::abs(world.velocity(box).x - 2.0) <= 1e-6);
    BOOST_TEST(std::abs(world.velocity(box).y) <= 1e-6);
    // The anchor, 0.5 m left of the box's centre, stays on the carrier's point (1 + 2 t, 0.5).
    BOOST_TEST(std::abs(world.position(box).x - (1.5 + 2.0 * t)) <= 1e-3);
    BOOST_TEST(std::abs(world.position(box).y - 0.5) <= 1e-3);
}

BOOST_AUTO_TEST_SUITE_END()
