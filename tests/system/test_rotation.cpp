// System test cases TC8-TC9 (R6, IM2): rotation under constant torque and at constant angular
// velocity, over the whole history, against closed forms; both senses of rotation, and bodies
// that also translate (non-zero vertical velocity). Orientation is reported in [0, 2 pi).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "system/system_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::system_test;

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;
constexpr double exact_rel = 1e-12;

struct Spin {
    double phi0, omega0, alpha; ///< rad, rad/s, rad/s^2
    Vec2d v0;                   ///< m/s: the body also translates
};

/// Runs boxes 2 x 1 m of density 1.5 (m = 3 kg, I = m (w^2 + h^2) / 12 = 1.25 kg m^2, DD14 by
/// hand) with torque tau = alpha I and checks every step against
///  * IM2's exact discrete solution phi_n = phi0 + omega0 t + alpha t^2/2 + alpha h t/2,
///    omega_n = omega0 + alpha t (norm-relative error over the history at round-off),
///  * the continuous solution phi(t) = phi0 + omega0 t + alpha t^2 / 2 within |alpha| h t / 2,
///  * the reported orientation in [0, 2 pi) (DCO_phi), and p(t) = p0 + v0 t (no force).
void check_spins(const std::vector<Spin>& spins, double dt, int steps) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    std::vector<BodyId> ids;
    std::vector<Vec2d> p0s;
    for (std::size_t i = 0; i < spins.size(); ++i) {
        BodyDef def;
        def.position = {10.0 * double(i), 0.0};
        def.angle = spins[i].phi0;
        def.angular_velocity = spins[i].omega0;
        def.linear_velocity = spins[i].v0;
        def.torque = spins[i].alpha * 1.25;
        const BodyId b = world.create_body(def);
        world.create_shape(b, box_shape(2.0, 1.0, Material{1.5, 0.0, 0.0}));
        BOOST_TEST(std::abs(world.inertia(b) - 1.25) < 1e-14);
        ids.push_back(b);
        p0s.push_back(def.position);
    }
    const double h = dt / world.settings().substeps;
    History discrete, omega, continuous, position;
    std::vector<double> unwrapped;
    for (const Spin& s : spins)
        unwrapped.push_back(s.phi0);
    bool in_range = true, within = true;
    for (int n = 1; n <= steps; ++n) {
        world.step(dt);
        const double t = n * dt;
        for (std::size_t i = 0; i < spins.size(); ++i) {
            const Spin& s = spins[i];
            const BodyState st = world.state(ids[i]);
            in_range = in_range && st.orientation >= 0.0 && st.orientation < two_pi;
            unwrapped[i] = unwrap(st.orientation, unwrapped[i]);
            discrete.add(unwrapped[i], discrete_position(s.phi0, s.omega0, s.alpha, t, h));
            omega.add(st.angular_velocity, s.omega0 + s.alpha * t);
            const double phi_c = s.phi0 + s.omega0 * t + 0.5 * s.alpha * t * t;
            continuous.add(unwrapped[i], phi_c);
            within = within && std::abs(unwrapped[i] - phi_c) <=
                                   0.5 * std::abs(s.alpha) * h * t * (1.0 + 1e-9) + 1e-11;
            position.add(st.position, p0s[i] + t * s.v0);
        }
    }
    BOOST_TEST(in_range, "orientation in [0, 2 pi) at every step");
    BOOST_TEST(discrete.rel_error() < exact_rel);
    BOOST_TEST(omega.rel_error() < exact_rel);
    BOOST_TEST(within, "pointwise |phi - phi(t)| <= |alpha| h t / 2 at every step");
    BOOST_TEST(position.rel_error() < exact_rel);
    BOOST_TEST_MESSAGE("rotation history: discrete rel "
                       << discrete.rel_error() << ", continuous rel " << continuous.rel_error());
}

} // namespace

// Oracle: closed form of IM2 with constant alpha = tau / I (T4): omega = omega0 + alpha t (the
// change alpha dt of every step, DD7, summed), phi = phi0 + omega0 t + alpha t^2 / 2 (+ the
// scheme's alpha h t / 2); counter-clockwise and clockwise torques, from rest, against an
// initial spin, and while translating.
BOOST_AUTO_TEST_CASE(TC8_rotation_under_constant_torque, *utf::label("R6") * utf::label("IM2") *
                                                             utf::label("T4") * utf::label("DD7") *
                                                             utf::label("DCO_phi")) {
    check_spins({{0.0, 0.0, 2.0, {0.0, 0.0}},
                 {0.0, 0.0, -2.0, {0.0, 0.0}},
                 {1.0, 1.2, -3.0, {0.0, 2.0}},
                 {5.5, -1.2, 3.0, {1.0, -2.0}},
                 {-0.4, 0.0, 0.4, {-1.0, 0.5}}},
                1.0 / 60.0, 300);
}

// Oracle: closed form of IM2 with alpha = 0: phi(t) = phi0 + omega t (the turn omega dt of every
// step, DD6, summed), omega constant (exact for the scheme), wrapped into [0, 2 pi); slow and
// fast (20 rad/s: many turns) in both senses.
BOOST_AUTO_TEST_CASE(TC9_constant_angular_velocity, *utf::label("R6") * utf::label("IM2") *
                                                        utf::label("DD6") * utf::label("DCO_phi")) {
    check_spins({{0.0, 3.0, 0.0, {0.0, 0.0}},
                 {0.0, -3.0, 0.0, {0.0, 0.0}},
                 {2.0, 20.0, 0.0, {0.0, 1.5}},
                 {6.0, -20.0, 0.0, {-2.0, -1.5}},
                 {-7.0, 0.25, 0.0, {0.0, 0.0}}},
                1.0 / 60.0, 600);
}
