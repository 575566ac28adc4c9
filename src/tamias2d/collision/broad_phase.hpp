// Broad phase: which shape pairs might touch. Each shape is a proxy with a fattened box in one
// of two dynamic AABB trees (static shapes in their own tree, so static-static pairs are never
// looked for). A proxy gets a new fat box only when its tight box leaves the old one, and only
// pairs with such a ("moved") proxy are looked for: a resting scene costs nothing here.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "tamias2d/collision/dynamic_tree.hpp"
#include "tamias2d/memory/allocator.hpp"

namespace tamias2d {

class SnapshotWriter;
class SnapshotReader;

class BroadPhase {
  public:
    /// Room for n proxies in either tree, and their moved flags, without growing.
    void reserve(std::size_t n) {
        trees_[0].reserve(n);
        trees_[1].reserve(n);
        move_buffer_.reserve(n);
        moved_.reserve(4 * n + 2); // proxy ids: node * 2 + tree
    }
    using Pair = std::pair<std::uint32_t, std::uint32_t>;

    /// `margin` (m) fattens every box, so small motions need no tree update; a box smaller
    /// than the margin is fattened less (fattened).
    explicit BroadPhase(double margin = 0.1) : margin_(margin) {}

    /// A proxy for a shape with tight box `tight` and user data `user` (the shape index).
    /// New proxies count as moved: the next update_pairs finds their pairs.
    int create_proxy(const Aabb& tight, std::uint32_t user, bool is_static = false);
    void destroy_proxy(int proxy);
    /// A new fat box (and marked moved) only when `tight` is no longer inside the fat one; the
    /// tree is rebuilt around it by the next update_pairs.
    void move_proxy(int proxy, const Aabb& tight);

    /// A proxy's new fat box, for a tight box that left its old one.
    struct ProxyMove {
        int proxy;
        Aabb fat; ///< fattened(tight)
    };
    /// The fat box move_proxy gives a proxy whose tight box left its old one: the tight box
    /// grown on each side by the margin, or, if smaller, by the larger of its own extent (its
    /// larger side) and the least margin. A fixed margin makes every pair of small shapes
    /// within it a pair: 5050 boxes of 1e-12 m in a pyramid 0.1 m wide made all 12.7 million
    /// pairs candidates with 0.1 m. Scaled, a small shape pairs only with shapes within its
    /// size or the least margin, the world's speculative distance: two shapes that close are
    /// always a pair, as the speculative contacts and the continuous pass (which stops a body
    /// a quarter of that distance short of a static shape) need.
    Aabb fattened(const Aabb& tight) const {
        const double extent = std::max(tight.max_x - tight.min_x, tight.max_y - tight.min_y);
        return inflated(tight, std::min(margin_, std::max(extent, least_margin_)));
    }
    /// The least margin (m, >= 0), for the proxies created or moved from now on.
    void set_least_margin(double least) { least_margin_ = least; }
    /// move_proxy for many proxies whose tight boxes left their fat boxes, in order, with the
    /// tree nodes asked for ahead: the world's write-back gathers its moves into one call, as
    /// each enlargement walks scattered nodes (rain_16k).
    void move_proxies(std::span<const ProxyMove> moves);
    /// Marks a proxy moved without moving it: the next update_pairs reports its pairs again
    /// (its shape's filter changed, so pairs once refused may now be wanted).
    void touch_proxy(int proxy) { mark_moved(proxy); }

    const Aabb& fat_aabb(int proxy) const { return tree(proxy).aabb(node(proxy)); }
    std::uint32_t user_data(int proxy) const { return tree(proxy).user_data(node(proxy)); }
    bool is_static(int proxy) const { return (proxy & 1) != 0; }

    /// Appends every pair of proxies whose fat boxes overlap (IM4) and of which at least one
    /// moved since the last call, once each, as (min user, max user), sorted; then forgets
    /// the moves. Static-static pairs are never reported. Allocation-free once `out` and the
    /// internal buffers have grown to the scene's size. A bad_alloc leaves `out` as it was and
    /// the moves for the next call.
    void update_pairs(memory::vector<Pair>& out);

    /// Calls f(proxy) for every proxy whose fat box overlaps `box` (IM4), dynamic tree first.
    /// f may return bool: false stops the query.
    template <class F> void query(const Aabb& box, F&& f) const;

    /// Calls f(proxy, max_fraction) -> double for proxies the segment crosses; see
    /// DynamicTree::ray_cast for the meaning of the return value.
    template <class F> void ray_cast(Vec2d origin, Vec2d translation, F&& f) const;

    /// Calls f(proxy, max_fraction) -> double for proxies whose fat boxes the box `box` meets
    /// as it moves along `translation` (DynamicTree::box_cast), dynamic tree first; f returns
    /// as for ray_cast.
    template <class F> void box_cast(const Aabb& box, Vec2d translation, F&& f) const;

    int proxy_count() const { return trees_[0].proxy_count() + trees_[1].proxy_count(); }
    double margin() const { return margin_; }
    const DynamicTree& dynamic_tree() const { return trees_[0]; }
    const DynamicTree& static_tree() const { return trees_[1]; }

    // --- snapshot (dynamics/snapshot_io.hpp) ---
    /// Writes the margins, both trees node for node, and the proxies moved since the last
    /// update_pairs (the move buffer and the flags), so that the next update_pairs reports the
    /// same pairs in the same order.
    void write(SnapshotWriter& out) const;
    /// Reads what write wrote into this broad phase; throws SnapshotError for a tree that is
    /// not one, or a moved flag that names no proxy.
    void read(SnapshotReader& in);
    /// Whether `proxy` names a proxy (a leaf of its tree) that has a moved flag.
    bool is_proxy(int proxy) const {
        return proxy >= 0 && std::size_t(proxy) < moved_.size() && tree(proxy).is_leaf(node(proxy));
    }

  private:
    // Proxy id = tree node id * 2 + (1 if static): no lookup table, and ids stay small.
    static int node(int proxy) { return proxy >> 1; }
    const DynamicTree& tree(int proxy) const { return trees_[proxy & 1]; }
    DynamicTree& tree(int proxy) { return trees_[proxy & 1]; }
    void mark_moved(int proxy);
    /// update_pairs' work, the pairs appended to `out` from index `first` on.
    void find_pairs(memory::vector<Pair>& out, std::size_t first);
    /// update_pairs' two searches for the pairs of the moved (marked) proxies.
    void query_moved(memory::vector<Pair>& out);
    void descend_marked(memory::vector<Pair>& out);
    /// The descent is chosen while the marks take at most this many nodes per moved proxy
    /// (2 is the least: a leaf and its share of the ancestors). Measured: 2.0-2.2 in a rain's
    /// free fall, where the descent was faster; 2.4-3.1 for every second, fourth or eighth box
    /// of a grid and 4.5-8 in a settled rain where a few boxes stir, where the queries were.
    static constexpr double marks_per_moved_for_descent = 2.3;

    double margin_;
    double least_margin_ = 0.0;
    DynamicTree trees_[2]; ///< [0] dynamic and kinematic, [1] static
    memory::vector<int> move_buffer_;
    /// Per proxy id: 0 not moved, 1 moved, 2 moved and marked, 3 moved and queried (the last
    /// two only within update_pairs).
    memory::vector<std::uint8_t> moved_;
};

template <class F> void BroadPhase::query(const Aabb& box, F&& f) const {
    bool go_on = true;
    for (int t = 0; t < 2 && go_on; ++t) {
        trees_[t].query(box, [&](int id) {
            const int proxy = id * 2 + t;
            if constexpr (std::is_same_v<std::invoke_result_t<F&, int>, void>) {
                f(proxy);
                return true;
            } else {
                go_on = f(proxy);
                return go_on;
            }
        });
    }
}

template <class F> void BroadPhase::ray_cast(Vec2d origin, Vec2d translation, F&& f) const {
    double best = 1.0; // fraction of the full ray still worth searching
    for (int t = 0; t < 2 && best > 0.0; ++t) {
        // The second tree casts the ray as clipped by the first: rescale its fractions.
        const double scale = best;
        trees_[t].ray_cast(origin, scale * translation, [&](int id, double tree_max) {
            const double v = f(id * 2 + t, tree_max * scale);
            best = v < best ? v : best;
            return v / scale;
        });
    }
}

template <class F> void BroadPhase::box_cast(const Aabb& box, Vec2d translation, F&& f) const {
    double best = 1.0; // as ray_cast: the second tree's cast clipped by the first's
    for (int t = 0; t < 2 && best > 0.0; ++t) {
        const double scale = best;
        trees_[t].box_cast(box, scale * translation, [&](int id, double tree_max) {
            const double v = f(id * 2 + t, tree_max * scale);
            best = v < best ? v : best;
            return v / scale;
        });
    }
}

} // namespace tamias2d
