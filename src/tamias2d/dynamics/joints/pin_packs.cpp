#include "tamias2d/dynamics/joints/pin_packs.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#include "tamias2d/dynamics/bridge/joints.hpp"
#include "tamias2d/dynamics/contacts/wide_pack_loops.hpp"
#include "tamias2d/dynamics/joints/joint_solver.hpp"

namespace tamias2d {

namespace {

// The packs a colour must fill on average for a chain to be coloured. A short chain gains
// little from its few packs, and its creation order converges better where it holds a body far
// heavier than its links (the benchmark's heavy chains).
constexpr std::uint32_t colour_packs = 4;

/// The lanes' pins from their centres in the world frame: each frame turned by its body's
/// rotation now (joint_solver.hpp's anchor_a, four at once).
inline Vec2<Wide> anchor(const Rot* const (&q)[wide_lanes], Vec2<Wide> frame) {
    static_assert(wide_lanes == 4);
    const Wide c{q[0]->c, q[1]->c, q[2]->c, q[3]->c};
    const Wide s{q[0]->s, q[1]->s, q[2]->s, q[3]->s};
    return rotate(c, s, frame);
}

// The loops over a run of packs: each pack's warm start as joint_solver.cpp's
// warm_start_revolute is for one plain pin, operation for operation, and its iteration the same
// pin_iteration as solve_pin's.
inline void warm_start_run(PinPack* packs, std::uint32_t count, SolverBody* bodies) {
    for (std::uint32_t i = 0; i < count; ++i) {
        PinPack& p = packs[i];
        WideBody a = wide::gather(bodies, p.body_a);
        WideBody b = wide::gather(bodies, p.body_b);
        bridge::apply_angular_impulse(a, b, p.angular);
        bridge::apply_pin_impulse(a, anchor(p.q_a, p.frame_a), b, anchor(p.q_b, p.frame_b),
                                  p.impulse);
        wide::scatter(bodies, p.body_a, a);
        wide::scatter(bodies, p.body_b, b);
    }
}

template <bool use_bias>
inline void solve_run(PinPack* packs, std::uint32_t count, SolverBody* bodies) {
    for (std::uint32_t i = 0; i < count; ++i) {
        PinPack& p = packs[i];
        WideBody a = wide::gather(bodies, p.body_a);
        WideBody b = wide::gather(bodies, p.body_b);
        pin_iteration<use_bias>(a, b, anchor(p.q_a, p.frame_a), anchor(p.q_b, p.frame_b),
                                p.center_offset, p.bias_rate, p.mass_scale, p.impulse_scale,
                                p.impulse);
        wide::scatter(bodies, p.body_a, a);
        wide::scatter(bodies, p.body_b, b);
    }
}

// One clone per instruction set (wide_pack_loops.hpp's TAMIAS_WIDE_KERNEL), each with the same
// bits: no clone contracts a product and a sum.
TAMIAS_WIDE_KERNEL void warm_start_kernel(PinPack* packs, std::uint32_t count, SolverBody* bodies) {
    warm_start_run(packs, count, bodies);
}
TAMIAS_WIDE_KERNEL void soft_kernel(PinPack* packs, std::uint32_t count, SolverBody* bodies) {
    solve_run<true>(packs, count, bodies);
}
TAMIAS_WIDE_KERNEL void relax_kernel(PinPack* packs, std::uint32_t count, SolverBody* bodies) {
    solve_run<false>(packs, count, bodies);
}

} // namespace

void PinPacks::order(memory::vector<SolvedJoint>& solved, std::span<const std::uint32_t> bounds,
                     std::size_t body_count) {
    // The last step's joints, bodies and pins: the last order stands (it is a function of them).
    const bool same =
        !stream_begin_.empty() && body_count == last_body_count_ &&
        solved.size() == last_solved_.size() && bounds.size() == last_bounds_.size() &&
        std::equal(bounds.begin(), bounds.end(), last_bounds_.begin()) &&
        (solved.empty() ||
         std::memcmp(solved.data(), last_solved_.data(), solved.size() * sizeof(SolvedJoint)) == 0);
    if (!same) {
        last_solved_.assign(solved.begin(), solved.end());
        last_bounds_.assign(bounds.begin(), bounds.end());
        last_body_count_ = body_count;
        ordered_.resize(solved.size());
        packs_.clear();
        pack_first_.clear();
        runs_.clear();
        stream_begin_.assign(1, 0);
        for (std::size_t s = 0; s + 1 < bounds.size(); ++s)
            order_stream(solved, bounds[s], bounds[s + 1], body_count);
        packs_.resize(pack_first_.size());
        in_pack_.assign(solved.size(), 0);
        for (const std::uint32_t first : pack_first_)
            std::fill_n(in_pack_.begin() + first, wide_lanes, std::uint8_t{1});
    }
    solved.assign(ordered_.begin(), ordered_.end());
}

void PinPacks::order_stream(const memory::vector<SolvedJoint>& solved, std::uint32_t first,
                            std::uint32_t last, std::size_t body_count) {
    if (mark_.size() < body_count)
        mark_.resize(body_count, 0); // all zero between calls
    const std::uint32_t n = last - first;
    // Each joint's level: one past the last level of an earlier joint on either moving body.
    level_of_.resize(n);
    std::uint32_t levels = 0;
    for (std::uint32_t k = 0; k < n; ++k) {
        const SolvedJoint& s = solved[first + k];
        const std::uint32_t level = std::max(s.solver_a != 0 ? mark_[s.solver_a] : 0u,
                                             s.solver_b != 0 ? mark_[s.solver_b] : 0u);
        level_of_[k] = level;
        if (s.solver_a != 0)
            mark_[s.solver_a] = level + 1;
        if (s.solver_b != 0)
            mark_[s.solver_b] = level + 1;
        levels = std::max(levels, level + 1);
    }
    for (std::uint32_t k = first; k < last; ++k)
        mark_[solved[k].solver_a] = mark_[solved[k].solver_b] = 0;
    // Levels narrower than a pack on average (a chain: one joint a level) fill few packs: the
    // stream is coloured instead where each colour fills several packs; else it keeps the
    // creation order, one joint at a time.
    if (std::uint64_t(n) < std::uint64_t(wide_lanes) * levels) {
        const std::uint32_t colours = colour_stream(solved, first, last, body_count);
        if (colours > 0 && std::uint64_t(n) >= std::uint64_t(colour_packs * wide_lanes) * colours)
            levels = colours;
    }
    if (std::uint64_t(n) < std::uint64_t(wide_lanes) * levels) {
        std::copy(solved.begin() + first, solved.begin() + last, ordered_.begin() + first);
        if (n > 0)
            runs_.push_back({first, n, 0, false});
        stream_begin_.push_back(std::uint32_t(runs_.size()));
        return;
    }
    // The joints by level, creation order within one (a counting sort).
    level_start_.assign(std::size_t(levels) + 1, 0);
    for (std::uint32_t k = 0; k < n; ++k)
        ++level_start_[level_of_[k] + 1];
    for (std::uint32_t l = 0; l < levels; ++l)
        level_start_[l + 1] += level_start_[l];
    sorted_.resize(n);
    for (std::uint32_t k = 0; k < n; ++k)
        sorted_[level_start_[level_of_[k]]++] = first + k; // level_start_[l]: now level l's end
    // Each level: its plain pins four to a pack (all but the last one to three), then the rest
    // one by one; the records follow in that order.
    std::uint32_t out = first;
    std::uint32_t begin = 0;
    for (std::uint32_t l = 0; l < levels; ++l) {
        const std::uint32_t end = level_start_[l];
        std::uint32_t pins = 0;
        for (std::uint32_t i = begin; i < end; ++i)
            pins += solved[sorted_[i]].plain;
        const std::uint32_t packed = pins - pins % wide_lanes;
        if (packed > 0) {
            const auto pack = std::uint32_t(pack_first_.size());
            PinRun* last_run = runs_.size() > stream_begin_.back() ? &runs_.back() : nullptr;
            if (last_run != nullptr && last_run->packed && last_run->first + last_run->count == out)
                last_run->count += packed; // the packs of consecutive levels run as one loop
            else
                runs_.push_back({out, packed, pack, true});
            for (std::uint32_t p = 0; p < packed / wide_lanes; ++p)
                pack_first_.push_back(out + p * wide_lanes);
        }
        std::uint32_t taken = 0, single = out + packed;
        const std::uint32_t singles = single;
        for (std::uint32_t i = begin; i < end; ++i) {
            const SolvedJoint& s = solved[sorted_[i]];
            if (s.plain != 0 && taken < packed)
                ordered_[out + taken++] = s;
            else
                ordered_[single++] = s;
        }
        if (single > singles) {
            PinRun* last_run = runs_.size() > stream_begin_.back() ? &runs_.back() : nullptr;
            if (last_run != nullptr && !last_run->packed &&
                last_run->first + last_run->count == singles)
                last_run->count += single - singles;
            else
                runs_.push_back({singles, single - singles, 0, false});
        }
        out = single;
        begin = end;
    }
    stream_begin_.push_back(std::uint32_t(runs_.size()));
}

std::uint32_t PinPacks::colour_stream(const memory::vector<SolvedJoint>& solved,
                                      std::uint32_t first, std::uint32_t last,
                                      std::size_t body_count) {
    colours_.cover(body_count);
    std::uint32_t colours = 0;
    std::uint32_t k = first;
    for (; k < last; ++k) {
        const std::uint32_t c = colours_.take(solved[k].solver_a, solved[k].solver_b);
        if (c == GreedyColours::colours)
            break;
        level_of_[k - first] = c;
        colours = std::max(colours, c + 1);
    }
    const bool coloured = k == last;
    for (std::uint32_t i = first; i < k; ++i)
        colours_.release(solved[i].solver_a, solved[i].solver_b);
    return coloured ? colours : 0;
}

void PinPacks::fill(std::size_t pack, int lane, const PinLane& pin) {
    PinPack& p = packs_[pack];
    p.body_a[lane] = pin.body_a;
    p.body_b[lane] = pin.body_b;
    p.q_a[lane] = pin.q_a;
    p.q_b[lane] = pin.q_b;
    p.frame_a.x[lane] = pin.frame_a.x;
    p.frame_a.y[lane] = pin.frame_a.y;
    p.frame_b.x[lane] = pin.frame_b.x;
    p.frame_b.y[lane] = pin.frame_b.y;
    p.center_offset.x[lane] = pin.center_offset.x;
    p.center_offset.y[lane] = pin.center_offset.y;
    p.impulse.x[lane] = pin.impulse.x;
    p.impulse.y[lane] = pin.impulse.y;
    p.angular[lane] = pin.angular;
    p.bias_rate[lane] = pin.softness.bias_rate;
    p.mass_scale[lane] = pin.softness.mass_scale;
    p.impulse_scale[lane] = pin.softness.impulse_scale;
}

void PinPacks::warm_start(std::uint32_t first, std::uint32_t count, SolverBody* bodies) {
    warm_start_kernel(&packs_[first], count, bodies);
}

void PinPacks::solve(std::uint32_t first, std::uint32_t count, SolverBody* bodies, bool use_bias) {
    if (use_bias)
        soft_kernel(&packs_[first], count, bodies);
    else
        relax_kernel(&packs_[first], count, bodies);
}

} // namespace tamias2d
