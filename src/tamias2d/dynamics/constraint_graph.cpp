#include "tamias2d/dynamics/constraint_graph.hpp"

#include <algorithm>

namespace tamias2d {

void ConstraintGraph::colour(std::span<const GraphEdge> edges, std::size_t body_count) {
    // Constraints of one level share no body, and constraints that share one keep their
    // creation order, so solving level by level is the sequential pass in creation order.
    body_level_.assign(body_count, 0);
    level_of_.resize(edges.size());
    std::uint32_t levels = 0;
    for (std::uint32_t i = 0; i < edges.size(); ++i) {
        const GraphEdge& c = edges[i];
        // Body 0 stands for every static body: never written, so it orders nothing.
        const std::uint32_t la = c.body_a != 0 ? body_level_[c.body_a] : 0;
        const std::uint32_t lb = c.body_b != 0 ? body_level_[c.body_b] : 0;
        const std::uint32_t level = std::max(la, lb) + 1;
        if (c.body_a != 0)
            body_level_[c.body_a] = level;
        if (c.body_b != 0)
            body_level_[c.body_b] = level;
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
        sorted_[level_fill_[level_of_[i]]++] = i;
    packs_.clear();
    for (std::uint32_t l = 0; l < levels; ++l) {
        const std::uint32_t end = level_start_[path_groups * (l + 1)];
        for (std::uint32_t k = level_start_[path_groups * l]; k < end; k += wide_lanes) {
            Pack p;
            p.fill(no_constraint);
            for (std::uint32_t j = 0; j < wide_lanes && k + j < end; ++j)
                p[j] = sorted_[k + j];
            packs_.push_back(p);
        }
    }
}

} // namespace tamias2d
