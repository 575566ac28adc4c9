// Capsule mass properties (DD30) against DD14's defining integral, evaluated numerically.
#include <boost/test/unit_test.hpp>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <numbers>

#include "tamias2d/geometry/mass_properties.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

struct Capsule2 {
    double L, r;
};

/// Half the capsule's height at abscissa x along its axis (centre at 0).
double half_height(const Capsule2& c, double x) {
    const double beyond = std::abs(x) - 0.5 * c.L;
    return beyond <= 0.0 ? c.r : std::sqrt(std::max(0.0, c.r * c.r - beyond * beyond));
}

/// Integrates f over [a, b] with GSL's adaptive QAGS (it takes the square-root ends).
template <class F> double integrate(F f, double a, double b) {
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
    gsl_function g;
    g.function = [](double x, void* p) { return (*static_cast<F*>(p))(x); };
    g.params = &f;
    double result = 0.0, error = 0.0;
    gsl_integration_qags(&g, a, b, 0.0, 1e-13, 1000, w, &result, &error);
    gsl_integration_workspace_free(w);
    return result;
}

/// Area and polar moment of area about the centre from their definitions: slices across
/// the axis, each of height 2h(x); integral of (x^2 + y^2) over a slice is 2 h x^2 + 2 h^3 / 3.
double area_by_quadrature(const Capsule2& c) {
    const double ends = 0.5 * c.L + c.r;
    // Three pieces: the kinks at +-L/2 are where the integrand stops being smooth.
    auto f = [&](double x) { return 2.0 * half_height(c, x); };
    return integrate(f, -ends, -0.5 * c.L) + integrate(f, -0.5 * c.L, 0.5 * c.L) +
           integrate(f, 0.5 * c.L, ends);
}

double polar_moment_by_quadrature(const Capsule2& c) {
    const double ends = 0.5 * c.L + c.r;
    auto f = [&](double x) {
        const double h = half_height(c, x);
        return 2.0 * h * x * x + 2.0 * h * h * h / 3.0;
    };
    return integrate(f, -ends, -0.5 * c.L) + integrate(f, -0.5 * c.L, 0.5 * c.L) +
           integrate(f, 0.5 * c.L, ends);
}

const Capsule2 cases[] = {{2.0, 0.5}, {0.1, 1.0}, {10.0, 0.05}, {1e-3, 0.3}, {1.0, 1.0}};

} // namespace

BOOST_AUTO_TEST_SUITE(capsule_mass)

// Oracle: DD14's definition I = integral of rho |x|^2 dA (and A = integral of dA), evaluated by
// GSL's adaptive quadrature over slices across the axis: no use of DD30's closed form.
BOOST_AUTO_TEST_CASE(matches_the_defining_integrals, *utf::label("DD30") * utf::label("DD14")) {
    gsl_set_error_handler_off();
    for (const Capsule2& c : cases) {
        const double rho = 2.5;
        const Capsule shape{{-0.5 * c.L, 0.0}, {0.5 * c.L, 0.0}, c.r};
        const MassData md = compute_mass(shape, rho);
        const double A = area_by_quadrature(c);
        const double J = rho * polar_moment_by_quadrature(c);
        BOOST_TEST_CONTEXT("L " << c.L << " r " << c.r) {
            BOOST_TEST(md.mass == rho * A, boost::test_tools::tolerance(1e-11));
            BOOST_TEST(md.inertia == J, boost::test_tools::tolerance(1e-11));
            BOOST_TEST(md.center.x == 0.0);
            BOOST_TEST(md.center.y == 0.0);
        }
    }
}

// Oracle: closed-form limits: a capsule of vanishing length is a disc (I = m r^2 / 2), and a long
// thin one a rod (I -> m L^2 / 12).
BOOST_AUTO_TEST_CASE(disc_and_rod_limits, *utf::label("DD30")) {
    const double r = 0.7;
    const MassData disc = compute_mass(Capsule{{0.0, 0.0}, {1e-9, 0.0}, r}, 1.0);
    BOOST_TEST(disc.inertia == 0.5 * disc.mass * r * r, boost::test_tools::tolerance(1e-8));
    const double L = 100.0;
    const MassData rod = compute_mass(Capsule{{-0.5 * L, 0.0}, {0.5 * L, 0.0}, 1e-4}, 1.0);
    BOOST_TEST(rod.inertia == rod.mass * L * L / 12.0, boost::test_tools::tolerance(1e-5));
}

// Oracle: the defining integrals (as above) and the parallel-axis theorem for a capsule away
// from the body origin and turned: a world body's mass, centre and inertia about its centre.
BOOST_AUTO_TEST_CASE(world_body_of_a_turned_offset_capsule,
                     *utf::label("DD30") * utf::label("DD1")) {
    gsl_set_error_handler_off();
    const Capsule2 c{3.0, 0.4};
    const double angle = 0.6, rho = 1.5;
    const Vec2d mid{2.0, -1.0}, axis{std::cos(angle), std::sin(angle)};
    World world;
    const BodyId body = world.create_body({});
    world.create_shape(body, capsule_shape(mid - (0.5 * c.L) * axis, mid + (0.5 * c.L) * axis, c.r,
                                           Material{rho, 0.0, 0.0}));
    BOOST_TEST(world.mass(body) == rho * area_by_quadrature(c),
               boost::test_tools::tolerance(1e-11));
    BOOST_TEST(world.inertia(body) == rho * polar_moment_by_quadrature(c),
               boost::test_tools::tolerance(1e-11));
    const Vec2d centre = world.state(body).position;
    BOOST_TEST(centre.x == mid.x, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(centre.y == mid.y, boost::test_tools::tolerance(1e-12));
}

// Oracle: a segment or a chain has no area: a body of one has the shapeless default mass (1 kg)
// and no rotational inertia, whatever the density given.
BOOST_AUTO_TEST_CASE(segments_add_no_mass) {
    World world;
    const BodyId body = world.create_body({});
    world.create_shape(body, segment_shape({0.0, 0.0}, {2.0, 0.0}, Material{5.0, 0.0, 0.0}));
    BOOST_TEST(world.mass(body) == 1.0);
    BOOST_TEST(world.inertia(body) == 0.0);
    const BodyId box = world.create_body({});
    world.create_shape(box, box_shape(1.0, 1.0));
    const Vec2d pts[] = {{-1.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}};
    world.create_chain(box, chain_shapes(pts, false));
    BOOST_TEST(world.mass(box) == 1.0); // the unit box alone
    BOOST_TEST(world.inertia(box) == 1.0 / 6.0, boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_SUITE_END()
