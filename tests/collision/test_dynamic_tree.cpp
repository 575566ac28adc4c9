// Dynamic AABB tree: structure invariants under random updates, and queries equal to a
// brute-force scan with IM4's overlap test.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "tamias2d/collision/dynamic_tree.hpp"
#include "tamias2d/model/im4_aabb_overlap.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
namespace im4 = tamias2d::model::im4;

namespace {

Aabb random_box(std::mt19937_64& rng, double extent) {
    std::uniform_real_distribution<double> c(-extent, extent);
    std::uniform_real_distribution<double> s(0.05, 2.0);
    const double x = c(rng), y = c(rng), w = s(rng), h = s(rng);
    const auto b = im4::from_centre(x, y, w, h);
    return {b.min_x, b.min_y, b.max_x, b.max_y};
}

/// Segment-box overlap by the separating axis theorem (axes x, y and the segment normal);
/// an independent oracle for the tree's slab test.
bool segment_hits_box(Vec2d p, Vec2d d, const Aabb& b) {
    const double sx0 = std::min(p.x, p.x + d.x), sx1 = std::max(p.x, p.x + d.x);
    const double sy0 = std::min(p.y, p.y + d.y), sy1 = std::max(p.y, p.y + d.y);
    if (sx1 < b.min_x || sx0 > b.max_x || sy1 < b.min_y || sy0 > b.max_y)
        return false;
    const Vec2d c{0.5 * (b.min_x + b.max_x), 0.5 * (b.min_y + b.max_y)};
    const Vec2d h{0.5 * (b.max_x - b.min_x), 0.5 * (b.max_y - b.min_y)};
    const Vec2d n{-d.y, d.x};
    const double dist = std::abs(n.x * (c.x - p.x) + n.y * (c.y - p.y));
    return dist <= std::abs(n.x) * h.x + std::abs(n.y) * h.y;
}

/// The leaves a query reports, sorted.
std::vector<int> query_ids(const DynamicTree& tree, const Aabb& q) {
    std::vector<int> got;
    tree.query(q, [&](int id) { got.push_back(id); });
    std::sort(got.begin(), got.end());
    return got;
}

/// The oracle: every live box that overlaps q by IM4, sorted (live: pairs of id and box).
template <class Live> std::vector<int> brute_force_ids(const Live& live, const Aabb& q) {
    std::vector<int> want;
    for (const auto& [id, b] : live)
        if (im4::overlaps(b, q))
            want.push_back(id);
    std::sort(want.begin(), want.end());
    return want;
}

} // namespace

BOOST_AUTO_TEST_SUITE(dynamic_tree)

// Oracle: brute-force O(n^2)-free scan: a query returns exactly the live leaves whose boxes
// overlap the query box by IM4 (model::im4::overlaps), after random create/move/destroy, both
// with enlarged (loose) ancestors and after rebuilds.
BOOST_AUTO_TEST_CASE(query_equals_brute_force, *utf::label("IM4")) {
    std::mt19937_64 rng(11);
    DynamicTree tree;
    std::map<int, Aabb> live; // id -> box (oracle copy)
    std::uniform_int_distribution<int> op(0, 9);
    for (int step = 0; step < 4000; ++step) {
        const int o = op(rng);
        if (live.empty() || o < 5) {
            const Aabb b = random_box(rng, 30.0);
            const int id = tree.create_proxy(b, static_cast<std::uint32_t>(step));
            BOOST_TEST_REQUIRE(live.count(id) == 0u);
            live[id] = b;
        } else {
            auto it = live.begin();
            std::advance(it, std::uniform_int_distribution<int>(0, int(live.size()) - 1)(rng));
            if (o < 8) {
                const Aabb b = random_box(rng, 30.0);
                tree.enlarge_proxy(it->first, b);
                it->second = b;
                if (o == 7)
                    tree.rebuild();
            } else {
                tree.destroy_proxy(it->first);
                live.erase(it);
            }
        }
        if (step % 97 == 0) {
            BOOST_TEST_REQUIRE(tree.validate());
            BOOST_TEST(tree.proxy_count() == int(live.size()));
            const Aabb q = random_box(rng, 30.0);
            BOOST_TEST(query_ids(tree, q) == brute_force_ids(live, q));
            for (const auto& [id, b] : live)
                BOOST_TEST((tree.aabb(id).min_x == b.min_x && tree.aabb(id).max_y == b.max_y));
        }
    }
    // The rebuild's guarantee.
    tree.rebuild();
    BOOST_TEST_REQUIRE(tree.validate());
    BOOST_TEST(tree.height() <= tree.height_limit());
}

// Oracle: brute-force O(n^2) scan with IM4's overlap test (model::im4::overlaps): the
// marked-pair searches report exactly the pairs of live leaves, at least one of them marked,
// whose boxes overlap, each pair once, within one tree and across two; for none, few and most
// leaves marked, in trees that were enlarged and rebuilt; and the marks are gone after
// clear_marks.
BOOST_AUTO_TEST_CASE(marked_pairs_equal_brute_force, *utf::label("IM4")) {
    std::mt19937_64 rng(21);
    DynamicTree tree, other;
    std::map<int, Aabb> live, live_other;
    for (int i = 0; i < 600; ++i)
        live[tree.create_proxy(random_box(rng, 20.0), std::uint32_t(i))] = {};
    for (int i = 0; i < 60; ++i)
        live_other[other.create_proxy(random_box(rng, 20.0), std::uint32_t(i))] = {};
    for (auto& [id, b] : live)
        b = tree.aabb(id);
    for (auto& [id, b] : live_other)
        b = other.aabb(id);
    using Pairs = std::vector<std::pair<int, int>>;
    for (const double share : {0.0, 0.01, 0.1, 0.6, 1.0}) {
        // Move some leaves (loose ancestors, then the rebuild), and mark a share of both trees.
        std::bernoulli_distribution moves(0.2), marked(share);
        for (auto& [id, b] : live) {
            if (moves(rng)) {
                b = random_box(rng, 20.0);
                tree.enlarge_proxy(id, b);
            }
        }
        tree.rebuild();
        std::map<int, bool> mark, mark_other;
        for (const auto& [id, b] : live) {
            mark[id] = marked(rng);
            if (mark[id])
                tree.mark_leaf(id);
        }
        for (const auto& [id, b] : live_other) {
            mark_other[id] = marked(rng);
            if (mark_other[id])
                other.mark_leaf(id);
        }
        Pairs within, across;
        tree.for_each_marked_pair(
            [&](int a, int b) { within.emplace_back(std::min(a, b), std::max(a, b)); });
        tree.for_each_marked_pair(other, [&](int a, int b) { across.emplace_back(a, b); });
        tree.clear_marks();
        other.clear_marks();
        Pairs want_within, want_across;
        for (const auto& [a, ba] : live) {
            for (const auto& [b, bb] : live)
                if (a < b && (mark[a] || mark[b]) && im4::overlaps(ba, bb))
                    want_within.emplace_back(a, b);
            for (const auto& [b, bb] : live_other)
                if ((mark[a] || mark_other[b]) && im4::overlaps(ba, bb))
                    want_across.emplace_back(a, b);
        }
        const std::size_t reported_within = within.size(), reported_across = across.size();
        std::sort(within.begin(), within.end());
        std::sort(across.begin(), across.end());
        BOOST_TEST((within == want_within), "share " << share);
        BOOST_TEST((across == want_across), "share " << share);
        // Once each: sorting and removing duplicates would hide a pair reported twice.
        const auto distinct = [](Pairs& v) {
            return std::size_t(std::unique(v.begin(), v.end()) - v.begin());
        };
        BOOST_TEST(distinct(within) == reported_within);
        BOOST_TEST(distinct(across) == reported_across);
        if (share == 1.0) // a search that opened too little would show here, at the most pairs
            BOOST_TEST(want_within.size() > 100u);
        BOOST_TEST_REQUIRE(tree.validate());
    }
    // Cleared: nothing is marked, so nothing is reported.
    int reported = 0;
    tree.for_each_marked_pair([&](int, int) { ++reported; });
    tree.for_each_marked_pair(other, [&](int, int) { ++reported; });
    BOOST_TEST(reported == 0);
}

// Oracle: AVL height bound 1.44 log2(N + 2), N = 2n - 1 nodes for n leaves, for a tree built by
// insertions alone.
BOOST_AUTO_TEST_CASE(insertions_keep_the_tree_balanced, *utf::label("internals")) {
    std::mt19937_64 rng(3);
    DynamicTree tree;
    for (int i = 0; i < 3000; ++i)
        tree.create_proxy(random_box(rng, 30.0), static_cast<std::uint32_t>(i));
    BOOST_TEST_REQUIRE(tree.validate());
    const double n = double(tree.proxy_count());
    BOOST_TEST(tree.height() <= 1.45 * std::log2(2.0 * n + 2.0));
}

// Oracle: a rebuild with nothing marked changes nothing (a resting scene pays nothing): the
// height and the area ratio (sum of internal perimeters) stay bit for bit; one enlarged leaf
// marks its ancestors, and the rebuild clears the marks (validate checks they reach the root).
BOOST_AUTO_TEST_CASE(rebuild_touches_only_what_moved, *utf::label("internals")) {
    std::mt19937_64 rng(8);
    DynamicTree tree;
    std::vector<std::pair<int, Aabb>> live;
    for (int i = 0; i < 300; ++i) {
        const Aabb b = random_box(rng, 30.0);
        live.emplace_back(tree.create_proxy(b, static_cast<std::uint32_t>(i)), b);
    }
    const int height = tree.height();
    const double ratio = tree.area_ratio();
    tree.rebuild();
    BOOST_TEST(tree.height() == height);
    BOOST_TEST(tree.area_ratio() == ratio);

    auto& [id, b] = live[17];
    b = {b.min_x + 40.0, b.min_y, b.max_x + 40.0, b.max_y}; // 40 m right: mostly outside the root
    tree.enlarge_proxy(id, b);
    BOOST_TEST_REQUIRE(tree.validate());
    const Aabb q{69.0, -31.0, 72.0, 31.0};
    BOOST_TEST(query_ids(tree, q) == brute_force_ids(live, q));
    tree.rebuild();
    BOOST_TEST_REQUIRE(tree.validate());
    BOOST_TEST(query_ids(tree, q) == brute_force_ids(live, q));
    const Aabb all{-100.0, -100.0, 100.0, 100.0};
    BOOST_TEST(query_ids(tree, all).size() == live.size());
}

// Oracle: a median split halves the leaves, so a full rebuild has height ceil(log2 n). Boxes
// at exponentially spread places defeat the midpoint splits of a partial rebuild (each split
// peels off one box, height n - 1); the rebuild must catch that and stay within its limit.
BOOST_AUTO_TEST_CASE(rebuild_bounds_the_height, *utf::label("internals")) {
    DynamicTree tree;
    std::vector<std::pair<int, Aabb>> live;
    for (int i = 0; i < 48; ++i) {
        const Aabb b{double(i), 0.0, double(i) + 0.5, 0.5};
        live.emplace_back(tree.create_proxy(b, static_cast<std::uint32_t>(i)), b);
    }
    for (int i = 0; i < 48; ++i) {
        const double x = std::ldexp(1.0, i); // 1, 2, 4, ... 2^47 (+0.5 still exact)
        live[std::size_t(i)].second = {x, 0.0, x + 0.5, 0.5};
        tree.enlarge_proxy(live[std::size_t(i)].first, live[std::size_t(i)].second);
    }
    tree.rebuild();
    BOOST_TEST_REQUIRE(tree.validate());
    BOOST_TEST(tree.height() <= tree.height_limit());
    BOOST_TEST(tree.height() <= 6); // ceil(log2 48): the full rebuild's median splits
    for (int i = 0; i < 48; i += 5) {
        const double x = std::ldexp(1.0, i);
        const Aabb q{x + 0.1, 0.1, x + 0.2, 0.2};
        BOOST_TEST(query_ids(tree, q) == std::vector<int>{live[std::size_t(i)].first});
    }
}

// Oracle: the tree's own invariants (parents, heights, every box enclosing its children's,
// marks closed upwards: DynamicTree::validate) and a brute-force scan, after many small moves
// (each enlarging its ancestors) with a rebuild every 10, as a step would do.
BOOST_AUTO_TEST_CASE(small_moves_keep_the_tree_valid, *utf::label("IM4")) {
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    DynamicTree tree;
    std::vector<std::pair<int, Aabb>> live;
    for (int i = 0; i < 500; ++i) {
        const Aabb b = random_box(rng, 30.0);
        live.emplace_back(tree.create_proxy(b, static_cast<std::uint32_t>(i)), b);
    }
    std::uniform_int_distribution<std::size_t> pick(0, live.size() - 1);
    for (int step = 1; step <= 5000; ++step) {
        auto& [id, b] = live[pick(rng)];
        const double dx = jitter(rng), dy = jitter(rng);
        b = {b.min_x + dx, b.min_y + dy, b.max_x + dx, b.max_y + dy};
        tree.enlarge_proxy(id, b);
        if (step % 10 == 0)
            tree.rebuild();
        if (step % 50 == 0) {
            BOOST_TEST_REQUIRE(tree.validate());
            const Aabb q = random_box(rng, 30.0);
            BOOST_TEST(query_ids(tree, q) == brute_force_ids(live, q));
        }
    }
}

// Oracle: a query callback returning false stops the walk after one leaf.
BOOST_AUTO_TEST_CASE(query_can_stop_early, *utf::label("internals")) {
    DynamicTree tree;
    for (int i = 0; i < 50; ++i)
        tree.create_proxy({double(i) * 0.1, 0.0, double(i) * 0.1 + 1.0, 1.0}, std::uint32_t(i));
    int calls = 0;
    tree.query({0.0, 0.0, 10.0, 1.0}, [&](int) {
        ++calls;
        return false;
    });
    BOOST_TEST(calls == 1);
}

// Oracle: separating-axis segment/box test (segment_hits_box above): an unclipped ray cast
// visits exactly the leaves the segment crosses.
BOOST_AUTO_TEST_CASE(ray_cast_visits_crossed_leaves, *utf::label("IM4")) {
    std::mt19937_64 rng(5);
    DynamicTree tree;
    std::vector<Aabb> boxes;
    for (int i = 0; i < 400; ++i) {
        boxes.push_back(random_box(rng, 20.0));
        BOOST_TEST(tree.create_proxy(boxes.back(), std::uint32_t(i)) >= 0);
    }
    std::uniform_real_distribution<double> u(-25.0, 25.0);
    for (int trial = 0; trial < 200; ++trial) {
        const Vec2d p{u(rng), u(rng)};
        const Vec2d d{u(rng), u(rng)};
        std::vector<std::uint32_t> got;
        tree.ray_cast(p, d, [&](int id, double max_fraction) {
            got.push_back(tree.user_data(id));
            return max_fraction;
        });
        std::sort(got.begin(), got.end());
        std::vector<std::uint32_t> want;
        for (std::uint32_t i = 0; i < boxes.size(); ++i)
            if (segment_hits_box(p, d, boxes[i]))
                want.push_back(i);
        BOOST_TEST(got == want);
    }
}

BOOST_AUTO_TEST_SUITE_END()
