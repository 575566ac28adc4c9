// Broad phase: new pairs equal a brute-force IM4 scan over fattened boxes (IM4), collision
// determination of whole scenes equals a brute-force T5 check (R7), and the per-step calls
// allocate nothing.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cstdlib>
#include <new>
#include <random>
#include <set>
#include <vector>

#include "oracles.hpp"
#include "support/replaced_new.hpp"
#include "tamias2d/collision/broad_phase.hpp"
#include "tamias2d/collision/narrow_phase.hpp"
#include "tamias2d/geometry/shape_aabb.hpp"
#include "tamias2d/model/im4_aabb_overlap.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
namespace im4 = tamias2d::model::im4;
using Pairs = memory::vector<BroadPhase::Pair>;

namespace {

constexpr double margin = 0.1;

Aabb random_box(std::mt19937_64& rng, double extent) {
    std::uniform_real_distribution<double> c(-extent, extent);
    std::uniform_real_distribution<double> s(0.05, 2.0);
    const auto b = im4::from_centre(c(rng), c(rng), s(rng), s(rng));
    return {b.min_x, b.min_y, b.max_x, b.max_y};
}

Aabb shifted(const Aabb& b, double dx, double dy) {
    return {b.min_x + dx, b.min_y + dy, b.max_x + dx, b.max_y + dy};
}

Aabb fattened(const Aabb& b) {
    return {b.min_x - margin, b.min_y - margin, b.max_x + margin, b.max_y + margin};
}

bool encloses(const Aabb& outer, const Aabb& inner) {
    return outer.min_x <= inner.min_x && outer.min_y <= inner.min_y && inner.max_x <= outer.max_x &&
           inner.max_y <= outer.max_y;
}

struct OracleProxy {
    Aabb fat;
    bool is_static;
    bool moved;
    bool alive;
};

/// IM4's overlap written independently of model::im4 (which the broad phase calls): boxes are
/// apart when a gap separates them along x or y, touching counts as apart (IM4's strict "<").
bool boxes_overlap(const Aabb& a, const Aabb& b) {
    const bool apart_x = a.max_x <= b.min_x || b.max_x <= a.min_x;
    const bool apart_y = a.max_y <= b.min_y || b.max_y <= a.min_y;
    return !apart_x && !apart_y;
}

/// Brute force O(n^2): every pair of live proxies, not both static, at least one moved,
/// whose fat boxes overlap by IM4.
Pairs brute_force(const std::vector<OracleProxy>& ps) {
    Pairs out;
    for (std::uint32_t i = 0; i < ps.size(); ++i)
        for (std::uint32_t j = i + 1; j < ps.size(); ++j) {
            const OracleProxy &a = ps[i], &b = ps[j];
            if (!a.alive || !b.alive || (a.is_static && b.is_static) || !(a.moved || b.moved))
                continue;
            if (boxes_overlap(a.fat, b.fat))
                out.emplace_back(i, j);
        }
    return out;
}

} // namespace

BOOST_AUTO_TEST_SUITE(broad_phase)

// Oracle: brute-force O(n^2) IM4 check (boxes_overlap, not the model function the broad phase
// calls) over the fattened boxes,
// tracked independently of the library, through creation, small and large moves, static
// proxies and destruction.
BOOST_AUTO_TEST_CASE(new_pairs_equal_brute_force, *utf::label("IM4")) {
    std::mt19937_64 rng(3);
    BroadPhase bp(margin);
    std::vector<OracleProxy> oracle_ps;
    std::vector<int> ids;
    std::vector<Aabb> tight;
    std::bernoulli_distribution coin(0.25);
    for (std::uint32_t i = 0; i < 400; ++i) {
        const Aabb b = random_box(rng, 25.0);
        const bool st = coin(rng);
        ids.push_back(bp.create_proxy(b, i, st));
        tight.push_back(b);
        oracle_ps.push_back({fattened(b), st, true, true});
    }
    Pairs got;
    for (int round = 0; round < 30; ++round) {
        got.clear();
        bp.update_pairs(got);
        BOOST_TEST_REQUIRE((got == brute_force(oracle_ps)));
        for (auto& p : oracle_ps)
            p.moved = false;

        std::uniform_real_distribution<double> small(-0.08, 0.08), large(-3.0, 3.0);
        for (std::uint32_t i = 0; i < ids.size(); ++i) {
            if (!oracle_ps[i].alive)
                continue;
            const double r = std::uniform_real_distribution<double>(0, 1)(rng);
            if (oracle_ps[i].is_static && r > 0.02)
                continue; // statics rarely move
            if (r < 0.01) {
                bp.destroy_proxy(ids[i]);
                oracle_ps[i].alive = false;
                continue;
            }
            const bool big = r < 0.3;
            const Aabb b =
                shifted(tight[i], big ? large(rng) : small(rng), big ? large(rng) : small(rng));
            bp.move_proxy(ids[i], b);
            tight[i] = b;
            if (!encloses(oracle_ps[i].fat, b)) {
                oracle_ps[i].fat = fattened(b);
                oracle_ps[i].moved = true;
            }
            BOOST_TEST(bp.fat_aabb(ids[i]).min_x == oracle_ps[i].fat.min_x);
        }
        // A few newcomers, possibly reusing destroyed ids.
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t user = std::uint32_t(ids.size());
            const Aabb b = random_box(rng, 25.0);
            ids.push_back(bp.create_proxy(b, user, false));
            tight.push_back(b);
            oracle_ps.push_back({fattened(b), false, true, true});
        }
    }
    // Pairs are unique, ordered (min user, max user) and sorted.
    BOOST_TEST(std::is_sorted(got.begin(), got.end()));
    BOOST_TEST((std::adjacent_find(got.begin(), got.end()) == got.end()));
    for (const auto& [a, b] : got)
        BOOST_TEST(a < b);
}

// Oracle: the IM4 check over the fat boxes, restricted to static proxies: never a pair.
BOOST_AUTO_TEST_CASE(static_pairs_never_reported, *utf::label("internals")) {
    BroadPhase bp(margin);
    for (std::uint32_t i = 0; i < 20; ++i)
        bp.create_proxy({0.0, 0.0, 1.0, 1.0}, i, true);
    Pairs out;
    bp.update_pairs(out);
    BOOST_TEST(out.empty());
    const int d = bp.create_proxy({0.5, 0.5, 2.0, 2.0}, 100, false);
    bp.update_pairs(out);
    BOOST_TEST(out.size() == 20u);
    BOOST_TEST(bp.is_static(d) == false);
    // A resting proxy (tight box inside its fat box) is not re-reported.
    out.clear();
    bp.move_proxy(d, {0.55, 0.55, 2.05, 2.05});
    bp.update_pairs(out);
    BOOST_TEST(out.empty());
}

// Oracle: R7 through T5: in random moving scenes, the pairs with a contact found by
// broad phase + narrow phase equal the pairs a brute-force all-pairs distance check
// (oracle::distance == 0, i.e. T5's shared point) finds, every step.
BOOST_AUTO_TEST_CASE(scene_collisions_equal_brute_force, *utf::label("T5")) {
    std::mt19937_64 rng(17);
    const int n = 120;
    std::vector<Geometry> shapes;
    std::vector<Transform> xf;
    std::vector<Vec2d> vel;
    std::vector<bool> is_static;
    BroadPhase bp(margin);
    std::vector<int> proxy;
    std::uniform_real_distribution<double> v(-0.3, 0.3);
    for (int i = 0; i < n; ++i) {
        shapes.push_back(oracle::random_shape(rng));
        xf.push_back(oracle::random_transform(rng, 8.0));
        is_static.push_back(i % 10 == 0);
        vel.push_back(is_static.back() ? Vec2d{} : Vec2d{v(rng), v(rng)});
        proxy.push_back(
            bp.create_proxy(compute_aabb(shapes[i], xf[i]), std::uint32_t(i), is_static.back()));
    }
    std::set<BroadPhase::Pair> candidates; // the persistent pair set a world keeps
    Pairs fresh;
    int total_contacts = 0;
    for (int step = 0; step < 40; ++step) {
        for (int i = 0; i < n; ++i) {
            if (is_static[i])
                continue;
            xf[i].p += vel[i];
            xf[i].q = Rot::from_angle(std::atan2(xf[i].q.s, xf[i].q.c) + 0.05);
            bp.move_proxy(proxy[i], compute_aabb(shapes[i], xf[i]));
        }
        fresh.clear();
        bp.update_pairs(fresh);
        candidates.insert(fresh.begin(), fresh.end());
        std::erase_if(candidates, [&](const BroadPhase::Pair& p) {
            return !overlaps(bp.fat_aabb(proxy[p.first]), bp.fat_aabb(proxy[p.second]));
        });
        std::set<BroadPhase::Pair> found;
        for (const auto& [a, b] : candidates) {
            const CollideInput in{xf[a], xf[a].p, xf[b], xf[b].p, 0.0};
            if (collide(shapes[a], shapes[b], in).count > 0)
                found.insert({a, b});
        }
        std::set<BroadPhase::Pair> truth;
        for (std::uint32_t a = 0; a < std::uint32_t(n); ++a)
            for (std::uint32_t b = a + 1; b < std::uint32_t(n); ++b)
                if (!(is_static[a] && is_static[b]) &&
                    oracle::distance(shapes[a], xf[a], shapes[b], xf[b]) == 0.0)
                    truth.insert({a, b});
        BOOST_TEST_REQUIRE((found == truth));
        total_contacts += int(truth.size());
    }
    BOOST_TEST(total_contacts > 100);
}

// Oracle: move_proxy itself. Batched moves (move_proxies, as the world's write-back makes them)
// leave the same fat boxes and report the same pairs as one move_proxy call per proxy.
BOOST_AUTO_TEST_CASE(batched_moves_equal_single_moves, *utf::label("internals")) {
    std::mt19937_64 rng(29);
    BroadPhase one(margin), many(margin);
    std::vector<int> ids;
    std::vector<Aabb> tight;
    for (std::uint32_t i = 0; i < 400; ++i) {
        tight.push_back(random_box(rng, 20.0));
        const int a = one.create_proxy(tight.back(), i, i % 9 == 0);
        BOOST_TEST_REQUIRE(many.create_proxy(tight.back(), i, i % 9 == 0) == a);
        ids.push_back(a);
    }
    std::uniform_real_distribution<double> d(-0.5, 0.5);
    std::vector<BroadPhase::ProxyMove> moves;
    int moved = 0;
    for (int round = 0; round < 30; ++round) {
        moves.clear();
        for (std::size_t i = 0; i < ids.size(); ++i) {
            if (one.is_static(ids[i]))
                continue;
            // dy drawn first, as GCC evaluates the arguments (their order is unspecified).
            const double dy = 0.6 * d(rng);
            tight[i] = shifted(tight[i], 0.6 * d(rng), dy);
            one.move_proxy(ids[i], tight[i]);
            if (!contains(many.fat_aabb(ids[i]), tight[i]))
                moves.push_back({ids[i], many.fattened(tight[i])});
        }
        moved += int(moves.size());
        many.move_proxies(moves);
        for (const int id : ids) {
            const Aabb a = one.fat_aabb(id), b = many.fat_aabb(id);
            BOOST_TEST_REQUIRE((a.min_x == b.min_x && a.min_y == b.min_y && a.max_x == b.max_x &&
                                a.max_y == b.max_y));
        }
        Pairs p1, p2;
        one.update_pairs(p1);
        many.update_pairs(p2);
        BOOST_TEST_REQUIRE((p1 == p2));
    }
    BOOST_TEST(moved > 1000);
    BOOST_TEST(many.dynamic_tree().validate());
}

// Oracle: heap allocation counter (replaced global operator new): once warmed up, moving
// proxies, update_pairs and queries allocate nothing.
BOOST_AUTO_TEST_CASE(steady_state_allocation_free) {
    std::mt19937_64 rng(23);
    BroadPhase bp(margin);
    std::vector<int> ids;
    std::vector<Aabb> tight;
    for (std::uint32_t i = 0; i < 500; ++i) {
        tight.push_back(random_box(rng, 20.0));
        ids.push_back(bp.create_proxy(tight.back(), i, i % 7 == 0));
    }
    Pairs out;
    std::uniform_real_distribution<double> d(-0.5, 0.5);
    auto round = [&](double scale) {
        for (std::size_t i = 0; i < ids.size(); ++i) {
            const double dy = scale * d(rng); // (as above)
            tight[i] = shifted(tight[i], scale * d(rng), dy);
            bp.move_proxy(ids[i], tight[i]);
        }
        out.clear();
        bp.update_pairs(out);
        int hits = 0;
        bp.query({-5.0, -5.0, 5.0, 5.0}, [&](int) { ++hits; });
        return hits;
    };
    for (int k = 0; k < 5; ++k)
        round(4.0); // warm-up: every proxy moves, buffers reach their size
    out.reserve(out.capacity() * 2);
    const long before = tamias2d::test::allocation_count();
    for (int k = 0; k < 20; ++k)
        round(1.0);
    const long during = tamias2d::test::allocation_count() - before;
    // Positive control: the counter does see an allocation. Both counts are read before any
    // BOOST_TEST, whose logging (e.g. the JUnit logger at level all) allocates.
    void* volatile p = ::operator new(16);
    ::operator delete(p);
    const long control = tamias2d::test::allocation_count() - before - during;
    BOOST_TEST(during == 0);
    BOOST_TEST(control == 1);
}

// Oracle: IM4 over the fat boxes: BroadPhase::query visits both trees and stops on false.
BOOST_AUTO_TEST_CASE(query_both_trees, *utf::label("internals")) {
    BroadPhase bp(margin);
    const int s = bp.create_proxy({0.0, 0.0, 1.0, 1.0}, 1, true);
    const int d = bp.create_proxy({0.5, 0.0, 1.5, 1.0}, 2, false);
    std::vector<int> seen;
    bp.query({0.9, 0.5, 0.95, 0.6}, [&](int p) { seen.push_back(p); });
    std::sort(seen.begin(), seen.end());
    std::vector<int> want{s, d};
    std::sort(want.begin(), want.end());
    BOOST_TEST(seen == want);
    int calls = 0;
    bp.query({0.9, 0.5, 0.95, 0.6}, [&](int) {
        ++calls;
        return false;
    });
    BOOST_TEST(calls == 1);
    int rays = 0;
    bp.ray_cast({-1.0, 0.5}, {3.0, 0.0}, [&](int, double f) {
        ++rays;
        return f;
    });
    BOOST_TEST(rays == 2);
}

BOOST_AUTO_TEST_SUITE_END()
