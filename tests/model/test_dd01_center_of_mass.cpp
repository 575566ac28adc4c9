// DD1 (centre of mass p_CM = sum m_i p_i / M), checked by hand, by symmetry, and against the
// exact centroid of a triangle subdivided into equal-mass pieces.
#include <boost/test/unit_test.hpp>

#include <vector>

#include "tamias2d/model/dd01_center_of_mass.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd01 = tamias2d::model::dd01;

namespace {
Vec2<Length> L2(double x, double y) {
    return vec_from_values<Length>(x, y);
}
} // namespace

BOOST_AUTO_TEST_SUITE(dd01_center_of_mass)

// Oracle: hand derivation. 1 kg at (0, 0) and 3 kg at (4, 0): p_CM = (3 x 4 / 4, 0) = (3, 0) m;
// adding 4 kg at (0, 2) gives ((12) / 8, 8 / 8) = (1.5, 1) m.
BOOST_AUTO_TEST_CASE(hand_values, *utf::label("DD1")) {
    const dd01::PointMass two[] = {{1.0 * kilogram, L2(0, 0)}, {3.0 * kilogram, L2(4, 0)}};
    const Vec2<Length> c2 = dd01::center_of_mass(two);
    BOOST_TEST(c2.x.value() == 3.0, tt::tolerance(1e-15));
    BOOST_TEST(c2.y.value() == 0.0);
    const dd01::PointMass three[] = {
        {1.0 * kilogram, L2(0, 0)}, {3.0 * kilogram, L2(4, 0)}, {4.0 * kilogram, L2(0, 2)}};
    const Vec2<Length> c3 = dd01::center_of_mass(three);
    BOOST_TEST(c3.x.value() == 1.5, tt::tolerance(1e-15));
    BOOST_TEST(c3.y.value() == 1.0, tt::tolerance(1e-15));
}

// Oracle: symmetry. Equal masses at the corners of a square centred at (2, -1) have their centre
// of mass at the square's centre; a single particle's centre of mass is the particle.
BOOST_AUTO_TEST_CASE(symmetric_and_single, *utf::label("DD1")) {
    const dd01::PointMass corners[] = {{0.5 * kilogram, L2(1, -2)},
                                       {0.5 * kilogram, L2(3, -2)},
                                       {0.5 * kilogram, L2(3, 0)},
                                       {0.5 * kilogram, L2(1, 0)}};
    const Vec2<Length> c = dd01::center_of_mass(corners);
    BOOST_TEST(c.x.value() == 2.0, tt::tolerance(1e-15));
    BOOST_TEST(c.y.value() == -1.0, tt::tolerance(1e-15));
    const dd01::PointMass one[] = {{7.0 * kilogram, L2(0.3, -0.7)}};
    const Vec2<Length> c1 = dd01::center_of_mass(one);
    BOOST_TEST(c1.x.value() == 0.3, tt::tolerance(1e-15));
    BOOST_TEST(c1.y.value() == -0.7, tt::tolerance(1e-15));
}

// Oracle: textbook identities. Translating every particle by d translates p_CM by d, scaling
// every mass by the same factor leaves p_CM unchanged, and (composition, as DD1's comment
// allows) the centre of mass of two groups, each replaced by its mass at its own centre, equals
// the centre of mass of all particles. Sums of 5 terms: 1e-14 relative.
BOOST_AUTO_TEST_CASE(translation_scaling_and_composition, *utf::label("DD1")) {
    const std::vector<dd01::PointMass> ps = {{1.3 * kilogram, L2(0.2, 1.1)},
                                             {0.4 * kilogram, L2(-2.0, 0.7)},
                                             {2.2 * kilogram, L2(1.5, -0.3)},
                                             {0.9 * kilogram, L2(0.1, 0.1)},
                                             {3.1 * kilogram, L2(-0.6, -1.9)}};
    const Vec2<Length> c = dd01::center_of_mass(ps);
    const Vec2<Length> d = L2(10.0, -4.0);
    std::vector<dd01::PointMass> moved = ps;
    std::vector<dd01::PointMass> heavier = ps;
    for (std::size_t i = 0; i < ps.size(); ++i) {
        moved[i].p += d;
        heavier[i].m = 3.0 * ps[i].m;
    }
    const Vec2<Length> cm = dd01::center_of_mass(moved);
    BOOST_TEST(cm.x.value() == c.x.value() + 10.0, tt::tolerance(1e-14));
    BOOST_TEST(cm.y.value() == c.y.value() - 4.0, tt::tolerance(1e-14));
    const Vec2<Length> ch = dd01::center_of_mass(heavier);
    BOOST_TEST(ch.x.value() == c.x.value(), tt::tolerance(1e-14));
    BOOST_TEST(ch.y.value() == c.y.value(), tt::tolerance(1e-14));
    const std::span<const dd01::PointMass> all(ps);
    const dd01::PointMass groups[] = {
        {ps[0].m + ps[1].m, dd01::center_of_mass(all.first(2))},
        {ps[2].m + ps[3].m + ps[4].m, dd01::center_of_mass(all.last(3))}};
    const Vec2<Length> cg = dd01::center_of_mass(groups);
    BOOST_TEST(cg.x.value() == c.x.value(), tt::tolerance(1e-14));
    BOOST_TEST(cg.y.value() == c.y.value(), tt::tolerance(1e-14));
}

// Oracle: textbook centroid of a uniform triangle, (a + b + c) / 3. Subdividing the triangle
// (0, 0), (3, 0), (0, 3) into n^2 = 400 congruent sub-triangles of equal mass and placing each
// mass at its sub-centroid gives exactly the centroid (1, 1) (the sub-centroids are a symmetric
// lattice); the particle sum of 400 terms rounds within 400 eps relative, so 1e-13.
BOOST_AUTO_TEST_CASE(subdivided_triangle_centroid, *utf::label("DD1")) {
    constexpr int n = 20;
    const double h = 3.0 / n;
    std::vector<dd01::PointMass> ps;
    const Mass piece = (6.0 / (n * n)) * kilogram;
    for (int i = 0; i < n; ++i)
        for (int k = 0; i + k < n; ++k) {
            // upright sub-triangle with corner (i h, k h) and legs h
            ps.push_back({piece, L2((i + 1.0 / 3.0) * h, (k + 1.0 / 3.0) * h)});
            if (i + k < n - 1) // inverted one: corners (i+1, k), (i, k+1), (i+1, k+1)
                ps.push_back({piece, L2((i + 2.0 / 3.0) * h, (k + 2.0 / 3.0) * h)});
        }
    BOOST_TEST_REQUIRE(ps.size() == static_cast<std::size_t>(n * n));
    const Vec2<Length> c = dd01::center_of_mass(ps);
    BOOST_TEST(c.x.value() == 1.0, tt::tolerance(1e-13));
    BOOST_TEST(c.y.value() == 1.0, tt::tolerance(1e-13));
}

BOOST_AUTO_TEST_SUITE_END()
