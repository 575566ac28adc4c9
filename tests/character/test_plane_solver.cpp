// solve_planes and clip_vector (DD43) against closed forms: one plane (the target projected on
// it, or kept), the corner of two planes (their intersection, with the pushes that express the
// target's offset from it), a slope (the target's part along it), a soft plane's limited push,
// clipped velocities; their input checks.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/plane_solver.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

Vec2d unit(double x, double y) {
    const double l = std::hypot(x, y);
    return {x / l, y / l};
}

double dist(Vec2d a, Vec2d b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}

} // namespace

BOOST_AUTO_TEST_SUITE(plane_solver_dd43)

// Oracle: the closest point to t of the half-plane n . d >= o is t itself when t lies in it,
// else its projection t + (o - n . t) n, the push being o - n . t. (Exact to rounding: one
// plane converges in one sweep.)
BOOST_AUTO_TEST_CASE(one_plane, *utf::label("DD43")) {
    const Vec2d n = unit(0.3, 1.0);
    const double o = 0.25;
    for (const Vec2d t : {Vec2d{1.0, -2.0}, Vec2d{-0.7, 0.1}, Vec2d{0.4, 3.0}}) {
        std::vector<CollisionPlane> planes{{.normal = n, .offset = o}};
        const PlaneSolverResult r = solve_planes(t, planes);
        const double violation = o - dot(n, t);
        const double push = violation > 0.0 ? violation : 0.0;
        const Vec2d expected = t + push * n;
        BOOST_TEST(r.converged);
        BOOST_TEST(dist(r.translation, expected) <= 1e-14);
        BOOST_TEST(std::abs(planes[0].push - push) <= 1e-14);
    }
}

// Oracle: closed form. In the corner of two planes, a target t = d* - (p1 n1 + p2 n2) with
// p1, p2 > 0 lies in the planes' normal cone below their intersection d*, so the closest allowed
// translation is d* itself (Cramer's rule on n1 . d = o1, n2 . d = o2) with pushes p1 and p2 (the
// KKT conditions). A floor and a wall leaning at 63 degrees, and a right-angle corner.
BOOST_AUTO_TEST_CASE(corner_of_two_planes, *utf::label("DD43")) {
    struct Case {
        Vec2d n1, n2;
        double o1, o2, p1, p2;
    };
    for (const Case& c : {Case{{0.0, 1.0}, unit(-1.0, 0.5), 0.1, 0.2, 1.0, 2.0},
                          Case{{0.0, 1.0}, {-1.0, 0.0}, -0.05, 0.3, 0.5, 0.25}}) {
        const double det = c.n1.x * c.n2.y - c.n1.y * c.n2.x;
        const Vec2d corner{(c.o1 * c.n2.y - c.n1.y * c.o2) / det,
                           (c.n1.x * c.o2 - c.o1 * c.n2.x) / det};
        const Vec2d t = corner - c.p1 * c.n1 - c.p2 * c.n2;
        std::vector<CollisionPlane> planes{{.normal = c.n1, .offset = c.o1},
                                           {.normal = c.n2, .offset = c.o2}};
        const PlaneSolverResult r = solve_planes(t, planes);
        BOOST_TEST(r.converged);
        // The sweep stops once its pushes change by less than 1e-9 m in sum; the rate per
        // sweep is cos^2 of the normals' angle (0.2 here), so the remaining error is below
        // 1e-9 / (1 - 0.2).
        BOOST_TEST(dist(r.translation, corner) <= 2e-9);
        BOOST_TEST(std::abs(planes[0].push - c.p1) <= 2e-9);
        BOOST_TEST(std::abs(planes[1].push - c.p2) <= 2e-9);
    }
}

// Oracle: closed form. On a slope of angle alpha (normal n = (-sin a, cos a), through the
// origin), a target pressing into it keeps only its part along the slope's tangent
// tau = (cos a, sin a): d = (t . tau) tau. A character walking right at u with a drop of g (per
// step) goes up a 30 degree slope by (u cos a - g sin a) along tau.
BOOST_AUTO_TEST_CASE(slope, *utf::label("DD43")) {
    const double a = 30.0 * std::acos(-1.0) / 180.0;
    const Vec2d n{-std::sin(a), std::cos(a)};
    const Vec2d tau{std::cos(a), std::sin(a)};
    const Vec2d t{0.1, -0.02};
    std::vector<CollisionPlane> planes{{.normal = n, .offset = 0.0}};
    const PlaneSolverResult r = solve_planes(t, planes);
    const double along = 0.1 * std::cos(a) - 0.02 * std::sin(a);
    BOOST_TEST(dist(r.translation, along * tau) <= 1e-15);
    BOOST_TEST(std::abs(dot(n, r.translation)) <= 1e-15);
}

// Oracle: closed form. A soft plane pushes at most its limit L: a target that needs a push P > L is
// moved by L along the normal and stays inside by P - L.
BOOST_AUTO_TEST_CASE(soft_plane, *utf::label("DD43")) {
    const Vec2d n{0.0, 1.0};
    std::vector<CollisionPlane> planes{{.normal = n, .offset = 0.0, .push_limit = 0.3}};
    const PlaneSolverResult r = solve_planes({0.5, -1.0}, planes);
    BOOST_TEST(dist(r.translation, Vec2d{0.5, -0.7}) <= 1e-15);
    BOOST_TEST(planes[0].push == 0.3);
}

// Oracle: closed form. v' = v - min(0, v . n) n for each plane that pushed and clips: the part into
// the plane removed, a part away from it kept, a plane that did not push (or a soft one that does
// not clip) ignored. Against a floor and a wall at a right angle the velocity into the corner
// stops.
BOOST_AUTO_TEST_CASE(clipped_velocity, *utf::label("DD43")) {
    const CollisionPlane floor{.normal = {0.0, 1.0}, .offset = 0.0, .push = 0.1};
    const CollisionPlane wall{.normal = {-1.0, 0.0}, .offset = 0.0, .push = 0.2};
    const CollisionPlane idle{.normal = {-1.0, 0.0}, .offset = 0.0, .push = 0.0};
    const CollisionPlane soft{
        .normal = {-1.0, 0.0}, .offset = 0.0, .push = 0.2, .clip_velocity = false};
    const std::vector<CollisionPlane> f{floor};
    BOOST_TEST((clip_vector({2.0, -3.0}, f) == Vec2d{2.0, 0.0}));
    BOOST_TEST((clip_vector({2.0, 3.0}, f) == Vec2d{2.0, 3.0}));
    const std::vector<CollisionPlane> corner{floor, wall};
    BOOST_TEST((clip_vector({2.0, -3.0}, corner) == Vec2d{0.0, 0.0}));
    const std::vector<CollisionPlane> ignored{idle, soft};
    BOOST_TEST((clip_vector({2.0, -3.0}, ignored) == Vec2d{2.0, -3.0}));
    const Vec2d n = unit(-1.0, 2.0);
    const std::vector<CollisionPlane> slope{{.normal = n, .offset = 0.0, .push = 1.0}};
    const Vec2d v{3.0, -1.0};
    const Vec2d expected = v - dot(v, n) * n;
    BOOST_TEST(dist(clip_vector(v, slope), expected) <= 1e-15);
}

// Oracle: the input rules docs/user-guide.md states for solve_planes and clip_vector: a normal
// not of length 1, a negative push_limit, a target or vector not finite, a tolerance that is not
// positive and max_iterations below 1 are each refused with a ValidationError naming the field;
// with no plane the target itself is returned (plane_solver.hpp).
BOOST_AUTO_TEST_CASE(input_checks, *utf::label("reliability")) {
    const auto field_of = [](auto&& call) -> std::string {
        try {
            call();
        } catch (const ValidationError& e) {
            return e.field;
        }
        return "(none)";
    };
    std::vector<CollisionPlane> bad_normal{{.normal = {0.0, 2.0}}};
    BOOST_TEST(field_of([&] { solve_planes({}, bad_normal); }) == "planes[0].normal");
    std::vector<CollisionPlane> bad_limit{{.normal = {0.0, 1.0}}, {.normal = {1.0, 0.0}}};
    bad_limit[1].push_limit = -1.0;
    BOOST_TEST(field_of([&] { solve_planes({}, bad_limit); }) == "planes[1].push_limit");
    std::vector<CollisionPlane> ok{{.normal = {0.0, 1.0}}};
    const double nan = std::numeric_limits<double>::quiet_NaN();
    BOOST_TEST(field_of([&] { solve_planes({nan, 0.0}, ok); }) == "target.x");
    BOOST_TEST(field_of([&] { solve_planes({}, ok, 0.0); }) == "tolerance");
    BOOST_TEST(field_of([&] { solve_planes({}, ok, 1e-9, 0); }) == "max_iterations");
    BOOST_TEST(field_of([&] { clip_vector({nan, 0.0}, ok); }) == "vector.x");
    // No plane: the target itself.
    const PlaneSolverResult r = solve_planes({1.0, 2.0}, {});
    BOOST_TEST((r.translation == Vec2d{1.0, 2.0}));
}

BOOST_AUTO_TEST_SUITE_END()
