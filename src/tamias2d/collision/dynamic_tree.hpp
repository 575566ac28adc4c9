// A dynamic AABB tree: a binary bounding-volume hierarchy over boxes that move. Leaves are
// inserted where they enlarge the tree's surface least (a greedy surface-area heuristic) and
// AVL-style rotations keep it balanced, so queries and updates cost O(log n). A moved leaf is
// not re-inserted: its ancestors are only enlarged to hold its new box and marked, and one
// rebuild per step rebuilds the marked top of the tree over the unmarked subtrees below it
// (Box2D v3's scheme). A re-insertion walked about 45 scattered nodes, each a cache miss once
// the tree outgrows the caches; the rebuild partitions a compact array instead. Nodes live in
// one array with a free list; queries walk it with a fixed stack and never allocate.
#pragma once

#include <array>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include "tamias2d/geometry/aabb.hpp"
#include "tamias2d/math/prefetch.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/memory/large_array.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

class SnapshotWriter;
class SnapshotReader;

class DynamicTree {
  public:
    /// Room for n proxies' nodes (2 n - 1: leaves and branches) without growing.
    void reserve(std::size_t n) {
        nodes_.reserve(2 * n);
        marked_.reserve(2 * n);
    }
    static constexpr int null_node = -1;
    /// Enough for any AVL-balanced tree that fits in memory (height <= 1.44 log2 n).
    static constexpr int max_stack = 256;

    /// A leaf holding `box`; returns its id (stable until destroyed, then reused).
    int create_proxy(const Aabb& box, std::uint32_t user);
    void destroy_proxy(int id);
    /// Replaces a leaf's box. Its ancestors grow to hold the box and are marked for the next
    /// rebuild(); until then the tree stays correct, only looser.
    void enlarge_proxy(int id, const Aabb& box);
    /// Rebuilds the marked nodes (ancestors of enlarged leaves) top-down over the unmarked
    /// subtrees they hold, splitting at midpoints: O(m log m) for m such subtrees, nothing if
    /// none is marked. Allocation-free once the scratch has grown to the tree's size.
    void rebuild();
    /// Cache hints for a coming enlarge_proxy(id): the leaf's node, the parent's.
    void prefetch_node(int id) const { tamias2d::prefetch(&nodes_[id]); }
    void prefetch_parent(int id) const {
        const int p = nodes_[id].parent;
        if (p != null_node)
            tamias2d::prefetch(&nodes_[p]);
    }

    const Aabb& aabb(int id) const { return nodes_[id].box; }
    std::uint32_t user_data(int id) const { return nodes_[id].user; }

    /// Calls f(id) for every leaf whose box overlaps `box` by IM4. f may return bool:
    /// false stops the query.
    template <class F> void query(const Aabb& box, F&& f) const;

    /// Marks a leaf, and its ancestors, for the marked-pair searches below (until
    /// clear_marks()). Call after rebuild(): a rebuild frees ancestors.
    void mark_leaf(int id);
    void clear_marks();
    /// Nodes marked since clear_marks (leaves and their ancestors).
    std::size_t marked_count() const { return marked_.size(); }
    /// Calls f(a, b) once for every two distinct leaves of this tree whose boxes overlap (IM4),
    /// at least one of them marked: one descent of the tree against itself, where pairs of
    /// unmarked subtrees are never opened and the levels above the leaves are walked once for
    /// all marked leaves, not once per leaf from the root as query() does.
    template <class F> void for_each_marked_pair(F&& f);
    /// The same for a leaf a of this tree and a leaf b of `other`.
    template <class F> void for_each_marked_pair(const DynamicTree& other, F&& f);

    /// Calls f(id, max_fraction) -> double for every leaf whose box the segment
    /// origin -> origin + max_fraction * translation crosses. f returns the new max fraction
    /// (the hit fraction clips the ray, max_fraction continues, 0 stops).
    template <class F> void ray_cast(Vec2d origin, Vec2d translation, F&& f) const;

    /// Calls f(id, max_fraction) -> double for every leaf whose box the box `box` moved along
    /// origin... translation (its centre from the box's centre to centre + max_fraction *
    /// translation) meets: the segment of its centre against the leaves' boxes grown by its
    /// half extents (their Minkowski sum). f returns as for ray_cast: the shape casts' walk.
    template <class F> void box_cast(const Aabb& box, Vec2d translation, F&& f) const;

    int proxy_count() const { return proxy_count_; }
    int height() const { return root_ == null_node ? 0 : nodes_[root_].height; }
    /// The height rebuilds and insertions leave the tree within, far below max_stack: beyond
    /// it (stacked partial rebuilds, whose midpoint splits do not balance), all is rebuilt.
    int height_limit() const;
    /// Sum of internal node perimeters over the root's: a quality measure (lower is better).
    double area_ratio() const;
    /// Checks parent links, heights, enclosure, that marks reach the root, and the free list
    /// (tests).
    bool validate() const;

    // --- snapshot (dynamics/snapshot_io.hpp) ---
    /// Writes the nodes as they are (boxes, links, heights, users, marks), the root, the free
    /// list and the leaf count: a tree read back is the same tree, node for node, so that its
    /// queries, rebuilds and pair searches continue with the same bits.
    void write(SnapshotWriter& out) const;
    /// Reads what write wrote into this tree; throws SnapshotError unless every link is in
    /// range, the free list ends, and the tree passes validate() (no cycle, heights and boxes
    /// consistent, no deeper than a query's stack holds).
    void read(SnapshotReader& in);
    /// Whether node `id` exists and is a leaf (a proxy).
    bool is_leaf(int id) const {
        return id >= 0 && std::size_t(id) < nodes_.size() && nodes_[id].height == 0;
    }

  private:
    /// One cache line each: at 56 bytes most nodes straddled two lines, and a query or an
    /// insertion visits dozens of scattered nodes (rain_16k: -4 to -10 % per step).
    struct alignas(64) Node {
        Aabb box{};
        int parent = null_node; ///< or the next free node
        int child1 = null_node;
        int child2 = null_node;
        int height = -1; ///< 0 leaf, -1 free
        std::uint32_t user = 0;
        /// Enlarged since the last rebuild: its box may be loose. Every enlarged node's parent
        /// is enlarged too, so a rebuild finds them all from the root.
        bool enlarged = false;
        /// A marked leaf is in its subtree (mark_leaf): the marked-pair searches open it.
        bool marked = false;
        bool leaf() const { return child1 == null_node; }
    };
    /// A subtree the rebuild keeps, by its box's centre (a compact copy the splits partition).
    struct Item {
        double x, y;
        int node;
    };

    int allocate_node();
    void free_node(int id);
    void insert_leaf(int leaf);
    void remove_leaf(int leaf);
    int balance(int a);
    /// Recomputes node i's height and box from its children; returns i.
    int refit(int i);
    void refit_ancestors(int i);
    int validate_subtree(int id, int parent) const;
    void rebuild_all();
    Item item(int node) const {
        const Aabb& b = nodes_[node].box;
        return {0.5 * (b.min_x + b.max_x), 0.5 * (b.min_y + b.max_y), node};
    }
    int build(std::size_t begin, std::size_t end, bool median);
    /// The marked-pair searches' walk over pair_stack_ (with `self`, (a, a) stands for the
    /// pairs within a's subtree).
    template <class F> void descend_pairs(const DynamicTree& other, bool self, F& f);
    /// Room for the walk's deepest stack, so that it never allocates midway: a walk takes at
    /// most self_levels steps within one subtree, then cross_levels opening one side of a pair,
    /// and each step leaves at most two pairs behind it.
    void reserve_pair_stack(int self_levels, int cross_levels) {
        pair_stack_.reserve(std::size_t(2 * (self_levels + cross_levels) + 3));
    }

    LargeArray<Node> nodes_;
    int root_ = null_node;
    int free_list_ = null_node;
    int proxy_count_ = 0;
    memory::vector<Item> items_; ///< rebuild scratch
    /// Rebuild scratch: the freed nodes (one bit per node, then ascending), reused by build.
    memory::vector<std::uint64_t> spare_bits_;
    memory::vector<int> spare_;
    std::size_t next_spare_ = 0;
    memory::vector<int> marked_; ///< the nodes mark_leaf marked, for clear_marks
    /// The marked-pair searches' stack: node pairs still to open (this tree's, other's).
    memory::vector<std::pair<int, int>> pair_stack_;
};

namespace detail {
/// The segment o + t d, t in [0, t_max], crosses box b (slab test; closed box).
inline bool segment_crosses(const Aabb& b, Vec2d o, Vec2d d, double t_max) {
    double lo = 0.0;
    double hi = t_max;
    const double os[2] = {o.x, o.y};
    const double ds[2] = {d.x, d.y};
    const double mins[2] = {b.min_x, b.min_y};
    const double maxs[2] = {b.max_x, b.max_y};
    for (int k = 0; k < 2; ++k) {
        if (ds[k] == 0.0) {
            if (os[k] < mins[k] || os[k] > maxs[k])
                return false;
            continue;
        }
        double t1 = (mins[k] - os[k]) / ds[k];
        double t2 = (maxs[k] - os[k]) / ds[k];
        if (t1 > t2)
            std::swap(t1, t2);
        lo = t1 > lo ? t1 : lo;
        hi = t2 < hi ? t2 : hi;
        if (lo > hi)
            return false;
    }
    return true;
}
} // namespace detail

template <class F> void DynamicTree::query(const Aabb& box, F&& f) const {
    if (root_ == null_node)
        return;
    std::array<int, max_stack> stack;
    int top = 0;
    stack[top++] = root_;
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        if (!overlaps(n.box, box))
            continue;
        if (n.leaf()) {
            const int id = static_cast<int>(&n - nodes_.data());
            if constexpr (std::is_same_v<std::invoke_result_t<F&, int>, void>) {
                f(id);
            } else {
                if (!f(id))
                    return;
            }
        } else {
            stack[top++] = n.child1;
            stack[top++] = n.child2;
        }
    }
}

template <class F> void DynamicTree::descend_pairs(const DynamicTree& other, bool self, F& f) {
    while (!pair_stack_.empty()) {
        const auto [a, b] = pair_stack_.back();
        pair_stack_.pop_back();
        const Node& na = nodes_[a];
        if (self && a == b) {
            if (na.leaf() || !na.marked)
                continue;
            pair_stack_.push_back({na.child1, na.child1});
            pair_stack_.push_back({na.child2, na.child2});
            pair_stack_.push_back({na.child1, na.child2});
            continue;
        }
        const Node& nb = other.nodes_[b];
        if (!(na.marked || nb.marked) || !overlaps(na.box, nb.box))
            continue;
        if (na.leaf() && nb.leaf()) {
            f(a, b);
        } else if (nb.leaf() || (!na.leaf() && perimeter(na.box) >= perimeter(nb.box))) {
            // Open the larger box, so that the two shrink together.
            pair_stack_.push_back({na.child1, b});
            pair_stack_.push_back({na.child2, b});
        } else {
            pair_stack_.push_back({a, nb.child1});
            pair_stack_.push_back({a, nb.child2});
        }
    }
}

template <class F> void DynamicTree::for_each_marked_pair(F&& f) {
    if (root_ == null_node)
        return;
    reserve_pair_stack(height(), height());
    pair_stack_.push_back({root_, root_});
    descend_pairs(*this, true, f);
}

template <class F> void DynamicTree::for_each_marked_pair(const DynamicTree& other, F&& f) {
    if (root_ == null_node || other.root_ == null_node)
        return;
    reserve_pair_stack(0, height() + other.height());
    pair_stack_.push_back({root_, other.root_});
    descend_pairs(other, false, f);
}

template <class F> void DynamicTree::ray_cast(Vec2d origin, Vec2d translation, F&& f) const {
    if (root_ == null_node)
        return;
    double max_fraction = 1.0;
    std::array<int, max_stack> stack;
    int top = 0;
    stack[top++] = root_;
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        if (!detail::segment_crosses(n.box, origin, translation, max_fraction))
            continue;
        if (n.leaf()) {
            const double v = f(static_cast<int>(&n - nodes_.data()), max_fraction);
            if (v <= 0.0)
                return;
            if (v < max_fraction)
                max_fraction = v;
        } else {
            stack[top++] = n.child1;
            stack[top++] = n.child2;
        }
    }
}

template <class F> void DynamicTree::box_cast(const Aabb& box, Vec2d translation, F&& f) const {
    if (root_ == null_node)
        return;
    const Vec2d centre{0.5 * (box.min_x + box.max_x), 0.5 * (box.min_y + box.max_y)};
    const double hx = 0.5 * (box.max_x - box.min_x), hy = 0.5 * (box.max_y - box.min_y);
    double max_fraction = 1.0;
    std::array<int, max_stack> stack;
    int top = 0;
    stack[top++] = root_;
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        const Aabb grown{n.box.min_x - hx, n.box.min_y - hy, n.box.max_x + hx, n.box.max_y + hy};
        if (!detail::segment_crosses(grown, centre, translation, max_fraction))
            continue;
        if (n.leaf()) {
            const double v = f(static_cast<int>(&n - nodes_.data()), max_fraction);
            if (v <= 0.0)
                return;
            if (v < max_fraction)
                max_fraction = v;
        } else {
            stack[top++] = n.child1;
            stack[top++] = n.child2;
        }
    }
}

} // namespace tamias2d
