#include "tamias2d/collision/dynamic_tree.hpp"

#include <algorithm>
#include <bit>
#include <string>

#include "tamias2d/dynamics/snapshot_io.hpp"

namespace tamias2d {

int DynamicTree::allocate_node() {
    if (free_list_ == null_node) {
        nodes_.emplace_back();
        return static_cast<int>(nodes_.size()) - 1;
    }
    const int id = free_list_;
    free_list_ = nodes_[id].parent;
    nodes_[id] = Node{};
    return id;
}

void DynamicTree::free_node(int id) {
    nodes_[id] = Node{};
    nodes_[id].parent = free_list_; // height -1 marks it free
    free_list_ = id;
}

int DynamicTree::create_proxy(const Aabb& box, std::uint32_t user) {
    const int id = allocate_node();
    nodes_[id].box = box;
    nodes_[id].user = user;
    nodes_[id].height = 0;
    insert_leaf(id);
    ++proxy_count_;
    if (height() > height_limit()) // an insertion into a tree a rebuild left near its limit
        rebuild_all();
    return id;
}

void DynamicTree::destroy_proxy(int id) {
    remove_leaf(id);
    free_node(id);
    --proxy_count_;
}

void DynamicTree::enlarge_proxy(int id, const Aabb& box) {
    nodes_[id].box = box;
    // Grow the ancestors until one already holds the box, and mark them up to the first one
    // marked before (its ancestors are marked: the marks are closed upwards).
    for (int i = nodes_[id].parent; i != null_node; i = nodes_[i].parent) {
        Node& n = nodes_[i];
        const bool holds = contains(n.box, box);
        if (holds && n.enlarged)
            return;
        if (!holds)
            n.box = union_of(n.box, box);
        n.enlarged = true;
    }
}

void DynamicTree::mark_leaf(int id) {
    // Room for every node, so that a step marking more than any before does not allocate (only a
    // growing tree does).
    if (marked_.capacity() < nodes_.size())
        marked_.reserve(nodes_.size());
    // Up to the first node marked before: its ancestors are marked already.
    for (int i = id; i != null_node && !nodes_[i].marked; i = nodes_[i].parent) {
        nodes_[i].marked = true;
        marked_.push_back(i);
    }
}

void DynamicTree::clear_marks() {
    for (const int i : marked_)
        nodes_[i].marked = false;
    marked_.clear();
}

int DynamicTree::height_limit() const {
    return 2 * std::bit_width(static_cast<unsigned>(proxy_count_)) + 8;
}

void DynamicTree::rebuild() {
    if (root_ == null_node || !nodes_[root_].enlarged)
        return;
    // Free the marked nodes; keep what hangs below them. (The walk's stack suffices: every
    // operation leaves the height within height_limit().)
    items_.clear();
    spare_bits_.resize((nodes_.size() + 63) / 64); // grows with the tree only
    std::array<int, max_stack> stack;
    int top = 0;
    stack[top++] = root_;
    while (top > 0) {
        const int i = stack[--top];
        const Node& n = nodes_[i];
        if (n.leaf() || !n.enlarged) {
            items_.push_back(item(i));
            continue;
        }
        stack[top++] = n.child1;
        stack[top++] = n.child2;
        spare_bits_[std::size_t(i) >> 6] |= std::uint64_t{1} << (i & 63);
    }
    // m kept subtrees need the m - 1 nodes just freed: the array does not grow. They are
    // handed out in ascending order (a scan of the bits), so the new nodes lie in memory in
    // the order a query descends them.
    spare_.clear();
    for (std::size_t w = 0; w < spare_bits_.size(); ++w) {
        for (std::uint64_t bits = spare_bits_[w]; bits != 0; bits &= bits - 1)
            spare_.push_back(static_cast<int>(w * 64 + std::size_t(std::countr_zero(bits))));
        spare_bits_[w] = 0;
    }
    next_spare_ = 0;
    root_ = build(0, items_.size(), false);
    nodes_[root_].parent = null_node;
    // Midpoint splits of stacked partial rebuilds could grow the height without bound; a
    // full rebuild resets it to ceil(log2 n). The benchmark scenes never need one.
    if (height() > height_limit())
        rebuild_all();
}

void DynamicTree::rebuild_all() {
    // A scan of the array, not a walk: the tree may be taller than the walks' stack here.
    items_.clear();
    spare_.clear();
    for (int i = 0; i < static_cast<int>(nodes_.size()); ++i) {
        if (nodes_[i].height == 0)
            items_.push_back(item(i));
        else if (nodes_[i].height > 0)
            spare_.push_back(i);
    }
    next_spare_ = 0;
    if (items_.empty())
        return;
    root_ = build(0, items_.size(), true);
    nodes_[root_].parent = null_node;
}

// Splits items [begin, end) along the wider axis of their centres' bounds and joins the two
// halves' trees under a new node. A partial rebuild splits at the bounds' midpoint (one pass;
// Box2D v3's default), a full one at the median (a guaranteed height of ceil(log2 m)). Median
// ties go by node id, so the halves do not depend on how nth_element orders equal keys.
int DynamicTree::build(std::size_t begin, std::size_t end, bool median) {
    if (end - begin == 1)
        return items_[begin].node;
    double lo_x = items_[begin].x, hi_x = lo_x, lo_y = items_[begin].y, hi_y = lo_y;
    for (std::size_t k = begin + 1; k < end; ++k) {
        lo_x = std::min(lo_x, items_[k].x);
        hi_x = std::max(hi_x, items_[k].x);
        lo_y = std::min(lo_y, items_[k].y);
        hi_y = std::max(hi_y, items_[k].y);
    }
    const bool along_x = hi_x - lo_x >= hi_y - lo_y;
    const auto first = items_.begin() + static_cast<std::ptrdiff_t>(begin);
    const auto last = items_.begin() + static_cast<std::ptrdiff_t>(end);
    auto mid = first;
    if (!median) {
        const double cut = along_x ? 0.5 * (lo_x + hi_x) : 0.5 * (lo_y + hi_y);
        mid = std::partition(first, last,
                             [along_x, cut](const Item& a) { return (along_x ? a.x : a.y) < cut; });
    }
    if (mid == first || mid == last) { // all centres equal along the axis, or a median split
        mid = first + (last - first) / 2;
        std::nth_element(first, mid, last, [along_x](const Item& a, const Item& b) {
            const double ka = along_x ? a.x : a.y, kb = along_x ? b.x : b.y;
            return ka < kb || (ka == kb && a.node < b.node);
        });
    }
    const std::size_t split = static_cast<std::size_t>(mid - items_.begin());
    // The parent before its children (pre-order): a query reads them in that order.
    const int p = spare_[next_spare_++];
    nodes_[p] = Node{};
    const int c1 = build(begin, split, median);
    const int c2 = build(split, end, median);
    nodes_[p].child1 = c1;
    nodes_[p].child2 = c2;
    nodes_[c1].parent = p;
    nodes_[c2].parent = p;
    return refit(p);
}

void DynamicTree::insert_leaf(int leaf) {
    if (root_ == null_node) {
        root_ = leaf;
        nodes_[leaf].parent = null_node;
        return;
    }
    // Descend towards the sibling whose pairing with the leaf adds the least perimeter
    // (perimeter stands in for surface area in 2D: it predicts how often a box is hit).
    const Aabb box = nodes_[leaf].box;
    int index = root_;
    while (!nodes_[index].leaf()) {
        const Node& n = nodes_[index];
        const double here = perimeter(n.box);
        const double combined = perimeter(union_of(n.box, box));
        // Pairing with this whole subtree: a new parent of perimeter `combined`.
        const double cost = 2.0 * combined;
        // Going deeper still enlarges this node (and every ancestor) by the same amount.
        const double inherited = 2.0 * (combined - here);
        auto descend_cost = [&](int c) {
            const Node& child = nodes_[c];
            const double grown = perimeter(union_of(child.box, box));
            return (child.leaf() ? grown : grown - perimeter(child.box)) + inherited;
        };
        const double cost1 = descend_cost(n.child1);
        const double cost2 = descend_cost(n.child2);
        if (cost < cost1 && cost < cost2)
            break;
        index = cost1 < cost2 ? n.child1 : n.child2;
    }
    const int sibling = index;

    const int old_parent = nodes_[sibling].parent;
    const int parent = allocate_node();
    nodes_[parent].parent = old_parent;
    nodes_[parent].box = union_of(box, nodes_[sibling].box);
    nodes_[parent].height = nodes_[sibling].height + 1;
    nodes_[parent].child1 = sibling;
    nodes_[parent].child2 = leaf;
    nodes_[parent].enlarged = nodes_[sibling].enlarged; // keeps the marks closed upwards
    nodes_[sibling].parent = parent;
    nodes_[leaf].parent = parent;
    if (old_parent == null_node) {
        root_ = parent;
    } else if (nodes_[old_parent].child1 == sibling) {
        nodes_[old_parent].child1 = parent;
    } else {
        nodes_[old_parent].child2 = parent;
    }

    // The new parent may be unbalanced (a tall sibling); above it, refit until nothing changes.
    const int top = refit(balance(parent));
    refit_ancestors(nodes_[top].parent);
}

void DynamicTree::remove_leaf(int leaf) {
    if (leaf == root_) {
        root_ = null_node;
        return;
    }
    const int parent = nodes_[leaf].parent;
    const int grand = nodes_[parent].parent;
    const int sibling =
        nodes_[parent].child1 == leaf ? nodes_[parent].child2 : nodes_[parent].child1;
    free_node(parent);
    nodes_[leaf].parent = null_node;
    if (grand == null_node) {
        root_ = sibling;
        nodes_[sibling].parent = null_node;
        return;
    }
    if (nodes_[grand].child1 == parent)
        nodes_[grand].child1 = sibling;
    else
        nodes_[grand].child2 = sibling;
    nodes_[sibling].parent = grand;
    refit_ancestors(grand);
}

int DynamicTree::refit(int i) {
    Node& n = nodes_[i];
    n.height = 1 + std::max(nodes_[n.child1].height, nodes_[n.child2].height);
    n.box = union_of(nodes_[n.child1].box, nodes_[n.child2].box);
    return i;
}

void DynamicTree::refit_ancestors(int i) {
    // Rebalance and refit on the way up, and stop at the first node whose box and height come
    // out as they were: its ancestors enclose the same boxes at the same heights, so no box or
    // rotation above would change (Box2D 2.4 walks to the root).
    while (i != null_node) {
        const Aabb box = nodes_[i].box;
        const int height = nodes_[i].height;
        i = refit(balance(i));
        const Node& n = nodes_[i];
        if (n.height == height && n.box.min_x == box.min_x && n.box.min_y == box.min_y &&
            n.box.max_x == box.max_x && n.box.max_y == box.max_y)
            return;
        i = n.parent;
    }
}

// If one child of a is two levels taller than the other, lift the taller child into a's
// place (an AVL rotation) and hand a the shorter of its grandchildren. Returns the subtree's
// new root.
int DynamicTree::balance(int a) {
    if (nodes_[a].leaf() || nodes_[a].height < 2)
        return a;
    const int b = nodes_[a].child1;
    const int c = nodes_[a].child2;
    const int skew = nodes_[c].height - nodes_[b].height;
    if (skew >= -1 && skew <= 1)
        return a;

    const int up = skew > 1 ? c : b;   // the child that rises
    const int stay = skew > 1 ? b : c; // a's other child, kept
    const int f = nodes_[up].child1;
    const int g = nodes_[up].child2;
    // `up` takes a's place under a's parent.
    nodes_[up].parent = nodes_[a].parent;
    nodes_[a].parent = up;
    nodes_[up].enlarged = nodes_[up].enlarged || nodes_[a].enlarged; // up is a's parent now
    const int ap = nodes_[up].parent;
    if (ap == null_node) {
        root_ = up;
    } else if (nodes_[ap].child1 == a) {
        nodes_[ap].child1 = up;
    } else {
        nodes_[ap].child2 = up;
    }
    // The taller grandchild stays under `up`; the shorter moves under a.
    const int keep = nodes_[f].height > nodes_[g].height ? f : g;
    const int give = keep == f ? g : f;
    nodes_[up].child1 = a;
    nodes_[up].child2 = keep;
    if (skew > 1)
        nodes_[a].child2 = give;
    else
        nodes_[a].child1 = give;
    nodes_[give].parent = a;
    nodes_[a].box = union_of(nodes_[stay].box, nodes_[give].box);
    nodes_[a].height = 1 + std::max(nodes_[stay].height, nodes_[give].height);
    nodes_[up].box = union_of(nodes_[a].box, nodes_[keep].box);
    nodes_[up].height = 1 + std::max(nodes_[a].height, nodes_[keep].height);
    return up;
}

double DynamicTree::area_ratio() const {
    if (root_ == null_node)
        return 0.0;
    double total = 0.0;
    for (const Node& n : nodes_)
        if (n.height > 0)
            total += perimeter(n.box);
    return total / perimeter(nodes_[root_].box);
}

int DynamicTree::validate_subtree(int id, int parent) const {
    const Node& n = nodes_[id];
    if (n.parent != parent || n.height < 0)
        return -1;
    if (n.enlarged && parent != null_node && !nodes_[parent].enlarged)
        return -1; // a mark the rebuild would not reach
    if (n.leaf())
        return n.height == 0 && n.child2 == null_node && !n.enlarged ? 1 : -1;
    const Node& c1 = nodes_[n.child1];
    const Node& c2 = nodes_[n.child2];
    if (n.height != 1 + std::max(c1.height, c2.height))
        return -1;
    if (!contains(n.box, c1.box) || !contains(n.box, c2.box))
        return -1;
    const int k1 = validate_subtree(n.child1, id);
    const int k2 = validate_subtree(n.child2, id);
    return k1 < 0 || k2 < 0 ? -1 : 1 + k1 + k2;
}

bool DynamicTree::validate() const {
    int reachable = 0;
    if (root_ != null_node) {
        reachable = validate_subtree(root_, null_node);
        if (reachable < 0)
            return false;
    }
    int free_count = 0;
    for (int i = free_list_; i != null_node; i = nodes_[i].parent) {
        if (nodes_[i].height != -1)
            return false;
        ++free_count;
    }
    const int leaves = root_ == null_node ? 0 : (reachable + 1) / 2;
    return reachable + free_count == static_cast<int>(nodes_.size()) && leaves == proxy_count_;
}

// --- snapshot ---

namespace {

/// Every field of a tree node, in the snapshot's order (the writer and the reader both call it).
template <class IO, class N> void node_fields(IO& io, N& n) {
    io("box", n.box);
    io("parent", n.parent);
    io("child1", n.child1);
    io("child2", n.child2);
    io("height", n.height);
    io("user", n.user);
    io("enlarged", n.enlarged);
    io("marked", n.marked);
}

} // namespace

void DynamicTree::write(SnapshotWriter& out) const {
    out.count("nodes", nodes_.size());
    for (const Node& n : nodes_)
        node_fields(out, n);
    out("root", root_);
    out("free_list", free_list_);
    out("proxy_count", proxy_count_);
}

void DynamicTree::read(SnapshotReader& in) {
    const std::size_t n = in.count("nodes", 56, std::size_t{1} << 30);
    nodes_.resize(n);
    const auto link_ok = [n](int v) { return v == null_node || (v >= 0 && std::size_t(v) < n); };
    for (std::size_t i = 0; i < n; ++i) {
        in.in("tree.nodes", i);
        const std::size_t at = in.offset();
        Node& node = nodes_[i];
        node_fields(in, node);
        if (!(link_ok(node.parent) && link_ok(node.child1) && link_ok(node.child2) &&
              (node.child1 == null_node) == (node.child2 == null_node) && node.height >= -1 &&
              node.height < max_stack / 2)) // (message built only to fail)
            in.fail_at(at, "",
                       "links must be -1 or < " + decimal(std::uint64_t(n)) +
                           ", both children or none, height in [-1, " +
                           decimal(std::uint64_t(max_stack / 2)) + ")");
    }
    in.in(nullptr);
    const std::size_t at = in.offset();
    in("tree.root", root_);
    in("tree.free_list", free_list_);
    in("tree.proxy_count", proxy_count_);
    // The free list ends (null_node) within n links before validate() walks it.
    int i = link_ok(free_list_) ? free_list_ : null_node;
    std::size_t free = 0;
    for (; i != null_node && link_ok(i) && free <= n; i = nodes_[std::size_t(i)].parent)
        ++free;
    const bool free_list_ends = link_ok(free_list_) && i == null_node;
    in.require(link_ok(root_) && free_list_ends && validate(), "tree",
               "must be a valid tree (links, heights, boxes, free list and leaf count agree)", at);
}

} // namespace tamias2d
