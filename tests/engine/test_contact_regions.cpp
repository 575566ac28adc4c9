// Contact regions (WorldDef::contact_regions): the colouring's streams, and the threads that run
// them, against the sequential Gauss-Seidel pass in the order the regions define (world_def.hpp):
// the manifolds within region 0, ..., within region R - 1, in creation order, then those
// between regions by greedy colour; the regions are slabs of the bodies' places, bounded at the
// manifolds' places of rank n r / R.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <random>
#include <set>
#include <thread>
#include <utility>
#include <vector>

#include "support/random_contacts.hpp"
#include "support/sequential_pass.hpp"
#include "support/wide_solver_access.hpp"
#include "tamias2d/dynamics/constraint_graph.hpp"
#include "tamias2d/dynamics/contacts/contact_iteration.hpp"
#include "tamias2d/dynamics/contacts/pack_streams.hpp"
#include "tamias2d/dynamics/contacts/wide_contact_solver.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

using test::check_same_pass;
using test::iteration_settings;
using test::random_scene;
using test::Scene;
using test::sequential_passes;

/// Random places along the cut axis for the bodies (body 0, the static one, has none).
std::vector<double> random_places(std::uint32_t seed, std::size_t body_count) {
    std::mt19937_64 rng(seed * 7919u);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    std::vector<double> cut(body_count, 0.0);
    for (std::size_t i = 1; i < body_count; ++i)
        cut[i] = u(rng);
    return cut;
}

/// The order by its definition, written independently of ConstraintGraph (a full sort where it
/// selects): each manifold's stream (its region, or R for one between regions) and the pass's
/// sequence of manifolds.
struct RegionOrder {
    std::vector<std::uint32_t> stream;
    std::vector<std::uint32_t> sequence;
};
RegionOrder region_order(const Scene& s, const std::vector<double>& cut, std::uint32_t regions) {
    const auto place = [&](const ContactConstraint& c) {
        if (c.body_a == 0)
            return cut[c.body_b];
        if (c.body_b == 0)
            return cut[c.body_a];
        return 0.5 * (cut[c.body_a] + cut[c.body_b]);
    };
    std::vector<double> sorted;
    for (const ContactConstraint& c : s.constraints)
        sorted.push_back(place(c));
    std::sort(sorted.begin(), sorted.end());
    std::vector<double> bounds;
    for (std::uint32_t r = 1; r < regions; ++r)
        bounds.push_back(sorted[sorted.size() * r / regions]);
    const auto region = [&](std::uint32_t body) {
        return std::uint32_t(
            std::count_if(bounds.begin(), bounds.end(), [&](double b) { return b <= cut[body]; }));
    };
    RegionOrder o;
    for (const ContactConstraint& c : s.constraints) {
        const std::uint32_t ra = region(c.body_a != 0 ? c.body_a : c.body_b);
        const std::uint32_t rb = region(c.body_b != 0 ? c.body_b : c.body_a);
        o.stream.push_back(ra == rb ? ra : regions);
    }
    for (std::uint32_t st = 0; st < regions; ++st) {
        for (std::uint32_t i = 0; i < s.constraints.size(); ++i)
            if (o.stream[i] == st)
                o.sequence.push_back(i);
    }
    // Those between regions by greedy colour: in creation order each takes the lowest colour
    // (of 64; with all taken, 64) none of the earlier ones on its moving bodies has; then by
    // colour, creation order within.
    std::vector<std::set<int>> taken(cut.size());
    std::vector<std::pair<int, std::uint32_t>> coloured;
    for (std::uint32_t i = 0; i < s.constraints.size(); ++i) {
        if (o.stream[i] != regions)
            continue;
        const ContactConstraint& c = s.constraints[i];
        int colour = 0;
        while (colour < 64 && ((c.body_a != 0 && taken[c.body_a].count(colour) != 0) ||
                               (c.body_b != 0 && taken[c.body_b].count(colour) != 0)))
            ++colour;
        if (colour < 64) {
            taken[c.body_a].insert(colour);
            taken[c.body_b].insert(colour);
        }
        coloured.emplace_back(colour, i);
    }
    std::sort(coloured.begin(), coloured.end());
    for (const auto& [colour, i] : coloured)
        o.sequence.push_back(i);
    return o;
}

/// The same rounds on the wide solver's streams, run by `threads` std::threads at once through
/// PackStreams, thread t preferring stream (first_stream + t) mod streams, as the World's pool runs
/// them (a worker may take any stream's item first).
void threaded_passes(WideContactSolver& solver, std::vector<SolverBody>& bodies, int threads,
                     std::uint32_t first_stream = 0) {
    const ContactSolverSettings st = iteration_settings();
    struct Pass {
        WideContactSolver* solver;
        std::vector<SolverBody>* bodies;
        const ContactSolverSettings* settings; // null: the warm start
        bool use_bias;
    };
    const PackStreams::RunPacks run_packs = [](void* context, std::size_t first, std::size_t count,
                                               std::uint32_t stream) {
        const Pass& p = *static_cast<const Pass*>(context);
        if (p.settings == nullptr)
            p.solver->warm_start_run(first, count, stream, *p.bodies);
        else
            p.solver->solve_run(first, count, stream, *p.bodies, *p.settings, p.use_bias);
    };
    PackStreams streams;
    const auto pass = [&](Pass p) {
        streams.reset();
        std::vector<std::thread> running;
        for (int t = 0; t < threads; ++t) {
            running.emplace_back([&, t] {
                streams.run(solver.graph(),
                            (first_stream + std::uint32_t(t)) % solver.graph().streams(), run_packs,
                            &p);
            });
        }
        for (std::thread& t : running)
            t.join();
    };
    for (int round = 0; round < 3; ++round) {
        pass({&solver, &bodies, nullptr, false});
        pass({&solver, &bodies, &st, true});
        pass({&solver, &bodies, &st, false});
    }
}

/// The bodies' states after 120 steps of a scene under `gravity` with `regions` contact
/// regions. Every body's gravity scale is 0: the gravity only chooses the cut's direction.
/// The grid: 48 boxes in a loose 12 x 4 grid with seeded velocities. The diagonal: 24 discs on
/// the line y = x moving along it, which keeps them on it exactly (every impulse's normal and
/// every velocity have equal components, computed alike).
std::vector<BodyState> run_regions(Vec2d gravity, int regions, bool diagonal = false) {
    World world(WorldDef{.gravity = gravity, .contact_regions = regions});
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<BodyId> ids;
    for (int i = 0; i < (diagonal ? 24 : 48); ++i) {
        BodyDef d;
        d.gravity_scale = 0.0;
        if (diagonal) {
            d.position = {1.5 * i, 1.5 * i};
            const double v = 2.0 * u(rng);
            d.linear_velocity = {v, v};
        } else {
            d.position = {1.1 * (i % 12), 1.1 * (i / 12)};
            d.linear_velocity = {2.0 * u(rng), 2.0 * u(rng)};
            d.angular_velocity = u(rng);
        }
        ids.push_back(world.create_body(d));
        world.create_shape(ids.back(), diagonal ? circle_shape(0.5) : box_shape(1.0, 1.0));
    }
    for (int k = 0; k < 120; ++k)
        world.step(1.0 / 60.0);
    std::vector<BodyState> states;
    for (const BodyId b : ids)
        states.push_back(world.state(b));
    return states;
}

bool same_states(const std::vector<BodyState>& a, const std::vector<BodyState>& b) {
    return std::memcmp(a.data(), b.data(), a.size() * sizeof(BodyState)) == 0;
}

/// The streams of `regions` regions coloured from the scene's manifolds placed at `cut`: every
/// manifold in one lane of one pack of its region's stream (or the stream between regions),
/// no pack holding a moving body twice, and, walking the order's sequence, each manifold in a
/// later pack than the last one on its bodies, waiting for it where that one is in another
/// stream, whose streams never meet on a body unless one is the stream between regions.
void check_streams(const Scene& scene, const std::vector<double>& cut, std::uint32_t regions) {
    std::vector<GraphEdge> edges;
    for (const ContactConstraint& c : scene.constraints)
        edges.push_back(test::prepared_edge(c));
    const RegionOrder order = region_order(scene, cut, regions);
    ConstraintGraph graph;
    graph.colour(edges, scene.bodies.size(), regions, cut);
    const auto packs = graph.packs();
    const std::size_t n = scene.constraints.size();
    // Where each manifold was placed: pack, stream.
    std::vector<std::size_t> pack_of(n, packs.size());
    std::vector<std::uint32_t> stream_of(n, 0);
    for (std::uint32_t s = 0; s < graph.streams(); ++s) {
        for (std::size_t p = graph.stream_begin(s); p < graph.stream_begin(s + 1); ++p) {
            std::set<std::uint32_t> seen;
            for (const std::uint32_t i : packs[p]) {
                if (i == ConstraintGraph::no_constraint)
                    continue;
                BOOST_TEST_REQUIRE(i < n);
                BOOST_TEST(pack_of[i] == packs.size()); // in one lane only
                pack_of[i] = p;
                stream_of[i] = s;
                BOOST_TEST(order.stream[i] == s);
                for (const std::uint32_t body :
                     {scene.constraints[i].body_a, scene.constraints[i].body_b})
                    BOOST_TEST((body == 0 || seen.insert(body).second));
            }
        }
    }
    BOOST_TEST(graph.stream_begin(graph.streams()) == packs.size());
    for (std::size_t i = 0; i < n; ++i)
        BOOST_TEST(pack_of[i] < packs.size());
    // Each pack's wait on each stream, counting the earlier packs' of its stream.
    std::vector<std::vector<std::uint32_t>> waited(packs.size());
    for (std::uint32_t s = 0; s < graph.streams(); ++s) {
        std::vector<std::uint32_t> so_far(graph.streams(), 0);
        for (std::size_t p = graph.stream_begin(s); p < graph.stream_begin(s + 1); ++p) {
            for (const StreamWait& w : graph.waits(p)) {
                BOOST_TEST(w.stream < s); // only on streams before it
                so_far[w.stream] = std::max(so_far[w.stream], w.packs);
            }
            waited[p] = so_far;
        }
    }
    // Walk the sequence, remembering each moving body's last manifold.
    std::vector<std::uint32_t> last(scene.bodies.size(), ConstraintGraph::no_constraint);
    for (const std::uint32_t i : order.sequence) {
        for (const std::uint32_t body :
             {scene.constraints[i].body_a, scene.constraints[i].body_b}) {
            if (body == 0)
                continue;
            const std::uint32_t before = last[body];
            last[body] = i;
            if (before == ConstraintGraph::no_constraint)
                continue;
            BOOST_TEST(pack_of[before] < pack_of[i]); // solved before it
            const std::uint32_t t = stream_of[before], s = stream_of[i];
            // Two regions' streams never meet on a body.
            BOOST_TEST((t == s || t == regions || s == regions));
            if (t != s) {
                const std::size_t position = pack_of[before] - graph.stream_begin(t);
                BOOST_TEST(waited[pack_of[i]][t] >= position + 1);
            }
        }
    }
}

} // namespace

BOOST_AUTO_TEST_SUITE(contact_regions)

// Oracle: IM7's iteration as a sequential Gauss-Seidel pass over the manifolds, one after
// another, in the order the regions define (region_order above, a separate implementation of
// the rule). The packs in their stored order, and the streams run by one, two or three threads
// at once, must give its numbers exactly: a missing wait, a lane mix-up or a pack run before a
// manifold it follows on a body shows up as a difference.
BOOST_AUTO_TEST_CASE(regions_reproduce_the_sequential_pass_in_their_order, *utf::label("IM7")) {
    int compared = 0;
    for (std::uint32_t seed = 1; seed <= 24; ++seed) {
        const Scene scene = random_scene(seed, 6 + int(seed % 23), 40 + int(seed * 13 % 160));
        const std::vector<double> cut = random_places(seed, scene.bodies.size());
        for (std::uint32_t regions = 2; regions <= 4; ++regions) {
            BOOST_TEST_CONTEXT("seed " << seed << ", " << regions << " regions") {
                Scene seq = scene;
                sequential_passes(seq, region_order(scene, cut, regions).sequence);

                Scene stored = scene;
                WideContactSolver solver;
                test::load(solver, stored.constraints, stored.bodies, regions, cut);
                BOOST_TEST_REQUIRE(solver.graph().streams() == regions + 1);
                const ContactSolverSettings st = iteration_settings();
                for (int round = 0; round < 3; ++round) {
                    solver.warm_start(stored.bodies);
                    solver.solve(stored.bodies, st, true);
                    solver.solve(stored.bodies, st, false);
                }
                test::store(solver, stored.constraints);
                check_same_pass(stored, seq);

                // One, two and three threads from stream 0; and one thread from each later
                // stream, which waits for another: it must come back to it.
                std::vector<std::pair<int, std::uint32_t>> runs{{1, 0}, {2, 0}, {3, 0}};
                for (std::uint32_t first = 1; first <= regions; ++first)
                    runs.emplace_back(1, first);
                for (const auto& [threads, first] : runs) {
                    BOOST_TEST_CONTEXT(threads << " threads from stream " << first) {
                        Scene run = scene;
                        WideContactSolver streamed;
                        test::load(streamed, run.constraints, run.bodies, regions, cut);
                        threaded_passes(streamed, run.bodies, threads, first);
                        test::store(streamed, run.constraints);
                        check_same_pass(run, seq);
                    }
                }
                ++compared;
            }
        }
    }
    BOOST_TEST(compared == 72);
}

// Oracle: the rules of the region order and of the streams' waits, checked pack by pack
// against region_order: each stream's packs hold its manifolds only; every manifold is in one
// lane; no moving body appears twice in a pack; two manifolds on one moving body are solved in
// the order's sequence; the regions' streams share no moving body; and a manifold whose
// predecessor on a body is in another stream waits (by its pack's or an earlier pack's waits)
// for that stream to have finished the predecessor's pack, a stream that comes before it.
// Every region count the settings allow (up to ConstraintGraph::max_regions, the largest
// WorldDef::contact_regions validate() accepts).
BOOST_AUTO_TEST_CASE(streams_keep_the_order_and_wait_for_their_predecessors) {
    for (std::uint32_t seed = 40; seed < 64; ++seed) {
        const Scene scene = random_scene(seed, 5 + int(seed % 19), 30 + int(seed * 11 % 150));
        const std::vector<double> cut = random_places(seed, scene.bodies.size());
        for (std::uint32_t regions = 2; regions <= ConstraintGraph::max_regions; ++regions) {
            BOOST_TEST_CONTEXT("seed " << seed << ", " << regions << " regions") {
                check_streams(scene, cut, regions);
            }
        }
    }
}

// Oracle: the order is a function of its inputs (the rule of world_def.hpp names no history):
// a graph that coloured other scenes and other region counts before gives each scene the packs,
// streams and waits a new graph gives it, as the world's solver reuses its graph step by step.
BOOST_AUTO_TEST_CASE(a_graph_used_before_colours_as_a_new_one) {
    ConstraintGraph reused;
    int compared = 0;
    for (std::uint32_t seed = 40; seed < 52; ++seed) {
        const Scene scene = random_scene(seed, 5 + int(seed % 19), 30 + int(seed * 11 % 150));
        const std::vector<double> cut = random_places(seed, scene.bodies.size());
        std::vector<GraphEdge> edges;
        for (const ContactConstraint& c : scene.constraints)
            edges.push_back(test::prepared_edge(c));
        for (std::uint32_t regions = 2; regions <= 4; ++regions) {
            BOOST_TEST_CONTEXT("seed " << seed << ", " << regions << " regions") {
                ConstraintGraph fresh;
                fresh.colour(edges, scene.bodies.size(), regions, cut);
                reused.colour(edges, scene.bodies.size(), regions, cut);
                BOOST_TEST_REQUIRE(reused.streams() == fresh.streams());
                BOOST_TEST(std::ranges::equal(reused.packs(), fresh.packs()));
                for (std::uint32_t st = 0; st <= fresh.streams(); ++st)
                    BOOST_TEST(reused.stream_begin(st) == fresh.stream_begin(st));
                for (std::size_t p = 0; p < std::min(reused.packs().size(), fresh.packs().size());
                     ++p)
                    BOOST_TEST(std::ranges::equal(
                        reused.waits(p), fresh.waits(p), [](StreamWait a, StreamWait b) {
                            return a.stream == b.stream && a.packs == b.packs;
                        }));
                ++compared;
            }
        }
    }
    BOOST_TEST(compared == 36);
}

// Oracle: as above, where the colours run out: a body with more manifolds between regions than
// the 64 colours (the definition's "with all taken, 64", after every coloured one). A hub on
// one side of the cut touches 70 bodies on the other, and a second hub touches the last six of
// them again, so that the manifolds after the colours ran out meet bodies that had them.
BOOST_AUTO_TEST_CASE(a_body_with_more_manifolds_between_regions_than_colours) {
    Scene scene = random_scene(7, 2, 1); // the static body 0 and one body: the first hub
    scene.constraints.clear();
    const std::uint32_t hub = 1, leaves = 70;
    for (std::uint32_t k = 0; k <= leaves; ++k)
        scene.bodies.push_back(scene.bodies[hub]); // leaves 2 .. 71, then the second hub, 72
    ContactConstraint c = random_scene(7, 3, 1).constraints.front(); // a manifold's points
    const auto link = [&](std::uint32_t a, std::uint32_t b) {
        c.body_a = a;
        c.body_b = b;
        scene.constraints.push_back(c);
    };
    for (std::uint32_t k = 0; k < leaves; ++k)
        link(hub, 2 + k);
    for (std::uint32_t k = leaves - 6; k < leaves; ++k)
        link(2 + k, 2 + leaves);
    std::vector<double> cut(scene.bodies.size(), 1.0); // the leaves on one side
    cut[hub] = cut[2 + leaves] = -1.0;                 // the hubs on the other
    const RegionOrder order = region_order(scene, cut, 2);
    BOOST_TEST_REQUIRE(std::count(order.stream.begin(), order.stream.end(), 2u) ==
                       std::ptrdiff_t(scene.constraints.size())); // all between the regions
    check_streams(scene, cut, 2);
}

// Oracle: the rule for regions = 1: one stream, no waits, the packs of the sequential pass in
// creation order (the colouring without regions).
BOOST_AUTO_TEST_CASE(one_region_is_one_stream_without_waits) {
    const Scene scene = random_scene(7, 12, 120);
    std::vector<GraphEdge> edges;
    for (const ContactConstraint& c : scene.constraints)
        edges.push_back(test::prepared_edge(c));
    ConstraintGraph with_places, without;
    with_places.colour(edges, scene.bodies.size(), 1, random_places(7, scene.bodies.size()));
    without.colour(edges, scene.bodies.size());
    BOOST_TEST(with_places.streams() == 1u);
    BOOST_TEST(with_places.stream_begin(1) == with_places.packs().size());
    BOOST_TEST(std::equal(with_places.packs().begin(), with_places.packs().end(),
                          without.packs().begin(), without.packs().end()));
    for (std::size_t p = 0; p < with_places.packs().size(); ++p)
        BOOST_TEST(with_places.waits(p).empty());
}

// Oracle: WorldDef::contact_regions' rule, "without gravity, the cuts are across x", as under
// gravity along -y. The grid collides in a world without gravity; under gravity (0, -9.81) it
// must give the same bits (its cuts are across x by the rule). The same world solved in one
// region must not (the positive control: the regions change the order).
BOOST_AUTO_TEST_CASE(without_gravity_the_regions_are_cut_across_x) {
    const std::vector<BodyState> weightless = run_regions({0.0, 0.0}, 2);
    BOOST_TEST(same_states(weightless, run_regions({0.0, -9.81}, 2)));
    BOOST_TEST(!same_states(weightless, run_regions({0.0, 0.0}, 1)));
}

// Oracle: the rule "cut across gravity", whatever its strength: under a weak gravity along x,
// 0.5 m/s^2, the grid is cut across y as under 9.81 m/s^2 along x, to the same bits; cut
// across x (no gravity) it is not (the positive control: the cut's direction shows).
BOOST_AUTO_TEST_CASE(weak_gravity_cuts_the_regions_across_it_as_strong_gravity_does) {
    const std::vector<BodyState> strong = run_regions({9.81, 0.0}, 2);
    BOOST_TEST(same_states(strong, run_regions({0.5, 0.0}, 2)));
    BOOST_TEST(!same_states(strong, run_regions({0.0, 0.0}, 2)));
}

// Oracle: the rule "cut across gravity" for a gravity along neither axis. Under gravity
// (5, -5) the cut runs along (1, 1) / sqrt(2): the discs on y = x are ordered along it as by
// x alone, so the world must give the bits of gravity (0, -9.81), whose cut is x. The same
// world in one region must not (the positive control: the regions change the order).
BOOST_AUTO_TEST_CASE(a_diagonal_gravity_cuts_the_regions_across_it) {
    const std::vector<BodyState> along_x = run_regions({0.0, -9.81}, 2, true);
    BOOST_TEST(same_states(along_x, run_regions({5.0, -5.0}, 2, true)));
    BOOST_TEST(!same_states(along_x, run_regions({0.0, -9.81}, 1, true)));
    for (const BodyState& b : along_x) // still on the diagonal
        BOOST_TEST(b.position.x == b.position.y);
}

// Oracle: the rule "cut across gravity" for a slanted gravity of two strengths: (3, -4) and
// (0.3, -0.4) m/s^2 point the same way, so both cut the grid along (0.8, 0.6) (the same
// doubles: 4 / 5 and 0.4 / 0.5 round alike) and must give the same bits; cut across x
// (gravity along -y) it is not (the positive control: this direction shows in the grid).
BOOST_AUTO_TEST_CASE(a_slanted_gravity_cuts_alike_at_any_strength) {
    const std::vector<BodyState> strong = run_regions({3.0, -4.0}, 2);
    BOOST_TEST(same_states(strong, run_regions({0.3, -0.4}, 2)));
    BOOST_TEST(!same_states(strong, run_regions({0.0, -9.81}, 2)));
}

BOOST_AUTO_TEST_SUITE_END()
