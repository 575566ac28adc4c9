// World::explode (DD38) against closed forms: a ring of equal discs around the blast each
// receives the same radial impulse of DD38's magnitude, the ring's momentum sums to zero and
// no disc turns; the falloff's linear fade; the per-body impulse; a box's exposed width;
// what the blast leaves alone; the strong guarantee.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double a = 0.25;      // m, the discs' radius
constexpr double density = 2.0; // kg m^-2
const double disc_mass = density * pi * a * a;

/// n discs of radius a at distance R from `centre`, evenly round, in a world without gravity.
std::vector<BodyId> ring(World& w, Vec2d centre, double R, int n, double phase = 0.0) {
    std::vector<BodyId> out;
    for (int k = 0; k < n; ++k) {
        const double t = phase + 2.0 * pi * k / n;
        BodyDef d;
        d.position = {centre.x + R * std::cos(t), centre.y + R * std::sin(t)};
        const BodyId b = w.create_body(d);
        w.create_shape(b, circle_shape(a, Material{.density = density}));
        out.push_back(b);
    }
    return out;
}

/// Every disc of the ring moves radially outward at `speed` (m s^-1) without turning, and the
/// ring's momentum sums to zero (by symmetry).
void check_ring(const World& w, const std::vector<BodyId>& discs, Vec2d centre, double speed) {
    Vec2d momentum{};
    for (const BodyId b : discs) {
        const Vec2d p = w.position(b);
        const double R = std::hypot(p.x - centre.x, p.y - centre.y);
        const Vec2d radial{(p.x - centre.x) / R, (p.y - centre.y) / R};
        const Vec2d v = w.velocity(b);
        BOOST_TEST(std::abs(v.x - speed * radial.x) <= 1e-12 * speed);
        BOOST_TEST(std::abs(v.y - speed * radial.y) <= 1e-12 * speed);
        BOOST_TEST(std::abs(w.angular_velocity(b)) <= 1e-12 * speed);
        momentum += w.mass(b) * v;
    }
    BOOST_TEST(std::hypot(momentum.x, momentum.y) <=
               1e-12 * disc_mass * speed * double(discs.size()));
}

World empty_world() {
    return World(WorldDef{.gravity = {0.0, 0.0}});
}

} // namespace

BOOST_AUTO_TEST_SUITE(explosion_dd38)

// Oracle: DD38 in closed form for a disc of radius a whose nearest point lies within the
// radius: width 2a, J = j_w 2a, radial, at the nearest point (on the line through the disc's
// centre: no torque); dv = J / m (DD10). Twelve discs at R = 3 m round a blast of radius 4 m,
// j_w = 2 N s m^-1: J = 1 N s each. A second ring at 6 m (beyond radius + falloff) keeps its
// state bit for bit.
BOOST_AUTO_TEST_CASE(ring_of_equal_discs, *utf::label("DD38")) {
    World w = empty_world();
    const Vec2d centre{1.5, -0.5};
    const std::vector<BodyId> inner = ring(w, centre, 3.0, 12);
    const std::vector<BodyId> outer = ring(w, centre, 6.0, 7, 0.3);
    std::vector<BodyState> outer_before;
    for (const BodyId b : outer)
        outer_before.push_back(w.state(b));
    const std::size_t moved =
        w.explode({.position = centre, .radius = 4.0, .falloff = 0.5, .impulse_per_length = 2.0});
    BOOST_TEST(moved == inner.size());
    check_ring(w, inner, centre, 2.0 * 2.0 * a / disc_mass);
    for (std::size_t k = 0; k < outer.size(); ++k) {
        const BodyState s = w.state(outer[k]);
        BOOST_TEST(s.velocity.x == outer_before[k].velocity.x);
        BOOST_TEST(s.velocity.y == outer_before[k].velocity.y);
        BOOST_TEST(s.angular_velocity == outer_before[k].angular_velocity);
    }
}

// Oracle: DD38's linear falloff, s = (r + f - d) / f for r < d < r + f: discs at R = 3 m
// (nearest point d = 2.75 m) round a blast of radius 2 m and falloff 2 m take
// s = 1.25 / 2 = 0.625 of the full J = j_w 2a; the per-body impulse j_b fades alike.
BOOST_AUTO_TEST_CASE(linear_falloff, *utf::label("DD38")) {
    World w = empty_world();
    const std::vector<BodyId> discs = ring(w, {}, 3.0, 8, 0.1);
    w.explode({.position = {},
               .radius = 2.0,
               .falloff = 2.0,
               .impulse_per_length = 4.0,
               .impulse_per_body = 0.5});
    check_ring(w, discs, {}, 0.625 * (4.0 * 2.0 * a + 0.5) / disc_mass);

    // At d = r + f exactly the strength is zero: nothing moves, nothing wakes.
    World edge = empty_world();
    const std::vector<BodyId> far = ring(edge, {}, 3.0, 4);
    const auto before = edge.state_hash();
    BOOST_TEST(
        edge.explode({.position = {}, .radius = 1.0, .falloff = 1.75, .impulse_per_length = 4.0}) ==
        0u);
    BOOST_TEST(edge.state_hash() == before);
}

// Oracle: DD38's width for a box face-on to the blast: a 1 m x 0.5 m box (long side along y)
// centred 3 m to the right of the blast shows its 1 m side, J = j_w x 1 m along +x; a box at
// 3 m along +y, turned by pi/2, shows its 1 m side too, J along +y. dv = J / m with
// m = rho w h (DD1), no turn (the nearest point lies on the box's axis of symmetry).
BOOST_AUTO_TEST_CASE(box_exposes_its_face, *utf::label("DD38")) {
    World w = empty_world();
    BodyDef d;
    d.position = {3.0, 0.0};
    const BodyId right = w.create_body(d);
    w.create_shape(right, box_shape(0.5, 1.0, Material{.density = density}));
    d.position = {0.0, 3.0};
    d.angle = pi / 2.0;
    const BodyId up = w.create_body(d);
    w.create_shape(up, box_shape(0.5, 1.0, Material{.density = density}));
    w.explode({.position = {}, .radius = 5.0, .impulse_per_length = 3.0});
    const double m = density * 0.5 * 1.0;
    BOOST_TEST(std::abs(w.velocity(right).x - 3.0 / m) <= 1e-12);
    BOOST_TEST(std::abs(w.velocity(right).y) <= 1e-12);
    BOOST_TEST(std::abs(w.velocity(up).x) <= 1e-12);
    BOOST_TEST(std::abs(w.velocity(up).y - 3.0 / m) <= 1e-12);
    BOOST_TEST(std::abs(w.angular_velocity(right)) <= 1e-12);
    BOOST_TEST(std::abs(w.angular_velocity(up)) <= 1e-12);
}

// Oracle: DD38's statement (only the shapes of dynamic bodies are pushed) and ExplosionDef's
// documented rules: static and kinematic bodies, sensors and shapes whose categories miss the
// mask are not pushed (their states unchanged bit for bit); a sleeping disc is woken and pushed
// as an awake one is, by DD38's closed form for a disc: 2 a j_w / m along the diagonal.
BOOST_AUTO_TEST_CASE(what_the_blast_leaves_alone, *utf::label("DD38")) {
    World w(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = true});
    const auto disc_at = [&](Vec2d p, BodyType type, bool awake, bool sensor,
                             std::uint32_t category) {
        BodyDef d;
        d.type = type;
        d.position = p;
        d.awake = awake;
        const BodyId b = w.create_body(d);
        ShapeDef s = circle_shape(a, Material{.density = density});
        s.is_sensor = sensor;
        s.filter.category_bits = category;
        w.create_shape(b, s);
        return b;
    };
    const BodyId fixed = disc_at({2.0, 0.0}, BodyType::static_body, true, false, 1);
    const BodyId kin = disc_at({-2.0, 0.0}, BodyType::kinematic, true, false, 1);
    const BodyId sensor = disc_at({0.0, 2.0}, BodyType::dynamic, true, true, 1);
    const BodyId masked = disc_at({0.0, -2.0}, BodyType::dynamic, true, false, 2);
    const BodyId asleep = disc_at({2.0, 2.0}, BodyType::dynamic, false, false, 1);
    BOOST_TEST_REQUIRE(!w.is_awake(asleep));
    const std::size_t moved =
        w.explode({.position = {}, .radius = 5.0, .impulse_per_length = 1.0, .mask_bits = 1});
    BOOST_TEST(moved == 1u);
    for (const BodyId b : {fixed, kin, sensor, masked}) {
        BOOST_TEST(w.velocity(b).x == 0.0);
        BOOST_TEST(w.velocity(b).y == 0.0);
    }
    BOOST_TEST(w.is_awake(asleep));
    const double speed = 1.0 * 2.0 * a / disc_mass;
    BOOST_TEST(std::abs(w.velocity(asleep).x - speed / std::sqrt(2.0)) <= 1e-12 * speed);
    BOOST_TEST(std::abs(w.velocity(asleep).y - speed / std::sqrt(2.0)) <= 1e-12 * speed);
}

// Oracle: the documented strong guarantee (state_hash before and after) and DD38's ranges
// (r, f >= 0, finite): each bad field is refused with a ValidationError naming it, and a blast that
// would push a very light body beyond the supported velocity (1e24 m s^-1) is refused whole, the
// heavier bodies it would also push untouched. A blast of zero impulse changes no bit.
BOOST_AUTO_TEST_CASE(bad_input_changes_nothing, *utf::label("DD38")) {
    World w = empty_world();
    ring(w, {}, 1.0, 3);
    BodyDef d;
    d.position = {0.0, -1.0};
    const BodyId light = w.create_body(d);
    w.create_shape(light, circle_shape(1e-6, Material{.density = 1e-12}));
    const auto before = w.state_hash();
    const double nan = std::nan("");
    const auto refused = [&](const ExplosionDef& e, const char* field) {
        try {
            w.explode(e);
            BOOST_ERROR("accepted a bad " << field);
        } catch (const ValidationError& err) {
            BOOST_TEST(err.field.find(field) == 0u, err.field << " names " << field);
        }
        BOOST_TEST(w.state_hash() == before);
    };
    refused({.radius = -1.0, .impulse_per_length = 1.0}, "explosion.radius");
    refused({.radius = nan, .impulse_per_length = 1.0}, "explosion.radius");
    refused({.falloff = -0.1, .impulse_per_length = 1.0}, "explosion.falloff");
    refused({.position = {nan, 0.0}, .impulse_per_length = 1.0}, "explosion.position");
    refused({.position = {2e12, 0.0}, .impulse_per_length = 1.0}, "explosion.position");
    refused({.impulse_per_length = 1e13}, "explosion.impulse_per_length");
    refused({.impulse_per_body = -nan}, "explosion.impulse_per_body");
    refused({.radius = 3.0, .impulse_per_body = 1e12}, "explosion: the velocity");
    BOOST_TEST(w.explode({.radius = 3.0}) == 0u);
    BOOST_TEST(w.state_hash() == before);
}

// Oracle: a second world given the same blast (state_hash, bitwise) on 1 to 4 workers, then
// stepped: the blast and the step after it do not depend on the worker count.
BOOST_AUTO_TEST_CASE(same_bits_on_any_worker_count, *utf::label("determinism")) {
    std::uint64_t first = 0;
    for (int workers = 1; workers <= 4; ++workers) {
        World w(WorldDef{.workers = workers});
        BodyDef g;
        g.type = BodyType::static_body;
        w.create_shape(w.create_body(g), box_shape(40.0, 1.0, {}, {0.0, -0.5}));
        for (int k = 0; k < 30; ++k) {
            BodyDef d;
            d.position = {-7.0 + 0.5 * k, 0.5 + (k % 3)};
            w.create_shape(w.create_body(d), box_shape(0.4, 0.4));
        }
        for (int k = 0; k < 30; ++k)
            w.step(1.0 / 60.0);
        w.explode({.position = {0.0, 0.0},
                   .radius = 3.0,
                   .falloff = 2.0,
                   .impulse_per_length = 2.0,
                   .impulse_per_body = 0.3});
        for (int k = 0; k < 30; ++k)
            w.step(1.0 / 60.0);
        if (workers == 1)
            first = w.state_hash();
        BOOST_TEST(w.state_hash() == first, "workers " << workers);
    }
}

BOOST_AUTO_TEST_SUITE_END()
