// IM7, the engine's soft-contact collision response, against IM3's closed form in the regime
// where IM7 states it reduces to IM3: an isolated frictionless one-point (vertex-edge) contact
// with no other load in the step of impact, over random masses, shapes, velocities, C_R and
// every soft parameter (substeps, stiffness, damping ratio) and with the contact found
// touching, overlapping or across a speculative gap the approach closes within the step.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <numbers>
#include <vector>

#include "properties/random_scenes.hpp"
#include "support/box_column.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using tamias2d::property_test::Rng;

namespace {

double cross2(Vec2d a, Vec2d b) {
    return a.x * b.y - a.y * b.x;
}

Vec2d rotated(Vec2d v, double phi) {
    return {std::cos(phi) * v.x - std::sin(phi) * v.y, std::sin(phi) * v.x + std::cos(phi) * v.y};
}

struct Tally {
    int compared = 0;
    int touching = 0, overlapping = 0, speculative = 0;
    double worst = 0.0; ///< largest error over the velocity scale
};

} // namespace

BOOST_AUTO_TEST_SUITE(soft_contact)

namespace {
/// A box dropped into the ground (overlapping it by 5 cm) beside a pendulum, stepped 120 times
/// at dt = 1/64 s with 4 substeps (the cap n / (4 dt) is 64 Hz exactly); the final state hash.
std::uint64_t capped_scene(double contact_hertz, double joint_hertz) {
    const double dt = 1.0 / 64.0;
    World world(WorldDef{.contact_hertz = contact_hertz, .joint_hertz = joint_hertz});
    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    const BodyId ground = world.create_body(ground_def);
    world.create_shape(ground, box_shape(20.0, 1.0));
    BodyDef box_def;
    box_def.position = {0.0, 0.95};
    const BodyId box = world.create_body(box_def);
    world.create_shape(box, box_shape(1.0, 1.0));
    BodyDef bob_def;
    bob_def.position = {5.0, 3.0};
    const BodyId bob = world.create_body(bob_def);
    world.create_shape(bob, circle_shape(0.25));
    world.create_joint(RevoluteJointDef{.body_a = ground, .body_b = bob, .anchor = {4.0, 3.0}});
    for (int k = 0; k < 120; ++k)
        world.step(dt);
    return world.state_hash();
}
} // namespace

// Oracle: IM7's and IM6's frequency omega = 2 pi min(f, n / (4 dt)): a stiffness asked above
// the cap (64 Hz here) behaves exactly as the cap itself, bit for bit, for the contacts and for
// the joints; one asked below it is used as asked (a different state: the test is not vacuous).
BOOST_AUTO_TEST_CASE(stiffness_above_the_cap_is_the_cap, *utf::label("IM7") * utf::label("IM6")) {
    const std::uint64_t capped = capped_scene(64.0, 64.0);
    BOOST_TEST(capped_scene(1.0e4, 64.0) == capped);
    BOOST_TEST(capped_scene(64.0, 1.0e4) == capped);
    BOOST_TEST(capped_scene(30.0, 64.0) != capped);
    BOOST_TEST(capped_scene(64.0, 30.0) != capped);
}

// Oracle: IM3's closed form written here from the SRS text: j = -(1 + C_R) v_n / K with
// K = 1/m_A + 1/m_B + (r_AP x n)^2 / I_A + (r_BP x n)^2 / I_B (DD8; 1/m = 1/I = 0 for a static
// B), v_A' = v_A + j n / m_A, v_B' = v_B - j n / m_B, omega_A' = omega_A + (r_AP x j n) / I_A,
// omega_B' = omega_B - (r_BP x j n) / I_B, with v_n from DD9 and DD11 and the masses and
// inertias of the boxes from their sides and densities (m = rho w h, I = m (w^2 + h^2) / 12).
// A is a box turned 15-75 degrees whose lowest corner P meets the top face of box B (n = +y
// from B into A); no gravity, no friction, restitution threshold 0.
BOOST_AUTO_TEST_CASE(TC12_soft_contact_reduces_to_im3_for_an_isolated_vertex_edge_contact,
                     *utf::label("IM7") * utf::label("IM3")) {
    constexpr int samples = 600;
    constexpr double dt = 1.0 / 60.0;
    Tally t;
    for (int s = 0; s < samples; ++s) {
        Rng r(7000000 + std::uint64_t(s));
        const int kind = s % 3; // 0 touching, 1 overlapping, 2 speculative gap
        WorldDef def{.gravity = {0.0, 0.0}};
        def.substeps = std::array{1, 2, 4, 8}[std::size_t(r.integer(0, 3))];
        def.contact_hertz = r.uniform(10.0, 120.0);
        def.contact_damping_ratio = r.uniform(0.5, 20.0);
        const double c_r = r.coin(0.2) ? 0.0 : r.uniform(0.05, 1.0);
        World world(def);

        // B: a box with its top face at y = 0; static one time in three.
        const double wB = r.uniform(3.0, 6.0), hB = r.uniform(0.5, 1.5);
        const double rhoB = r.uniform(0.5, 5.0);
        const bool b_static = r.coin(1.0 / 3.0);
        BodyDef bd;
        bd.type = b_static ? BodyType::static_body : BodyType::dynamic;
        bd.position = {0.0, -0.5 * hB};
        if (!b_static) {
            bd.linear_velocity = {r.uniform(-0.5, 0.5), r.uniform(-0.5, 0.5)};
            bd.angular_velocity = r.uniform(-0.3, 0.3);
        }
        const BodyId b = world.create_body(bd);
        world.create_shape(b, box_shape(wB, hB, Material{rhoB, c_r, 0.0}));

        // A: its lowest corner P at x0 on B's face, at height gap (negative: overlap).
        const double wA = r.uniform(0.3, 1.5), hA = r.uniform(0.3, 1.5);
        const double rhoA = r.uniform(0.5, 5.0);
        const double phi = r.uniform(15.0, 75.0) * std::numbers::pi / 180.0;
        Vec2d lowest{0.0, 1e300};
        for (const Vec2d c : {Vec2d{-0.5 * wA, -0.5 * hA}, Vec2d{0.5 * wA, -0.5 * hA},
                              Vec2d{0.5 * wA, 0.5 * hA}, Vec2d{-0.5 * wA, 0.5 * hA}}) {
            const Vec2d w = rotated(c, phi);
            if (w.y < lowest.y)
                lowest = w;
        }
        const double x0 = r.uniform(-0.5 * wB + 0.6, 0.5 * wB - 0.6);
        BodyDef ad;
        ad.angle = phi;
        ad.linear_velocity = {r.uniform(-1.0, 1.0), r.uniform(-6.0, -1.0)};
        ad.angular_velocity = r.uniform(-3.0, 3.0);
        const double mA = rhoA * wA * hA, IA = mA * (wA * wA + hA * hA) / 12.0;
        const double mB = rhoB * wB * hB, IB = mB * (wB * wB + hB * hB) / 12.0;
        const double inv_mB = b_static ? 0.0 : 1.0 / mB, inv_IB = b_static ? 0.0 : 1.0 / IB;

        // DD9 + DD11 at P (the anchors' components along n do not change r x n).
        const Vec2d n{0.0, 1.0};
        const Vec2d rAP = lowest; // P - p_A
        const Vec2d rBP = Vec2d{x0, 0.0} - bd.position;
        const Vec2d vAP = ad.linear_velocity + ad.angular_velocity * Vec2d{-rAP.y, rAP.x};
        const Vec2d vBP = bd.linear_velocity + bd.angular_velocity * Vec2d{-rBP.y, rBP.x};
        const double vn = dot(vAP - vBP, n);
        if (vn > -0.2)
            continue; // not approaching fast enough to be an impact: drawn again by the count
        double gap = 0.0;
        if (kind == 1)
            gap = -r.uniform(1e-4, 0.01);
        else if (kind == 2) // a gap the approach closes well within the step
            gap = std::min(r.uniform(1e-4, 0.015), -0.5 * vn * dt);
        ad.position = Vec2d{x0, gap} - lowest;
        const BodyId a = world.create_body(ad);
        world.create_shape(a, box_shape(wA, hA, Material{rhoA, c_r, 0.0}));

        const double K = 1.0 / mA + inv_mB + std::pow(cross2(rAP, n), 2) / IA +
                         std::pow(cross2(rBP, n), 2) * inv_IB;
        const double j = -(1.0 + c_r) * vn / K;

        world.step(dt);

        const auto contacts = world.contacts();
        BOOST_TEST_REQUIRE(contacts.size() == 1u);
        BOOST_TEST_REQUIRE(contacts[0].point_count == 1); // A5: one vertex-edge point
        const double scale =
            std::max({std::abs(vn), std::abs(ad.angular_velocity) * wA, std::abs(j / mA), 1.0});
        const Vec2d vA = world.velocity(a), vB = world.velocity(b);
        const double errs[] = {
            vA.x - (ad.linear_velocity.x + j * n.x / mA),
            vA.y - (ad.linear_velocity.y + j * n.y / mA),
            vB.x - (bd.linear_velocity.x - j * n.x * inv_mB),
            vB.y - (bd.linear_velocity.y - j * n.y * inv_mB),
            (world.angular_velocity(a) - (ad.angular_velocity + cross2(rAP, j * n) / IA)) * wA,
            (world.angular_velocity(b) - (bd.angular_velocity - cross2(rBP, j * n) * inv_IB)) * wB,
            (contacts[0].points[0].normal_impulse - j) / mA};
        double worst = 0.0;
        for (const double e : errs)
            worst = std::max(worst, std::abs(e) / scale);
        BOOST_TEST(worst < 1e-9, "sample " << s << " (kind " << kind << ", C_R " << c_r
                                           << ", substeps " << def.substeps << ", "
                                           << def.contact_hertz << " Hz): error " << worst);
        t.worst = std::max(t.worst, worst);
        ++t.compared;
        (kind == 0 ? t.touching : kind == 1 ? t.overlapping : t.speculative) += 1;
    }
    BOOST_TEST_MESSAGE("IM7 vs IM3: " << t.compared << " impacts (" << t.touching << " touching, "
                                      << t.overlapping << " overlapping, " << t.speculative
                                      << " speculative), worst error " << t.worst
                                      << " of the velocity scale");
    // The draws keep most samples: a test that compared few would prove little.
    BOOST_TEST(t.compared >= samples / 2);
    BOOST_TEST(t.touching > 0);
    BOOST_TEST(t.overlapping > 0);
    BOOST_TEST(t.speculative > 0);
}

// Oracle: the rigid two-point contact written out here. A unit box (m = 1, I = 1/6) lands flat
// on static ground with v = (0, -1), omega = 0.3, C_R = 0, no friction, no gravity: its lower
// corners, at x = -0.5 and +0.5 from the centre, approach at -1 -+ 0.15 m/s. Both keep
// approaching while one alone is stopped, so both push: j1 + j2 = m * 1 and
// 0.5 (j2 - j1) = I (0 - 0.3) give j1 = 0.55, j2 = 0.45 > 0, and afterwards both corners are
// at rest on the ground: v = (0, 0), omega = 0 (IM7's relax with rigid targets, the IM3 limit
// C_R = 0 at two points). Point-by-point iterations only approach this; the step must reach it.
BOOST_AUTO_TEST_CASE(flat_landing_stops_both_corners_exactly, *utf::label("IM7")) {
    for (const int substeps : {1, 4}) {
        World world(WorldDef{.gravity = {0.0, 0.0}, .substeps = substeps});
        BodyDef gd;
        gd.type = BodyType::static_body;
        const BodyId ground = world.create_body(gd);
        world.create_shape(ground, box_shape(10.0, 1.0, Material{1.0, 0.0, 0.0}));
        BodyDef bd;
        bd.position = {0.3, 1.0}; // touching: bottom face on the ground's top face, y = 0.5
        bd.linear_velocity = {0.0, -1.0};
        bd.angular_velocity = 0.3;
        const BodyId box = world.create_body(bd);
        world.create_shape(box, box_shape(1.0, 1.0, Material{1.0, 0.0, 0.0}));
        BOOST_TEST_REQUIRE(world.mass(box) == 1.0);
        world.step(1.0 / 60.0);
        BOOST_TEST_REQUIRE(world.contacts().size() == 1u);
        BOOST_TEST(world.contacts()[0].point_count == 2);
        BOOST_TEST(std::abs(world.velocity(box).x) < 1e-12, "substeps " << substeps);
        BOOST_TEST(std::abs(world.velocity(box).y) < 1e-9, "substeps " << substeps);
        BOOST_TEST(std::abs(world.angular_velocity(box)) < 1e-9, "substeps " << substeps);
    }
}

// Oracle: IM7's warm start, "a point keeps its impulse when the same features touch again":
// a square box rests on the ground until its points carry impulses, then is turned a quarter
// turn in place and stopped. Other corners touch now, so every point starts from no impulse,
// exactly as for the same box placed there in a new world: one step later both boxes have the
// same velocities, to round-off. Put back in its first pose instead (the same corners), it
// keeps its impulses, and the step differs from a new world's by far more.
BOOST_AUTO_TEST_CASE(warm_start_follows_the_touching_features, *utf::label("IM7")) {
    const auto add_ground = [](World& world) {
        BodyDef gd;
        gd.type = BodyType::static_body;
        const BodyId ground = world.create_body(gd);
        world.create_shape(ground, box_shape(10.0, 1.0, Material{1.0, 0.0, 0.6}));
    };
    const auto add_box = [](World& world, Vec2d p, double angle) {
        BodyDef bd;
        bd.position = p;
        bd.angle = angle;
        const BodyId box = world.create_body(bd);
        world.create_shape(box, box_shape(1.0, 1.0, Material{1.0, 0.0, 0.6}));
        return box;
    };
    for (const double turn : {std::numbers::pi / 2.0, 0.0}) {
        World settled(WorldDef{.gravity = {0.0, -10.0}});
        add_ground(settled);
        const BodyId box = add_box(settled, {0.0, 1.0}, 0.0);
        for (int k = 0; k < 30; ++k)
            settled.step(1.0 / 60.0);
        BOOST_TEST_REQUIRE(settled.contacts().size() == 1u);
        BOOST_TEST_REQUIRE(settled.contacts()[0].points[0].normal_impulse > 0.0);
        const Vec2d p = settled.position(box);
        settled.set_transform(box, p, turn);
        settled.set_velocity(box, {0.0, 0.0});
        settled.set_angular_velocity(box, 0.0);

        World fresh(WorldDef{.gravity = {0.0, -10.0}});
        add_ground(fresh);
        const BodyId twin = add_box(fresh, p, turn);
        settled.step(1.0 / 60.0);
        fresh.step(1.0 / 60.0);
        const double gap =
            std::max({std::abs(settled.velocity(box).x - fresh.velocity(twin).x),
                      std::abs(settled.velocity(box).y - fresh.velocity(twin).y),
                      std::abs(settled.angular_velocity(box) - fresh.angular_velocity(twin))});
        // Not bit for bit: the manifold's reference face may come from either shape (a cached
        // separating axis), which moves its points by up to the overlap, 1.6e-4 m, and the
        // velocities by a few 1e-9. A carried impulse of the box's weight, 0.08 N s per
        // point, moves them by about 4e-4 m/s: the bound lies between, 1e-7.
        if (turn != 0.0)
            BOOST_TEST(gap < 1e-7);
        else
            BOOST_TEST(gap > 1e-6);
        BOOST_TEST_MESSAGE("turn " << turn << ": largest velocity difference " << gap);
    }
}

// Oracle: GD1 and T2. Thirty discs of different masses thrown together in empty space, with
// friction and restitution: every contact impulse acts equally and oppositely on its two
// bodies, so the total linear momentum stays what it was, to rounding, through a crowd of
// simultaneous contacts (the solver's packs of manifolds that share no body).
BOOST_AUTO_TEST_CASE(a_crowd_of_contacts_conserves_linear_momentum,
                     *utf::label("IM7") * utf::label("GD1")) {
    World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false});
    double scale = 0.0;
    for (int i = 0; i < 30; ++i) {
        BodyDef bd;
        const double phi = 2.0 * std::numbers::pi * i / 30.0, r = 2.0 + 0.15 * (i % 4);
        bd.position = {r * std::cos(phi), r * std::sin(phi)};
        bd.linear_velocity = {-1.5 * std::cos(phi) + 0.1 * (i % 3), -1.5 * std::sin(phi)};
        bd.angular_velocity = 0.2 * (i % 5) - 0.4;
        const BodyId b = world.create_body(bd);
        const Material mat{1.0 + 0.5 * (i % 3), 0.3, 0.4};
        if (i % 2 == 0)
            world.create_shape(b, circle_shape(0.3, mat));
        else
            world.create_shape(b, box_shape(0.5, 0.4, mat));
        scale += world.mass(b) * 1.5;
    }
    const Vec2d p0 = world.linear_momentum();
    std::size_t most_contacts = 0;
    for (int k = 0; k < 120; ++k) {
        world.step(1.0 / 60.0);
        most_contacts = std::max(most_contacts, world.contacts().size());
        const Vec2d p = world.linear_momentum();
        BOOST_TEST_REQUIRE(std::abs(p.x - p0.x) < 1e-12 * scale, "step " << k);
        BOOST_TEST_REQUIRE(std::abs(p.y - p0.y) < 1e-12 * scale, "step " << k);
    }
    BOOST_TEST(most_contacts >= 20u); // a crowd, not a few pairs
}

namespace {
/// A column of `layers` unit boxes (support/box_column.hpp: 1 kg each, friction 0.6, C_R = 0,
/// on a static ground whose top face is y = 0) in a world with the given linear slop and every
/// manifold computed afresh (each separation is then the shapes' own overlap), stepped 20 s at
/// 60 Hz (sleeping off, the default): each box's centre height, the lowest first.
std::vector<double> resting_heights(int layers, double slop) {
    WorldDef def;
    def.linear_slop = slop;
    def.manifold_reuse_distance = 0.0;
    World world(def);
    const std::vector<BodyId> boxes = test::build_box_column(world, layers);
    for (int k = 0; k < 1200; ++k)
        world.step(1.0 / 60.0);
    std::vector<double> y;
    for (const BodyId b : boxes)
        y.push_back(world.position(b).y);
    return y;
}
} // namespace

// Oracle: IM7's target, which pushes an overlap out only beyond the slop (the push depends on
// s + slop alone), and WorldDef::linear_slop's statement that any slop lets every layer of a
// stack sink by that much. At rest a contact's overlap is the slop plus the overlap that
// balances its load without slop, which the slop does not change; so a box in layer i (1 at
// the bottom) rests i slops lower than in a twin world without slop. Within 1e-4 of the slop:
// the settled twins differ from the exact shift by at most 2e-8 m (measured; the stacks stand
// still from 20 s on), a world that ignores the setting by the whole slop. Friction keeps the
// stack upright: without it a stack in the band, which has no positional stiffness, tips.
BOOST_AUTO_TEST_CASE(every_layer_of_a_resting_stack_sinks_by_the_slop, *utf::label("IM7")) {
    const double slop = 0.01;
    for (const int layers : {1, 3}) {
        const std::vector<double> rigid = resting_heights(layers, 0.0);
        const std::vector<double> sloppy = resting_heights(layers, slop);
        for (int i = 0; i < layers; ++i) {
            const double sink = rigid[i] - sloppy[i];
            BOOST_TEST_MESSAGE("layers " << layers << ", box " << i + 1 << ": sinks "
                                         << std::setprecision(12) << sink);
            BOOST_TEST(std::abs(sink - (i + 1) * slop) < 1e-4 * slop,
                       "layers " << layers << ", box " << i + 1 << ": sinks " << sink);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
