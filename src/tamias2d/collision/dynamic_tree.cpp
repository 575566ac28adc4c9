#include "tamias2d/collision/dynamic_tree.hpp"

#include <algorithm>

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
    return id;
}

void DynamicTree::destroy_proxy(int id) {
    remove_leaf(id);
    free_node(id);
    --proxy_count_;
}

void DynamicTree::move_proxy(int id, const Aabb& box) {
    remove_leaf(id);
    nodes_[id].box = box;
    insert_leaf(id);
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
    // out as they were: its ancestors enclose the same boxes at the same heights, and the tree
    // was balanced everywhere, so nothing above would change (Box2D 2.4 walks to the root).
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
    if (n.leaf())
        return n.height == 0 && n.child2 == null_node ? 1 : -1;
    const Node& c1 = nodes_[n.child1];
    const Node& c2 = nodes_[n.child2];
    if (n.height != 1 + std::max(c1.height, c2.height))
        return -1;
    if (std::abs(c1.height - c2.height) > 1)
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

} // namespace tamias2d
