#include "tamias2d/dynamics/constraint_graph.hpp"

#include <algorithm>
#include <bit>

namespace tamias2d {

void ConstraintGraph::assign_streams(std::span<const GraphEdge> edges, std::uint32_t R,
                                     std::span<const double> cut) {
    const auto n = std::uint32_t(edges.size());
    stream_of_.resize(n);
    // The regions' bounds: the manifolds' places (midway between their moving bodies) at
    // ranks n/R, 2n/R, ...; a body lies in the region of the bounds at or below it.
    const auto place = [&](const GraphEdge& e) {
        return e.body_a == 0   ? cut[e.body_b]
               : e.body_b == 0 ? cut[e.body_a]
                               : 0.5 * (cut[e.body_a] + cut[e.body_b]);
    };
    cuts_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i)
        cuts_[i] = place(edges[i]);
    std::array<double, max_regions> bound{};
    for (std::uint32_t r = 1; r < R; ++r) {
        const auto rank = std::ptrdiff_t(std::uint64_t(n) * r / R);
        std::nth_element(cuts_.begin(), cuts_.begin() + rank, cuts_.end());
        bound[r] = cuts_[std::size_t(rank)];
    }
    const auto region = [&](std::uint32_t body) {
        std::uint32_t r = 0;
        while (r + 1 < R && cut[body] >= bound[r + 1])
            ++r;
        return r;
    };
    for (std::uint32_t i = 0; i < n; ++i) {
        const GraphEdge& e = edges[i];
        const std::uint32_t ra = region(e.body_a != 0 ? e.body_a : e.body_b);
        const std::uint32_t rb = region(e.body_b != 0 ? e.body_b : e.body_a);
        stream_of_[i] = ra == rb ? ra : R;
    }
}

void ConstraintGraph::sequence(std::span<const GraphEdge> edges, std::uint32_t R,
                               std::size_t body_count) {
    const auto n = std::uint32_t(edges.size());
    const std::uint32_t S = streams_;
    // Stream by stream, creation order within (one region: stream 0 and creation order, left
    // implicit).
    if (R > 1) {
        sequence_.resize(n);
        std::array<std::uint32_t, max_streams + 1> start{};
        for (std::uint32_t i = 0; i < n; ++i)
            ++start[stream_of_[i] + 1];
        for (std::uint32_t s = 0; s < S; ++s)
            start[s + 1] += start[s];
        for (std::uint32_t i = 0; i < n; ++i)
            sequence_[start[stream_of_[i]]++] = i;
        between_by_colour(edges, std::span(sequence_).subspan(start[R - 1]), body_count);
    }
}

void ConstraintGraph::between_by_colour(std::span<const GraphEdge> edges,
                                        std::span<std::uint32_t> between, std::size_t body_count) {
    // The manifolds between regions join the slabs along their bounds: in a pile's creation
    // order (bottom up) those across one bound are a chain up the pile, each sharing a box with
    // the one below it: one level per manifold, so one lane per pack. Greedy colours (at most
    // `colours`, the rest after them) make that chain two or three levels.
    constexpr std::uint32_t colours = GreedyColours::colours;
    body_colours_.cover(body_count);
    colour_of_.resize(between.size());
    std::array<std::uint32_t, colours + 2> start{};
    for (std::size_t k = 0; k < between.size(); ++k) {
        const GraphEdge& e = edges[between[k]];
        const std::uint32_t c = body_colours_.take(e.body_a, e.body_b); // 64: all taken
        colour_of_[k] = c;
        ++start[c + 1];
    }
    for (std::uint32_t c = 0; c <= colours; ++c)
        start[c + 1] += start[c];
    between_scratch_.resize(between.size());
    for (std::size_t k = 0; k < between.size(); ++k)
        between_scratch_[start[colour_of_[k]]++] = between[k];
    std::copy(between_scratch_.begin(), between_scratch_.end(), between.begin());
    for (const std::uint32_t i : between)
        body_colours_.release(edges[i].body_a, edges[i].body_b);
}

std::size_t ConstraintGraph::regrouped(std::span<const GraphEdge> edges, std::uint32_t R,
                                       std::size_t body_count) const {
    if (R != coloured_regions_ || body_count != coloured_bodies_ ||
        edges.size() != coloured_edges_.size())
        return other_bodies;
    std::size_t count = 0;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const GraphEdge& now = edges[i];
        const GraphEdge& then = coloured_edges_[i];
        if (now.body_a != then.body_a || now.body_b != then.body_b)
            return other_bodies;
        count += now.group != then.group;
    }
    return count;
}

void ConstraintGraph::colour(std::span<const GraphEdge> edges, std::size_t body_count,
                             std::uint32_t regions, std::span<const double> cut) {
    const std::uint32_t R = edges.empty() ? 1 : std::clamp<std::uint32_t>(regions, 1, max_regions);
    const std::size_t changed = regrouped(edges, R, body_count);
    if (changed != other_bodies && changed * regroup_share <= edges.size())
        return;
    if (R > 1 && changed == other_bodies)
        assign_streams(edges, R, cut);
    // Not coloured until every part below is done: a bad_alloc in any of them must not leave a
    // record saying these edges were coloured, or the next step would reuse half-made packs.
    coloured_regions_ = 0;
    const std::uint32_t S = streams_ = R > 1 ? R + 1 : 1;
    sequence(edges, R, body_count);
    level_sort(edges, body_count, S > 1);
    place_packs(body_count, S);
    coloured_edges_.assign(edges.begin(), edges.end());
    coloured_regions_ = R;
    coloured_bodies_ = body_count;
}

void ConstraintGraph::level_sort(std::span<const GraphEdge> edges, std::size_t body_count,
                                 bool streamed) {
    const auto n = std::uint32_t(edges.size());
    // Constraints of one level share no body, and constraints that share one keep their order
    // in the sequence, so solving level by level is the sequential pass in that order. Each
    // stream's levels come after the streams' before it: a stream's constraints are ordered by
    // the constraints of their own stream only (the earlier streams' are all solved before).
    body_mark_.assign(body_count, 0);
    level_of_.resize(n);
    std::uint32_t levels = 0, base = 0, stream = 0;
    for (std::uint32_t k = 0; k < n; ++k) {
        const std::uint32_t i = streamed ? sequence_[k] : k;
        const GraphEdge& c = edges[i];
        if (streamed && stream_of_[i] != stream) {
            stream = stream_of_[i];
            base = levels;
        }
        // Body 0 stands for every static body: never written, so it orders nothing.
        const std::uint32_t la = c.body_a != 0 ? body_mark_[c.body_a] : 0;
        const std::uint32_t lb = c.body_b != 0 ? body_mark_[c.body_b] : 0;
        const std::uint32_t level = std::max({base, la, lb}) + 1;
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
    sorted_.resize(n);
    level_fill_.assign(level_start_.begin(), level_start_.end() - 1);
    for (std::uint32_t k = 0; k < n; ++k) {
        const std::uint32_t i = streamed ? sequence_[k] : k;
        sorted_[level_fill_[level_of_[i]]++] = {i, edges[i].body_a, edges[i].body_b,
                                                streamed ? stream_of_[i] : 0};
    }
}

void ConstraintGraph::place_packs(std::size_t body_count, std::uint32_t S) {
    const bool streamed = S > 1;
    // The packs, in that order. Placed level by level, a constraint's predecessors on its
    // bodies are the bodies' last placed constraints; it joins the open pack unless one of them
    // is in it (the only way it could also share a moving body with a lane there), or unless
    // it begins a stream. A predecessor in another stream is in a pack of an earlier stream:
    // the pack waits for that stream to get past it.
    body_mark_.assign(body_count, no_constraint);
    packs_.clear();
    pack_stream_.clear();
    stream_begin_.assign(S + 1, 0);
    wait_begin_.assign(1, 0);
    waits_.clear();
    Pack empty;
    empty.fill(no_constraint);
    std::uint32_t open = no_constraint; // the open pack's index (none yet)
    std::uint32_t open_stream = 0;      // its stream
    int lanes = wide_lanes;             // so the first constraint opens one
    std::array<std::uint32_t, max_streams> need{}, waited{};
    // Closes the open pack: its waits, each only where an earlier pack of its stream did not
    // already wait as long (with one stream: none, set at the end).
    const auto close = [&] {
        if (!streamed || open == no_constraint)
            return;
        for (std::uint32_t t = 0; t < S; ++t) {
            if (need[t] > waited[t]) {
                waits_.push_back({t, need[t]});
                waited[t] = need[t];
            }
        }
        need.fill(0);
        wait_begin_.push_back(std::uint32_t(waits_.size()));
    };
    for (const Placement& c : sorted_) {
        const bool begins = open == no_constraint || c.stream != open_stream;
        // Body 0 stands for every static body: it is marked too, but never blocks.
        const bool follows = (c.body_a != 0 && body_mark_[c.body_a] == open) ||
                             (c.body_b != 0 && body_mark_[c.body_b] == open);
        if (begins || follows || lanes == wide_lanes) {
            close();
            if (begins) {
                for (std::uint32_t s = open == no_constraint ? 0 : open_stream + 1; s <= c.stream;
                     ++s)
                    stream_begin_[s] = std::uint32_t(packs_.size());
                waited.fill(0);
            }
            open = std::uint32_t(packs_.size());
            open_stream = c.stream;
            packs_.push_back(empty);
            if (streamed)
                pack_stream_.push_back(c.stream);
            lanes = 0;
        }
        packs_[open][lanes++] = c.index;
        if (streamed) {
            for (const std::uint32_t body : {c.body_a, c.body_b}) {
                const std::uint32_t before = body_mark_[body];
                if (body != 0 && before != no_constraint && pack_stream_[before] != c.stream) {
                    const std::uint32_t t = pack_stream_[before];
                    need[t] = std::max(need[t], before - stream_begin_[t] + 1);
                }
            }
        }
        body_mark_[c.body_a] = open;
        body_mark_[c.body_b] = open;
    }
    close();
    for (std::uint32_t s = open == no_constraint ? 0 : open_stream + 1; s <= S; ++s)
        stream_begin_[s] = std::uint32_t(packs_.size());
    if (!streamed)
        wait_begin_.assign(packs_.size() + 1, 0);
    awaited_.assign(streamed ? packs_.size() : 0, 0);
    for (const StreamWait& w : waits_)
        awaited_[stream_begin_[w.stream] + w.packs - 1] = 1;
}

} // namespace tamias2d
