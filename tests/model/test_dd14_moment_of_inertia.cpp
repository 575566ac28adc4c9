// DD14 (moment of inertia I = sum m_i r_i^2), checked by hand, against textbook formulas, and
// against exact particle sums: midpoint grids, rings and subdivided triangles whose deviation
// from the continuum value is known in closed form, plus the parallel-axis theorem checked
// against direct particle sums.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "tamias2d/model/dd14_moment_of_inertia.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd14 = tamias2d::model::dd14;

namespace {
Vec2<Length> L2(double x, double y) {
    return vec_from_values<Length>(x, y);
}
double I_of(const std::vector<dd14::Particle>& ps) {
    return dd14::moment_of_inertia(ps).value();
}
} // namespace

BOOST_AUTO_TEST_SUITE(dd14_moment_of_inertia)

// Oracle: hand derivation. 1 kg at 2 m and 3 kg at 1 m: I = 1 x 4 + 3 x 1 = 7 kg m^2; no
// particles: 0; the unit carries rad^-2 (per-radian convention, docs/units.md).
BOOST_AUTO_TEST_CASE(particle_sum_hand_value, *utf::label("DD14")) {
    BOOST_TEST(I_of({{1.0 * kilogram, 2.0 * metre}, {3.0 * kilogram, 1.0 * metre}}) == 7.0);
    BOOST_TEST(I_of({}) == 0.0);
    const MomentOfInertia I = dd14::moment_of_inertia(std::vector<dd14::Particle>{});
    BOOST_TEST((I == 0.0 * kilogram * metre * metre / (radian * radian)));
}

// Oracle: textbook formulas. Solid rectangle about its centroid m (w^2 + h^2) / 12: 3 kg,
// 2 m x 4 m -> 5 kg m^2; square of side a: m a^2 / 6. Solid disc m R^2 / 2: 2 kg, 3 m -> 9.
BOOST_AUTO_TEST_CASE(textbook_values, *utf::label("DD14")) {
    BOOST_TEST(dd14::rectangle(3.0 * kilogram, 2.0 * metre, 4.0 * metre).value() == 5.0,
               tt::tolerance(1e-15));
    BOOST_TEST(dd14::rectangle(6.0 * kilogram, 0.5 * metre, 0.5 * metre).value() == 0.25,
               tt::tolerance(1e-15));
    BOOST_TEST(dd14::disc(2.0 * kilogram, 3.0 * metre).value() == 9.0, tt::tolerance(1e-15));
}

// Oracle: DD14's particle form on a fine midpoint grid, with the midpoint rule's exact error.
// N x M equal particles at the cell centres of a w x h rectangle: sum over cells of
// x_i^2 / N = w^2 / 12 (1 - 1 / N^2) exactly (each cell misses its own width^2 / 12), so
// I_grid = m / 12 (w^2 (1 - 1/N^2) + h^2 (1 - 1/M^2)) and the continuum value is
// I_grid + m / 12 (w^2 / N^2 + h^2 / M^2). Round-off: 2000 positive terms, <= 2000 eps
// relative = 4.4e-13, so 1e-12.
BOOST_AUTO_TEST_CASE(rectangle_vs_particle_grid, *utf::label("DD14")) {
    const double m = 56.2, w = 1.3, h = 0.7;
    constexpr int N = 50, M = 40;
    std::vector<dd14::Particle> ps;
    for (int i = 0; i < N; ++i)
        for (int k = 0; k < M; ++k) {
            const double x = (i + 0.5) * w / N - w / 2, y = (k + 0.5) * h / M - h / 2;
            ps.push_back({(m / (N * M)) * kilogram, std::hypot(x, y) * metre});
        }
    const double grid = I_of(ps);
    BOOST_TEST(grid == m / 12 * (w * w * (1 - 1.0 / (N * N)) + h * h * (1 - 1.0 / (M * M))),
               tt::tolerance(1e-12));
    const double rect = dd14::rectangle(m * kilogram, w * metre, h * metre).value();
    BOOST_TEST(rect == grid + m / 12 * (w * w / (N * N) + h * h / (M * M)), tt::tolerance(1e-12));
}

// Oracle: DD14's particle form on rings, with the exact error. n rings of width d = R / n;
// ring i (radii i d, (i + 1) d) has mass m ((i + 1)^2 - i^2) / n^2 and, as one particle at its
// mid radius, misses exactly m_i d^2 / 4 of its annulus value m_i (r_in^2 + r_out^2) / 2, so the
// particle sum is m R^2 / 2 - m d^2 / 4. 1000 positive terms: 1e-12 relative.
BOOST_AUTO_TEST_CASE(disc_vs_particle_rings, *utf::label("DD14")) {
    const double m = 2.5, R = 0.8;
    constexpr int n = 1000;
    const double d = R / n;
    std::vector<dd14::Particle> ps;
    for (int i = 0; i < n; ++i)
        ps.push_back({m * (2.0 * i + 1.0) / (n * n) * kilogram, (i + 0.5) * d * metre});
    const double disc = dd14::disc(m * kilogram, R * metre).value();
    BOOST_TEST(I_of(ps) == m * R * R / 2 - m * d * d / 4, tt::tolerance(1e-12));
    BOOST_TEST(disc == I_of(ps) + m * d * d / 4, tt::tolerance(1e-12));
}

// Oracle: textbook formulas for triangles. Right triangle with legs a = 3, b = 4 (m = 6 kg)
// about the right-angle vertex: m (a^2 + b^2) / 6 = 25 kg m^2. Equilateral triangle of side
// s = 2 m (m = 3 kg) about a vertex: I_cm + m (s / sqrt 3)^2 = m s^2 / 12 + m s^2 / 3 =
// 5 m s^2 / 12 = 5 kg m^2.
BOOST_AUTO_TEST_CASE(triangle_textbook_values, *utf::label("DD14")) {
    BOOST_TEST(dd14::triangle_about_vertex(6.0 * kilogram, L2(3, 0), L2(0, 4)).value() == 25.0,
               tt::tolerance(1e-15));
    BOOST_TEST(
        dd14::triangle_about_vertex(3.0 * kilogram, L2(2, 0), L2(1, std::sqrt(3.0))).value() == 5.0,
        tt::tolerance(1e-15));
}

// Oracle: DD14's particle form on a subdivided triangle, with the exact error. Cutting the
// triangle (0, a, b) into n^2 congruent sub-triangles (each a scaled copy or its point
// reflection, mass m / n^2, size 1 / n) and placing each mass at its centroid misses
// sum I_cm,k = n^2 (m / n^2)(1 / n^2) I_cm / m = I_cm / n^2, with I_cm = I_O - m |c|^2
// (parallel axis, c = (a + b) / 3). Hence I_O = (n^2 S - m |c|^2) / (n^2 - 1) for the particle
// sum S. n = 20: 400 terms, 1e-12 relative.
BOOST_AUTO_TEST_CASE(triangle_vs_subdivided_particles, *utf::label("DD14")) {
    const double m = 1.7, a[2] = {3.0, 0.5}, b[2] = {1.0, 2.5};
    constexpr int n = 20;
    std::vector<dd14::Particle> ps;
    const Mass piece = m / (n * n) * kilogram;
    const auto at = [&](double i, double k) {
        return std::hypot((i * a[0] + k * b[0]) / n, (i * a[1] + k * b[1]) / n) * metre;
    };
    for (int i = 0; i < n; ++i)
        for (int k = 0; i + k < n; ++k) {
            ps.push_back({piece, at(i + 1.0 / 3, k + 1.0 / 3)});
            if (i + k < n - 1)
                ps.push_back({piece, at(i + 2.0 / 3, k + 2.0 / 3)});
        }
    BOOST_TEST_REQUIRE(ps.size() == static_cast<std::size_t>(n * n));
    const double c2 = ((a[0] + b[0]) * (a[0] + b[0]) + (a[1] + b[1]) * (a[1] + b[1])) / 9.0;
    const double expected = (n * n * I_of(ps) - m * c2) / (n * n - 1);
    const double I =
        dd14::triangle_about_vertex(m * kilogram, L2(a[0], a[1]), L2(b[0], b[1])).value();
    BOOST_TEST(I == expected, tt::tolerance(1e-12));
}

// Oracle: additivity of DD14's sum over a body's parts. A w x h rectangle centred on the origin
// is a fan of four triangles from the centre, each of area w h / 4 and so mass m / 4; their
// moments about the centre add up to m (w^2 + h^2) / 12.
BOOST_AUTO_TEST_CASE(rectangle_as_triangle_fan, *utf::label("DD14")) {
    const double m = 4.4, w = 2.2, h = 0.9;
    const Vec2<Length> c[4] = {L2(w / 2, -h / 2), L2(w / 2, h / 2), L2(-w / 2, h / 2),
                               L2(-w / 2, -h / 2)};
    double sum = 0.0;
    for (int i = 0; i < 4; ++i)
        sum += dd14::triangle_about_vertex(m / 4 * kilogram, c[i], c[(i + 1) % 4]).value();
    BOOST_TEST(sum == m * (w * w + h * h) / 12, tt::tolerance(1e-14));
    BOOST_TEST(sum == dd14::rectangle(m * kilogram, w * metre, h * metre).value(),
               tt::tolerance(1e-14));
}

// Oracle: direct particle sums. For five particles, I about their centre of mass c and about a
// point Q (both summed directly from distances) satisfy the parallel-axis theorem
// I_Q = I_c + M |Q - c|^2; and the textbook rectangle about a corner is m (w^2 + h^2) / 3.
BOOST_AUTO_TEST_CASE(parallel_axis_vs_direct_sums, *utf::label("DD14")) {
    const double ms[5] = {1.3, 0.4, 2.2, 0.9, 3.1};
    const double px[5] = {0.2, -2.0, 1.5, 0.1, -0.6}, py[5] = {1.1, 0.7, -0.3, 0.1, -1.9};
    double M = 0, cx = 0, cy = 0;
    for (int i = 0; i < 5; ++i) {
        M += ms[i];
        cx += ms[i] * px[i];
        cy += ms[i] * py[i];
    }
    cx /= M;
    cy /= M;
    const double qx = 4.0, qy = -2.5;
    std::vector<dd14::Particle> about_c, about_q;
    for (int i = 0; i < 5; ++i) {
        about_c.push_back({ms[i] * kilogram, std::hypot(px[i] - cx, py[i] - cy) * metre});
        about_q.push_back({ms[i] * kilogram, std::hypot(px[i] - qx, py[i] - qy) * metre});
    }
    const MomentOfInertia Ic = dd14::moment_of_inertia(about_c);
    const double Iq =
        dd14::parallel_axis(Ic, M * kilogram, std::hypot(qx - cx, qy - cy) * metre).value();
    BOOST_TEST(Iq == I_of(about_q), tt::tolerance(1e-13));
    const double w = 3.0, h = 1.0, m = 2.0;
    const MomentOfInertia corner =
        dd14::parallel_axis(dd14::rectangle(m * kilogram, w * metre, h * metre), m * kilogram,
                            std::hypot(w / 2, h / 2) * metre);
    BOOST_TEST(corner.value() == m * (w * w + h * h) / 3, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_SUITE_END()
