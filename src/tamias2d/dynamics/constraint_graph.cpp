#include "tamias2d/dynamics/constraint_graph.hpp"

#include <algorithm>

namespace tamias2d {

void ConstraintGraph::colour(std::span<const GraphEdge> edges, std::size_t body_count) {
    // Constraints of one level share no body, and constraints that share one keep their
    // creation order, so solving level by level is the sequential pass in creation order.
    body_mark_.assign(body_count, 0);
    level_of_.resize(edges.size());
    std::uint32_t levels = 0;
    for (std::uint32_t i = 0; i < edges.size(); ++i) {
        const GraphEdge& c = edges[i];
        // Body 0 stands for every static body: never written, so it orders nothing.
        const std::uint32_t la = c.body_a != 0 ? body_mark_[c.body_a] : 0;
        const std::uint32_t lb = c.body_b != 0 ? body_mark_[c.body_b] : 0;
        const std::uint32_t level = std::max(la, lb) + 1;
        if (c.body_a != 0)
            body_mark_[c.body_a] = level;
        if (c.body_b != 0)
            body_mark_[c.body_b] = level;
        // Within a level the order is free (its constraints commute): grouped by the path of
        // the iteration they take, so that packs mostly take one, not both.
        level_of_[i] = path_groups * (level - 1) + static_cast<std::uint32_t>(c.group);
        levels = std::max(levels, level);
    }
    // Counting sort by (level, group), stable.
    const std::uint32_t buckets = path_groups * levels;
    level_start_.assign(buckets + 1, 0);
    for (std::uint32_t l : level_of_)
        ++level_start_[l + 1];
    for (std::uint32_t l = 0; l < buckets; ++l)
        level_start_[l + 1] += level_start_[l];
    sorted_.resize(edges.size());
    level_fill_.assign(level_start_.begin(), level_start_.end() - 1);
    for (std::uint32_t i = 0; i < edges.size(); ++i)
        sorted_[level_fill_[level_of_[i]]++] = {i, edges[i].body_a, edges[i].body_b};
    // The packs, in that order. Placed level by level, a constraint's predecessors on its
    // bodies are the bodies' last placed constraints; it joins the open pack unless one of them
    // is in it (the only way it could also share a moving body with a lane there).
    body_mark_.assign(body_count, no_constraint);
    packs_.clear();
    Pack empty;
    empty.fill(no_constraint);
    std::uint32_t open = no_constraint; // the open pack's index (none yet)
    int lanes = wide_lanes;             // so the first constraint opens one
    for (const Placement& c : sorted_) {
        // Body 0 stands for every static body: it is marked too, but never blocks.
        const bool follows = (c.body_a != 0 && body_mark_[c.body_a] == open) ||
                             (c.body_b != 0 && body_mark_[c.body_b] == open);
        if (follows || lanes == wide_lanes) {
            open = std::uint32_t(packs_.size());
            packs_.push_back(empty);
            lanes = 0;
        }
        packs_[open][lanes++] = c.index;
        body_mark_[c.body_a] = open;
        body_mark_[c.body_b] = open;
    }
}

} // namespace tamias2d
