// Plain pins four at once (PinPacks, pin_packs.hpp) against the joint pass they stand for: the
// sequential Gauss-Seidel pass over the joints, each joint's warm start and iterations by its
// kind's own scalar code (joint_solver.cpp), in creation order where the streams are levelled,
// in the colours' order where they are coloured (chains). The packs, their levels and the
// joints solved alone between them must give that pass's bits exactly: the bodies' velocities
// and every joint's impulses. Random scenes mix plain pins with revolute joints that have a
// motor or limits (solved alone), put the static body 0 in some lanes, give each joint its own
// softness, and couple bodies as chains do (a joint on a body and the next) and at random, or
// as ropes only.
#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "tamias2d/dynamics/joints/joint_solver.hpp"
#include "tamias2d/dynamics/joints/pin_packs.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

struct Scene {
    std::vector<SolverBody> bodies;
    std::vector<Rot> rotations; ///< one per body, then one per immovable side
    std::vector<Joint> joints;
    std::vector<JointSim> sims; ///< creation order
};

/// `ropes`: every joint holds body k and k + 1 (k = 1, 2, ... in turn, one in ten on the
/// immovable body 0 instead), so that each stream is a chain: one joint a level.
Scene random_scene(std::uint32_t seed, std::uint32_t body_count, std::uint32_t joint_count,
                   bool ropes = false) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0), pos(0.5, 2.0), unit(0.0, 1.0);
    Scene s;
    s.bodies.resize(body_count);
    s.rotations.reserve(body_count + joint_count);
    s.rotations.push_back(Rot{});
    for (std::uint32_t k = 1; k < body_count; ++k) {
        SolverBody& b = s.bodies[k];
        b.v = {u(rng), u(rng)};
        b.w = u(rng);
        b.inv_m = pos(rng);
        b.inv_I = pos(rng);
        b.dp = {0.01 * u(rng), 0.01 * u(rng)};
        b.dq = 0.01 * u(rng);
        s.rotations.push_back(Rot::from_angle(3.0 * u(rng)));
    }
    std::uniform_int_distribution<std::uint32_t> body(1, body_count - 1);
    for (std::uint32_t i = 0; i < joint_count; ++i) {
        std::uint32_t a = unit(rng) < 0.1 ? 0 : body(rng);
        std::uint32_t b = body(rng);
        if (unit(rng) < 0.5 && a != 0 && a + 1 < body_count)
            b = a + 1; // a chain's next link
        if (a == b)
            b = a + 1 < body_count ? a + 1 : 1;
        if (ropes) {
            b = 1 + i % (body_count - 2);
            a = unit(rng) < 0.1 ? 0 : b + 1;
        }
        if (a == b)
            continue;
        Joint j;
        j.type = JointType::revolute;
        const double kind = unit(rng);
        j.enable_motor = kind > 0.85;
        j.enable_limit = kind > 0.7 && kind <= 0.85;
        j.motor_speed = u(rng);
        j.max_motor = pos(rng);
        j.lower_limit = -0.2;
        j.upper_limit = 0.3;
        JointSim sim;
        sim.solver_a = a;
        sim.solver_b = b;
        sim.joint = std::uint32_t(s.joints.size());
        sim.type = JointType::revolute;
        sim.motor = j.enable_motor;
        sim.limit = j.enable_limit;
        const auto rotation = [&](std::uint32_t k) {
            if (k != 0)
                return &s.rotations[k];
            s.rotations.push_back(Rot::from_angle(u(rng)));
            return &s.rotations.back();
        };
        sim.q_a = rotation(a);
        sim.q_b = rotation(b);
        sim.frame_a = {0.5 * u(rng), 0.5 * u(rng)};
        sim.frame_b = {0.5 * u(rng), 0.5 * u(rng)};
        sim.center_offset = {u(rng), u(rng)};
        sim.softness = {10.0 * pos(rng), 0.5 + 0.5 * unit(rng), 0.5 * unit(rng)};
        sim.step.linear_impulse = {0.1 * u(rng), 0.1 * u(rng)};
        // A pin that once had a motor or limits keeps their last impulses (warm started).
        sim.step.motor_impulse = unit(rng) < 0.2 ? 0.05 * u(rng) : 0.0;
        sim.step.lower_impulse = sim.limit ? 0.05 * unit(rng) : 0.0;
        sim.angle_a = u(rng);
        sim.angle_b = u(rng);
        s.joints.push_back(j);
        s.sims.push_back(sim);
    }
    return s;
}

constexpr double h = 1.0 / 240.0;

/// The oracle: rounds of the warm start, the soft iteration and the relax, each over the joints
/// one after another in `order` (their indices; empty: creation order).
void sequential(Scene& s, int rounds, const std::vector<std::uint32_t>& order = {}) {
    std::vector<JointSim*> sims;
    for (std::size_t k = 0; k < s.sims.size(); ++k)
        sims.push_back(&s.sims[order.empty() ? k : order[k]]);
    for (int r = 0; r < rounds; ++r) {
        for (JointSim* sim : sims)
            warm_start_joint(*sim, s.joints[sim->joint], s.bodies);
        for (JointSim* sim : sims)
            solve_joint(*sim, s.joints[sim->joint], s.bodies, h, true);
        for (JointSim* sim : sims)
            solve_joint(*sim, s.joints[sim->joint], s.bodies, h, false);
    }
}

/// The same rounds through PinPacks: the joints ordered into streams [bounds[i], bounds[i+1]),
/// the records in that order, each stream's runs in turn. Returns the packs made; `order`, if
/// given, receives the joints' order.
std::size_t packed(Scene& s, std::span<const std::uint32_t> bounds, int rounds,
                   std::vector<std::uint32_t>* order = nullptr) {
    memory::vector<SolvedJoint> solved;
    for (const JointSim& sim : s.sims)
        solved.push_back({sim.joint, sim.solver_a, sim.solver_b,
                          plain_pin(sim.type, sim.spring, sim.motor, sim.limit) ? 1u : 0u, 0, 0});
    PinPacks packs;
    packs.order(solved, bounds, s.bodies.size());
    // Ordering the same joints again keeps the order (the cached path).
    memory::vector<SolvedJoint> again;
    for (const JointSim& sim : s.sims)
        again.push_back({sim.joint, sim.solver_a, sim.solver_b,
                         plain_pin(sim.type, sim.spring, sim.motor, sim.limit) ? 1u : 0u, 0, 0});
    packs.order(again, bounds, s.bodies.size());
    BOOST_TEST_REQUIRE(
        std::memcmp(again.data(), solved.data(), solved.size() * sizeof(SolvedJoint)) == 0);
    std::vector<JointSim> records;
    for (const SolvedJoint& sj : solved) {
        records.push_back(s.sims[sj.joint]);
        if (order != nullptr)
            order->push_back(sj.joint);
    }
    // Each pack's lanes as the step solver fills them, from what each pin's record holds.
    for (std::size_t p = 0; p < packs.pack_count(); ++p) {
        for (int lane = 0; lane < wide_lanes; ++lane) {
            const JointSim& r = records[packs.first_record(p) + std::size_t(lane)];
            BOOST_TEST_REQUIRE(packs.in_pack(packs.first_record(p) + std::size_t(lane)));
            packs.fill(p, lane,
                       {r.solver_a, r.solver_b, r.q_a, r.q_b, r.frame_a, r.frame_b, r.center_offset,
                        r.step.linear_impulse,
                        reaction_angular_impulse(JointType::revolute, r.step), r.softness});
        }
    }
    for (int r = 0; r < rounds; ++r) {
        for (const bool warm : {true, false}) {
            for (const bool bias :
                 warm ? std::vector<bool>{false} : std::vector<bool>{true, false}) {
                for (std::uint32_t stream = 0; stream < packs.streams(); ++stream) {
                    for (const PinRun& run : packs.runs(stream)) {
                        if (run.packed) {
                            const std::uint32_t n = run.count / wide_lanes;
                            if (warm)
                                packs.warm_start(run.pack, n, s.bodies.data());
                            else
                                packs.solve(run.pack, n, s.bodies.data(), bias);
                            continue;
                        }
                        for (std::uint32_t k = run.first; k < run.first + run.count; ++k) {
                            JointSim& sim = records[k];
                            if (warm)
                                warm_start_joint(sim, s.joints[sim.joint], s.bodies);
                            else
                                solve_joint(sim, s.joints[sim.joint], s.bodies, h, bias);
                        }
                    }
                }
            }
        }
    }
    for (std::size_t p = 0; p < packs.pack_count(); ++p)
        for (int lane = 0; lane < wide_lanes; ++lane)
            records[packs.first_record(p) + std::size_t(lane)].step.linear_impulse =
                packs.impulse(p, lane);
    for (const JointSim& rec : records)
        s.sims[rec.joint] = rec;
    return packs.pack_count();
}

bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/// Every body's velocities and every joint's impulses, bit for bit.
void check_same_bits(const Scene& run, const Scene& seq) {
    for (std::size_t k = 0; k < seq.bodies.size(); ++k) {
        BOOST_TEST_CONTEXT("body " << k) {
            BOOST_TEST(same_bits(run.bodies[k].v.x, seq.bodies[k].v.x));
            BOOST_TEST(same_bits(run.bodies[k].v.y, seq.bodies[k].v.y));
            BOOST_TEST(same_bits(run.bodies[k].w, seq.bodies[k].w));
        }
    }
    for (std::size_t k = 0; k < seq.sims.size(); ++k) {
        BOOST_TEST_CONTEXT("joint " << k) {
            const JointStepState &a = run.sims[k].step, &b = seq.sims[k].step;
            BOOST_TEST(same_bits(a.linear_impulse.x, b.linear_impulse.x));
            BOOST_TEST(same_bits(a.linear_impulse.y, b.linear_impulse.y));
            BOOST_TEST(same_bits(a.motor_impulse, b.motor_impulse));
            BOOST_TEST(same_bits(a.lower_impulse, b.lower_impulse));
            BOOST_TEST(same_bits(a.upper_impulse, b.upper_impulse));
        }
    }
}

} // namespace

BOOST_AUTO_TEST_SUITE(pin_packs)

// Oracle: the sequential pass above (joint_solver.cpp's scalar code, joint by joint in creation
// order), bit for bit, on one stream and on two (a prefix and the rest, as JointStreams makes).
BOOST_AUTO_TEST_CASE(packs_reproduce_the_sequential_joint_pass, *utf::label("internals")) {
    std::size_t packs_made = 0;
    for (std::uint32_t seed = 1; seed <= 12; ++seed) {
        for (const bool two_streams : {false, true}) {
            BOOST_TEST_CONTEXT("seed " << seed << (two_streams ? ", two streams" : "")) {
                const Scene scene = random_scene(seed, 30 + seed * 17, 200 + seed * 41);
                Scene seq = scene;
                sequential(seq, 3);
                Scene run = scene;
                const auto n = std::uint32_t(scene.sims.size());
                const std::vector<std::uint32_t> bounds =
                    two_streams ? std::vector<std::uint32_t>{0, n / 2, n}
                                : std::vector<std::uint32_t>{0, n};
                packs_made += packed(run, bounds, 3);
                check_same_bits(run, seq);
            }
        }
    }
    BOOST_TEST(packs_made > 100u); // the scenes do fill packs
}

// Oracle: the stated rule for a chain's shape (pin_packs.hpp): its levels hold one joint each,
// so it is coloured, its colours holding more than four packs' worth; in creation order link k
// takes the lowest colour neither of its bodies has, 0 for the even links and 1 for the odd
// ones. Each colour runs as a level: 50 links, 12 packs of four in creation order, then the
// last two alone.
BOOST_AUTO_TEST_CASE(a_chain_is_solved_by_colour, *utf::label("internals")) {
    memory::vector<SolvedJoint> chain;
    for (std::uint32_t k = 0; k < 100; ++k)
        chain.push_back({k, k + 1, k + 2, 1, 0, 0});
    PinPacks packs;
    const std::uint32_t bounds[] = {0, 100};
    packs.order(chain, bounds, 102);
    BOOST_TEST(packs.pack_count() == 24u);
    BOOST_TEST_REQUIRE(packs.streams() == 1u);
    BOOST_TEST_REQUIRE(packs.runs(0).size() == 4u); // each colour's packs, then its two singles
    for (std::uint32_t colour = 0; colour < 2; ++colour) {
        const PinRun& in_packs = packs.runs(0)[2 * colour];
        const PinRun& alone = packs.runs(0)[2 * colour + 1];
        BOOST_TEST((in_packs.packed && in_packs.count == 48u && in_packs.first == 50 * colour));
        BOOST_TEST((!alone.packed && alone.count == 2u && alone.first == 50 * colour + 48));
    }
    for (std::uint32_t k = 0; k < 100; ++k)
        BOOST_TEST(chain[k].joint == (k < 50 ? 2 * k : 2 * (k - 50) + 1));
}

// Oracle: the same rule's exceptions, each keeping the creation order as one run of joints solved
// alone: a chain of 30 links, whose two colours would hold 15 joints each, fewer than four
// packs' worth; and joints that all hold one body, which take a colour each (no wider than the
// levels), and past 64 colours none.
BOOST_AUTO_TEST_CASE(a_short_chain_and_joints_around_one_body_keep_the_creation_order,
                     *utf::label("internals")) {
    const auto check = [](memory::vector<SolvedJoint> joints, std::size_t bodies) {
        const auto n = std::uint32_t(joints.size());
        PinPacks packs;
        const std::uint32_t bounds[] = {0, n};
        packs.order(joints, bounds, bodies);
        BOOST_TEST(packs.pack_count() == 0u);
        BOOST_TEST_REQUIRE(packs.runs(0).size() == 1u);
        BOOST_TEST(packs.runs(0)[0].count == n);
        for (std::uint32_t k = 0; k < n; ++k)
            BOOST_TEST(joints[k].joint == k);
    };
    memory::vector<SolvedJoint> chain;
    for (std::uint32_t k = 0; k < 30; ++k)
        chain.push_back({k, k + 1, k + 2, 1, 0, 0});
    BOOST_TEST_CONTEXT("a chain of 30") {
        check(chain, 32);
    }
    for (const std::uint32_t n : {40u, 100u}) {
        memory::vector<SolvedJoint> star;
        for (std::uint32_t k = 0; k < n; ++k)
            star.push_back({k, 1, k + 2, 1, 0, 0});
        BOOST_TEST_CONTEXT(n << " joints on one body") {
            check(star, n + 2);
        }
    }
}

// Oracle: the sequential pass (joint_solver.cpp's scalar code) over the joints in the order the
// packs give, bit for bit, for ropes (each stream a chain, so coloured), on one stream and on
// two; and that order is not the creation order (the colours did reorder).
BOOST_AUTO_TEST_CASE(coloured_packs_reproduce_the_sequential_pass_in_their_order,
                     *utf::label("internals")) {
    std::size_t packs_made = 0;
    for (std::uint32_t seed = 1; seed <= 6; ++seed) {
        for (const bool two_streams : {false, true}) {
            BOOST_TEST_CONTEXT("seed " << seed << (two_streams ? ", two streams" : "")) {
                const Scene scene = random_scene(seed, 150 + seed * 13, 130 + seed * 11, true);
                Scene run = scene;
                const auto n = std::uint32_t(scene.sims.size());
                const std::vector<std::uint32_t> bounds =
                    two_streams ? std::vector<std::uint32_t>{0, n / 2, n}
                                : std::vector<std::uint32_t>{0, n};
                std::vector<std::uint32_t> order;
                packs_made += packed(run, bounds, 3, &order);
                bool reordered = false;
                for (std::uint32_t k = 0; k < n; ++k)
                    reordered = reordered || order[k] != k;
                BOOST_TEST(reordered);
                Scene seq = scene;
                sequential(seq, 3, order);
                check_same_bits(run, seq);
            }
        }
    }
    BOOST_TEST(packs_made > 50u);
}

// Oracle: the order is a function of the joints, their bodies and their pins (pin_packs.hpp;
// order keeps the last one only for the same inputs). A PinPacks that ordered one scene's
// joints orders another's of the same count, bodies and streams exactly as a new PinPacks does:
// the same passes' order and the same runs and packs, in one stream and in two; and so for the
// same joints with one record changed near their end.
BOOST_AUTO_TEST_CASE(other_joints_of_the_same_count_are_ordered_afresh, *utf::label("internals")) {
    const auto solved_of = [](const Scene& s) {
        memory::vector<SolvedJoint> out;
        for (const JointSim& sim : s.sims)
            out.push_back({sim.joint, sim.solver_a, sim.solver_b,
                           plain_pin(sim.type, sim.spring, sim.motor, sim.limit) ? 1u : 0u, 0, 0});
        return out;
    };
    const auto same_runs = [](const PinPacks& a, const PinPacks& b) {
        bool same = a.streams() == b.streams() && a.pack_count() == b.pack_count();
        for (std::uint32_t s = 0; same && s < a.streams(); ++s) {
            const auto ra = a.runs(s), rb = b.runs(s);
            same = ra.size() == rb.size();
            for (std::size_t k = 0; same && k < ra.size(); ++k)
                same = ra[k].first == rb[k].first && ra[k].count == rb[k].count &&
                       ra[k].pack == rb[k].pack && ra[k].packed == rb[k].packed;
        }
        for (std::size_t p = 0; same && p < a.pack_count(); ++p)
            same = a.first_record(p) == b.first_record(p);
        return same;
    };
    for (const bool two_streams : {false, true}) {
        BOOST_TEST_CONTEXT((two_streams ? "two streams" : "one stream")) {
            const Scene first = random_scene(3, 60, 300), second = random_scene(4, 60, 300);
            const auto n = std::uint32_t(first.sims.size());
            BOOST_TEST_REQUIRE(second.sims.size() == n);
            const std::vector<std::uint32_t> bounds = two_streams
                                                          ? std::vector<std::uint32_t>{0, n / 2, n}
                                                          : std::vector<std::uint32_t>{0, n};
            memory::vector<SolvedJoint> a = solved_of(first), b = solved_of(second),
                                        fresh_b = solved_of(second);
            BOOST_TEST_REQUIRE((std::memcmp(a.data(), b.data(), n * sizeof(SolvedJoint)) != 0));
            PinPacks reused, fresh;
            reused.order(a, bounds, first.bodies.size());
            reused.order(b, bounds, second.bodies.size());
            fresh.order(fresh_b, bounds, second.bodies.size());
            BOOST_TEST((std::memcmp(b.data(), fresh_b.data(), n * sizeof(SolvedJoint)) == 0));
            BOOST_TEST(same_runs(reused, fresh));
            BOOST_TEST(fresh.pack_count() > 0u); // the scene fills packs

            // The same joints with only the last plain pin made not plain: inputs that differ
            // far past their first records, as when one joint of many gets a motor. The order
            // holds the changed record, as a new PinPacks' does, not the last step's.
            const auto flipped = [&] {
                memory::vector<SolvedJoint> c = solved_of(first);
                const auto last = std::find_if(c.rbegin(), c.rend(),
                                               [](const SolvedJoint& j) { return j.plain != 0; });
                BOOST_TEST_REQUIRE((last != c.rend()));
                last->plain = 0;
                return c;
            };
            memory::vector<SolvedJoint> a2 = solved_of(first), c = flipped(), fresh_c = flipped();
            PinPacks reused_c, new_c;
            reused_c.order(a2, bounds, first.bodies.size());
            reused_c.order(c, bounds, first.bodies.size());
            new_c.order(fresh_c, bounds, first.bodies.size());
            BOOST_TEST((std::memcmp(c.data(), fresh_c.data(), n * sizeof(SolvedJoint)) == 0));
            BOOST_TEST(same_runs(reused_c, new_c));
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
