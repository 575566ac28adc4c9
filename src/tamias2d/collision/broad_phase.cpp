#include "tamias2d/collision/broad_phase.hpp"

#include <algorithm>
#include <string>

#include "tamias2d/dynamics/snapshot_io.hpp"
#include "tamias2d/memory/allocator.hpp"

namespace tamias2d {

namespace {

/// A pair as update_pairs reports it: (min user, max user).
void emit_pair(memory::vector<BroadPhase::Pair>& out, std::uint32_t u, std::uint32_t v) {
    out.emplace_back(std::min(u, v), std::max(u, v));
}

} // namespace

void BroadPhase::mark_moved(int proxy) {
    if (moved_[proxy] == 0) {
        moved_[proxy] = 1;
        move_buffer_.push_back(proxy);
    }
}

int BroadPhase::create_proxy(const Aabb& tight, std::uint32_t user, bool is_static) {
    const int t = is_static ? 1 : 0;
    const int proxy = trees_[t].create_proxy(fattened(tight), user) * 2 + t;
    if (std::size_t(proxy) >= moved_.size())
        moved_.resize(std::size_t(proxy) + 2, 0);
    moved_[proxy] = 0; // an id freed earlier may have been left marked
    mark_moved(proxy);
    return proxy;
}

void BroadPhase::destroy_proxy(int proxy) {
    // Its move-buffer entry (if any) is skipped by update_pairs: flag 0 means "not moved".
    moved_[proxy] = 0;
    tree(proxy).destroy_proxy(node(proxy));
}

void BroadPhase::move_proxy(int proxy, const Aabb& tight) {
    if (contains(fat_aabb(proxy), tight))
        return;
    const ProxyMove move{proxy, fattened(tight)};
    move_proxies({&move, 1});
}

void BroadPhase::move_proxies(std::span<const ProxyMove> moves) {
    // The leaf eight moves ahead, its parent four ahead (the leaf has arrived by then); the
    // ancestors above are mostly shared with the neighbours just enlarged.
    constexpr std::size_t leaf_ahead = 8, parent_ahead = 4;
    for (std::size_t i = 0; i < moves.size(); ++i) {
        if (i + leaf_ahead < moves.size()) {
            const int p = moves[i + leaf_ahead].proxy;
            tree(p).prefetch_node(node(p));
        }
        if (i + parent_ahead < moves.size()) {
            const int p = moves[i + parent_ahead].proxy;
            tree(p).prefetch_parent(node(p));
        }
        const ProxyMove& m = moves[i];
        tree(m.proxy).enlarge_proxy(node(m.proxy), m.fat);
        mark_moved(m.proxy);
    }
}

void BroadPhase::query_moved(memory::vector<Pair>& out) {
    for (const int p : move_buffer_) {
        if (moved_[p] != 2)
            continue; // destroyed since it moved, or a duplicate entry already handled
        moved_[p] = 3;
        const Aabb box = fat_aabb(p);
        const std::uint32_t user = user_data(p);
        auto visit = [&](int q) {
            // Two moved proxies find each other twice: keep the query of the greater id.
            if (q == p || (moved_[q] != 0 && q > p))
                return true;
            emit_pair(out, user, user_data(q));
            return true;
        };
        trees_[0].query(box, [&](int id) { return visit(id * 2); });
        if (!is_static(p)) // static proxies never pair with each other
            trees_[1].query(box, [&](int id) { return visit(id * 2 + 1); });
    }
}

void BroadPhase::descend_marked(memory::vector<Pair>& out) {
    // (Static pairs are never looked for: the static tree is not descended against itself.)
    DynamicTree& dynamic = trees_[0];
    const DynamicTree& fixed = trees_[1];
    dynamic.for_each_marked_pair(
        [&](int a, int b) { emit_pair(out, dynamic.user_data(a), dynamic.user_data(b)); });
    dynamic.for_each_marked_pair(
        fixed, [&](int a, int b) { emit_pair(out, dynamic.user_data(a), fixed.user_data(b)); });
}

/// \srs{R7} candidate collisions: pairs whose fat boxes overlap by \srs{IM4}.
void BroadPhase::update_pairs(memory::vector<Pair>& out) {
    const std::size_t first = out.size();
    try {
        find_pairs(out, first);
    } catch (...) {
        // A bad_alloc (a rebuild, the pairs' growth) forgets nothing: every move is looked at
        // again by the next call, and the pairs found so far are found again there.
        trees_[0].clear_marks();
        trees_[1].clear_marks();
        for (const int p : move_buffer_)
            if (moved_[p] != 0)
                moved_[p] = 1;
        out.resize(first);
        throw;
    }
}

void BroadPhase::find_pairs(memory::vector<Pair>& out, std::size_t first) {
    // The moved proxies' ancestors were only enlarged: restore the trees' quality first.
    trees_[0].rebuild();
    trees_[1].rebuild();
    // Mark the moved proxies' leaves and their ancestors.
    std::size_t moved = 0;
    for (const int p : move_buffer_) {
        if (moved_[p] != 1)
            continue; // destroyed since it moved (0), or a duplicate entry already marked (2)
        moved_[p] = 2;
        ++moved;
        tree(p).mark_leaf(node(p));
    }
    // Two searches give the same pairs. One descent of the trees over the marked nodes walks the
    // upper levels once for all moved proxies, but opens every node pair that holds a marked
    // leaf: it wins when the moved proxies lie together (a falling crowd), so that their marks
    // share ancestors. A query per moved proxy wins when they are scattered (a few bodies
    // stirring in a pile): then nearly every node holds a mark. Chosen by how many nodes the
    // marks took per moved proxy (measured: tamias_stage_gbench broad_phase/update_pairs).
    const std::size_t marked = trees_[0].marked_count() + trees_[1].marked_count();
    if (double(marked) <= marks_per_moved_for_descent * double(moved))
        descend_marked(out);
    else
        query_moved(out);
    trees_[0].clear_marks();
    trees_[1].clear_marks();
    for (const int p : move_buffer_)
        moved_[p] = 0;
    move_buffer_.clear();
    // Deterministic output whatever the tree layout and the search; duplicates only arise if
    // two proxies share user data.
    const auto begin = out.begin() + static_cast<std::ptrdiff_t>(first);
    std::sort(begin, out.end());
    out.erase(std::unique(begin, out.end()), out.end());
}

// --- snapshot ---

void BroadPhase::write(SnapshotWriter& out) const {
    out.section("BRPH");
    out("margin", margin_);
    out("least_margin", least_margin_);
    for (const DynamicTree& t : trees_)
        t.write(out);
    out.count("move_buffer", move_buffer_.size());
    for (const int p : move_buffer_)
        out("move_buffer", p);
    out.count("moved", moved_.size());
    for (const std::uint8_t m : moved_)
        out("moved", m);
}

void BroadPhase::read(SnapshotReader& in) {
    in.section("BRPH");
    in("broad_phase.margin", margin_);
    in("broad_phase.least_margin", least_margin_);
    for (DynamicTree& t : trees_)
        t.read(in);
    const std::size_t moves = in.count("broad_phase.move_buffer", 4);
    move_buffer_.resize(moves);
    memory::vector<std::size_t> at(moves);
    for (std::size_t k = 0; k < moves; ++k) {
        at[k] = in.offset();
        in("broad_phase.move_buffer", move_buffer_[k]);
    }
    const std::size_t n = in.count("broad_phase.moved", 1);
    moved_.resize(n);
    for (std::size_t p = 0; p < n; ++p) {
        const std::size_t here = in.offset();
        in("broad_phase.moved", moved_[p]);
        if (!(moved_[p] == 0 || (moved_[p] == 1 && is_proxy(int(p))))) // (message built to fail)
            in.fail_at(here, "broad_phase.moved",
                       "must be 0, or 1 for a proxy (at proxy " + decimal(std::uint64_t(p)) + ")");
    }
    for (std::size_t k = 0; k < moves; ++k) {
        if (!(move_buffer_[k] >= 0 && std::size_t(move_buffer_[k]) < n))
            in.fail_at(at[k], "broad_phase.move_buffer",
                       "must be a proxy id < " + decimal(std::uint64_t(n)));
    }
}

} // namespace tamias2d
