// Revolute joints in chains (LC3: DD19, IM6): a double pendulum and a five-link chain in the
// engine against an independent reference of the constrained equations of motion (maximal
// coordinates, a KKT solve with Eigen at every evaluation, GSL rk8pd at 1e-12:
// constrained_chain_reference.hpp), itself checked against the double pendulum's Lagrange
// equations in minimal coordinates.
//
// Horizon. The motions are chaotic, so the engine can follow the reference only for a while.
// The reference measures how fast: a perturbation of 1e-8 rad of any one link's initial angle is
// followed, and A(t) is the largest factor by which one has grown up to t (centres in link
// lengths L, angles in rad). The engine's error is first order: about g h t / 2 in a position
// after time t at substep h, as semi-implicit Euler's under gravity (IM1, system_support.hpp's
// discrete_position), and the motion amplifies it as it amplifies any perturbation, to about
// eps(t, h) = A(t) g h t / (2 L). Once an error reaches a tenth of a link length (0.1 rad), its
// square, which the links' sines and cosines bring in, is no longer small against it: halving
// the step stops halving the error and the trajectories soon part. So the comparison ends where
// eps reaches 0.1 at the coarsest step (or at 3 s, to keep the test fast).
//
// Tolerance. Up to the horizon the error model is the bound: at each step the largest errors
// of the centres (over L) and of the angles stay below eps at the horizon; and halving the step
// shrinks the centres', the angles' and the energy's largest errors at least as first order
// does (ratio >= 1.8, as in the joint tests). The steps are 1/120, 1/240 and 1/480 s (4
// substeps): from 1/60 s, the default, to 1/120 s the chain's angle error does not yet halve
// (the step is not yet small enough for first order to dominate).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "system/constrained_chain_reference.hpp"
#include "system/system_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::system_test;

namespace {

constexpr double g = 9.81;
/// Steps per second compared (WorldDef's 4 substeps each). The reference is sampled on the
/// coarsest grid, where every run has a state.
constexpr int rates[] = {120, 240, 480};
constexpr double t_max = 3.0;            // s: the longest comparison (keeps the test fast)
constexpr double perturbation = 1e-8;    // rad: above rk8pd's 1e-12, below the engine's errors
constexpr double meaningful_error = 0.1; // link lengths or rad: see the horizon above

/// A link: a uniform box, pinned at the middle of its two short sides.
struct Box {
    double width, height, density;
};

/// The reference's links from the closed forms m = rho w h and I = m (w^2 + h^2) / 12 (DD14),
/// pins at (-w/2, 0) and (w/2, 0): at angle 0 a link points along +x from its parent pin.
ChainReference reference_of(const std::vector<Box>& boxes) {
    std::vector<ChainLink> links;
    for (const Box& b : boxes) {
        const double m = b.density * b.width * b.height;
        links.push_back(ChainLink{.mass = m,
                                  .inertia = m * (b.width * b.width + b.height * b.height) / 12.0,
                                  .parent_pin = {-b.width / 2.0, 0.0},
                                  .child_pin = {b.width / 2.0, 0.0}});
    }
    return ChainReference(std::move(links), {0.0, 0.0}, g);
}

/// The same chain in the engine: a static body without shapes at the pivot, box bodies placed
/// as the reference's initial state, each pinned to the previous one at its parent pin.
struct EngineChain {
    World world;
    std::vector<BodyId> links;
    EngineChain(const ChainReference& ref, const std::vector<Box>& boxes, const Eigen::VectorXd& y0)
        : world(WorldDef{.gravity = {0.0, -g}, .joint_hertz = 1e9}) {
        BodyDef ground_def;
        ground_def.type = BodyType::static_body;
        BodyId previous = world.create_body(ground_def);
        for (int i = 0; i < ref.size(); ++i) {
            BodyDef def;
            def.position = {y0[3 * i], y0[3 * i + 1]};
            def.angle = y0[3 * i + 2];
            const BodyId body = world.create_body(def);
            const Box& box = boxes[std::size_t(i)];
            world.create_shape(body,
                               box_shape(box.width, box.height, Material{box.density, 0.0, 0.0}));
            const Eigen::Vector2d pin = ref.parent_pin_position(y0, i);
            world.create_joint(
                RevoluteJointDef{.body_a = previous, .body_b = body, .anchor = {pin.x(), pin.y()}});
            links.push_back(body);
            previous = body;
        }
    }
    double energy() const { return world.kinetic_energy() + world.potential_energy(); }
};

/// The largest deviation of two states, centres in link lengths L and angles in rad.
double deviation(const Eigen::VectorXd& a, const Eigen::VectorXd& b, int links, double L) {
    double worst = 0.0;
    for (int i = 0; i < links; ++i) {
        const Eigen::Vector3d d = (a - b).segment<3>(3 * i);
        worst = std::max({worst, std::hypot(d[0], d[1]) / L, std::abs(d[2])});
    }
    return worst;
}

/// The comparison's horizon: the last sample at which eps(t, h_coarse) <= meaningful_error.
struct Horizon {
    int samples = 0;            // of the reference's grid
    double amplification = 0.0; // A at the horizon
    double seconds(double dt) const { return samples * dt; }
};

Horizon derive_horizon(const ChainReference& ref, const std::vector<double>& phi0,
                       const ChainTrajectory& nominal, double L, double h_coarse) {
    const int n = int(nominal.states.size()) - 1;
    std::vector<double> growth(std::size_t(n) + 1, 0.0);
    for (int j = 0; j < ref.size(); ++j) {
        std::vector<double> phi = phi0;
        phi[std::size_t(j)] += perturbation;
        const ChainTrajectory perturbed = ref.integrate(ref.state(phi), nominal.dt, n);
        for (int k = 0; k <= n; ++k)
            growth[std::size_t(k)] = std::max(
                growth[std::size_t(k)], deviation(perturbed.states[std::size_t(k)],
                                                  nominal.states[std::size_t(k)], ref.size(), L) /
                                            perturbation);
    }
    Horizon horizon;
    double A = 0.0;
    for (int k = 0; k <= n; ++k) {
        A = std::max(A, growth[std::size_t(k)]); // the largest growth so far
        if (A * g * h_coarse * (k * nominal.dt) / (2.0 * L) > meaningful_error)
            break;
        horizon.samples = k;
        horizon.amplification = A;
    }
    return horizon;
}

/// The engine's largest errors against the reference up to the horizon, at one rate.
struct Errors {
    double position = 0.0; // m, any link's centre
    double angle = 0.0;    // rad, any link's angle
    double energy = 0.0;   // J, the largest |E(t) - E(0)|
};

Errors engine_errors(const ChainReference& ref, const std::vector<Box>& boxes,
                     const ChainTrajectory& nominal, int samples, int rate) {
    EngineChain e(ref, boxes, nominal.states[0]);
    for (int i = 0; i < ref.size(); ++i) { // the engine's mass properties are the closed forms
        BOOST_TEST_REQUIRE(e.world.mass(e.links[std::size_t(i)]) == ref.link(i).mass,
                           boost::test_tools::tolerance(1e-12));
        BOOST_TEST_REQUIRE(e.world.inertia(e.links[std::size_t(i)]) == ref.link(i).inertia,
                           boost::test_tools::tolerance(1e-12));
    }
    const int steps_per_sample = int(std::lround(rate * nominal.dt));
    const double e0 = e.energy();
    Errors out;
    for (int k = 1; k <= samples; ++k) {
        for (int s = 0; s < steps_per_sample; ++s) {
            e.world.step(1.0 / rate);
            // The reference has no contacts: links that are not neighbours must never touch.
            BOOST_TEST_REQUIRE(e.world.contacts().empty());
        }
        const Eigen::VectorXd& y = nominal.states[std::size_t(k)];
        for (int i = 0; i < ref.size(); ++i) {
            const BodyId b = e.links[std::size_t(i)];
            const Vec2d p = e.world.position(b);
            const double phi = unwrap(e.world.orientation(b), y[3 * i + 2]);
            out.position = std::max(out.position, std::hypot(p.x - y[3 * i], p.y - y[3 * i + 1]));
            out.angle = std::max(out.angle, std::abs(phi - y[3 * i + 2]));
        }
        out.energy = std::max(out.energy, std::abs(e.energy() - e0));
    }
    return out;
}

/// The reference released at rest at angles phi0, on the coarsest grid up to t_max.
ChainTrajectory reference_trajectory(const ChainReference& ref, const std::vector<double>& phi0) {
    const double dt = 1.0 / rates[0];
    return ref.integrate(ref.state(phi0), dt, int(std::lround(t_max / dt)));
}

/// Checks the reference's own errors, derives the horizon, runs the engine at every rate and
/// checks the tolerance of the file's comment. All links have the first one's length L.
void compare_with_reference(const std::string& name, const ChainReference& ref,
                            const std::vector<Box>& boxes, const std::vector<double>& phi0,
                            const ChainTrajectory& nominal) {
    const double L = boxes[0].width, dt = nominal.dt;
    const int substeps = WorldDef{}.substeps;
    double mgl = 0.0; // J: the energy scale, each link's weight times its length
    for (int i = 0; i < ref.size(); ++i)
        mgl += ref.link(i).mass * g * boxes[std::size_t(i)].width;

    // The reference's own errors: far below the engine's smallest (1e-3), or it is no oracle.
    BOOST_TEST(nominal.max_pin_gap <= 1e-9);
    BOOST_TEST(nominal.max_pin_speed <= 1e-9);
    BOOST_TEST(nominal.max_energy_drift <= 1e-9 * mgl);

    const Horizon horizon = derive_horizon(ref, phi0, nominal, L, 1.0 / (rates[0] * substeps));
    BOOST_TEST_REQUIRE(horizon.seconds(dt) >= 1.0); // shorter would not be a comparison
    BOOST_TEST_MESSAGE(name << ": reference pin gap " << nominal.max_pin_gap << " m, pin speed "
                            << nominal.max_pin_speed << " m/s, energy drift "
                            << nominal.max_energy_drift << " J over " << t_max << " s; horizon "
                            << horizon.seconds(dt) << " s (perturbations grown "
                            << horizon.amplification << "x)");

    std::vector<Errors> errors;
    for (const int rate : rates) {
        const Errors e = engine_errors(ref, boxes, nominal, horizon.samples, rate);
        const double h = 1.0 / (rate * substeps);
        const double eps = horizon.amplification * g * h * horizon.seconds(dt) / (2.0 * L);
        BOOST_TEST_MESSAGE(name << " at 1/" << rate << " s: max centre error " << e.position
                                << " m, angle error " << e.angle << " rad, energy drift "
                                << e.energy << " J (" << e.energy / mgl
                                << " m g L); bound eps = " << eps);
        BOOST_TEST_CONTEXT(name << " at 1/" << rate << " s") {
            BOOST_TEST(e.position / L <= eps);
            BOOST_TEST(e.angle <= eps);
        }
        errors.push_back(e);
    }
    for (std::size_t r = 0; r + 1 < errors.size(); ++r) {
        BOOST_TEST_CONTEXT(name << ": 1/" << rates[r] << " s against 1/" << rates[r + 1] << " s") {
            BOOST_TEST(errors[r].position / errors[r + 1].position >= 1.8);
            BOOST_TEST(errors[r].angle / errors[r + 1].angle >= 1.8);
            BOOST_TEST(errors[r].energy / errors[r + 1].energy >= 1.8);
        }
    }
}

/// The double pendulum's Lagrange equations in minimal coordinates (the links' angles), for
/// links pinned at their ends: l1 the first link's pin distance, c_i a centre's distance from
/// its parent pin.
struct MinimalDoublePendulum {
    double m1, I1, l1, c1, m2, I2, c2;
};

int minimal_ode(double, const double y[], double dydt[], void* params) {
    const auto& p = *static_cast<const MinimalDoublePendulum*>(params);
    const double s = std::sin(y[0] - y[1]), c = std::cos(y[0] - y[1]), b = p.m2 * p.l1 * p.c2;
    // [a11 b c; b c a22] [phi1''; phi2''] = [r1; r2] (T and V written out, then Lagrange).
    const double a11 = p.I1 + p.m1 * p.c1 * p.c1 + p.m2 * p.l1 * p.l1,
                 a22 = p.I2 + p.m2 * p.c2 * p.c2;
    const double r1 = -b * s * y[3] * y[3] - (p.m1 * p.c1 + p.m2 * p.l1) * g * std::cos(y[0]);
    const double r2 = b * s * y[2] * y[2] - p.m2 * p.c2 * g * std::cos(y[1]);
    const double det = a11 * a22 - b * c * b * c;
    dydt[0] = y[2];
    dydt[1] = y[3];
    dydt[2] = (r1 * a22 - b * c * r2) / det;
    dydt[3] = (a11 * r2 - b * c * r1) / det;
    return GSL_SUCCESS;
}

/// The largest difference of the links' angles between the reference's trajectory and the
/// minimal-coordinates equations integrated from the same state by GSL rk8pd at 1e-12.
double minimal_coordinates_deviation(const ChainReference& ref, const std::vector<Box>& boxes,
                                     const ChainTrajectory& maximal) {
    MinimalDoublePendulum p{.m1 = ref.link(0).mass,
                            .I1 = ref.link(0).inertia,
                            .l1 = boxes[0].width,
                            .c1 = boxes[0].width / 2.0,
                            .m2 = ref.link(1).mass,
                            .I2 = ref.link(1).inertia,
                            .c2 = boxes[1].width / 2.0};
    gsl_odeiv2_system sys{minimal_ode, nullptr, 4, &p};
    gsl_odeiv2_driver* driver =
        gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, maximal.dt / 16.0, 1e-12, 1e-12);
    const Eigen::VectorXd& y0 = maximal.states[0];
    double y[4] = {y0[2], y0[5], y0[8], y0[11]}, t = 0.0, worst = 0.0;
    for (std::size_t k = 1; k < maximal.states.size(); ++k) {
        BOOST_TEST_REQUIRE(gsl_odeiv2_driver_apply(driver, &t, double(k) * maximal.dt, y) ==
                           GSL_SUCCESS);
        const Eigen::VectorXd& q = maximal.states[k];
        worst = std::max({worst, std::abs(q[2] - y[0]), std::abs(q[5] - y[1])});
    }
    gsl_odeiv2_driver_free(driver);
    return worst;
}

const std::vector<Box> double_pendulum = {{1.0, 0.1, 1.0}, {1.0, 0.1, 1.0}};
// Released with both links 30 degrees above the horizontal (120 degrees from hanging).
const std::vector<double> double_pendulum_angles = {std::numbers::pi / 6.0, std::numbers::pi / 6.0};
// Five links of 0.5 m released straight, 45 degrees from hanging: the links are 0.05 m thick,
// and neighbours' neighbours never come near each other before the horizon (checked).
const std::vector<Box> five_links(5, Box{0.5, 0.05, 1.0});
const std::vector<double> five_link_angles(5, -std::numbers::pi / 4.0);

} // namespace

BOOST_AUTO_TEST_SUITE(chain_reference)

// Oracle: the constrained equations of motion of two pinned boxes (m = rho w h, I = m (w^2 +
// h^2) / 12), KKT-solved with Eigen and integrated by GSL rk8pd at 1e-12, up to the horizon
// derived from the reference's own perturbation growth (file comment); first-order convergence
// of the centres, angles and energy at 1/120, 1/240 and 1/480 s. The reference is first checked
// against the Lagrange equations in minimal coordinates (written out in the test, sharing
// nothing with the KKT solve): the angles agree to 1e-9 rad over 3 s, six orders below the
// engine's errors.
BOOST_AUTO_TEST_CASE(double_pendulum_follows_the_reference,
                     *utf::label("DD19") * utf::label("IM6") * utf::label("LC3")) {
    const ChainReference ref = reference_of(double_pendulum);
    const ChainTrajectory nominal = reference_trajectory(ref, double_pendulum_angles);
    const double minimal = minimal_coordinates_deviation(ref, double_pendulum, nominal);
    BOOST_TEST_MESSAGE("double pendulum: reference against minimal coordinates "
                       << minimal << " rad over " << t_max << " s");
    BOOST_TEST(minimal <= 1e-9);
    compare_with_reference("double pendulum", ref, double_pendulum, double_pendulum_angles,
                           nominal);
}

// Oracle: as double_pendulum_follows_the_reference, for a chain of five pinned boxes released
// at 45 degrees.
BOOST_AUTO_TEST_CASE(five_link_chain_follows_the_reference,
                     *utf::label("DD19") * utf::label("IM6") * utf::label("LC3")) {
    const ChainReference ref = reference_of(five_links);
    compare_with_reference("five-link chain", ref, five_links, five_link_angles,
                           reference_trajectory(ref, five_link_angles));
}

BOOST_AUTO_TEST_SUITE_END()
