// Work-precision points: an engine's setting costs `cost` (ms/step) and leaves an error `error`
// (in the scene's measure); a point is worth taking only if no other setting is both as cheap and
// as accurate. The frontier of an engine's points, and the cheapest point of one engine at least
// as accurate as a point of another (docs/performance.md, "Work-precision diagrams").
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace tamias_bench {

struct WorkPoint {
    double cost = 0.0;  ///< ms/step
    double error = 0.0; ///< the scene's error measure (smaller is better)
    bool valid() const { return std::isfinite(cost) && std::isfinite(error); }
};

/// Indices of the Pareto frontier of `points`, by increasing cost: the valid points that no other
/// valid point matches in both cost and error while beating it in one (of equal points, the first).
inline std::vector<std::size_t> pareto_frontier(const std::vector<WorkPoint>& points) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (points[i].valid())
            order.push_back(i);
    }
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return points[a].cost < points[b].cost ||
               (points[a].cost == points[b].cost && points[a].error < points[b].error);
    });
    std::vector<std::size_t> front;
    double best = INFINITY;
    for (const std::size_t i : order) {
        if (points[i].error < best) {
            front.push_back(i);
            best = points[i].error;
        }
    }
    return front;
}

/// The index of the cheapest valid point of `points` whose error is at most `error` (of equal
/// cost, the more accurate); none when no valid point is that accurate.
inline std::optional<std::size_t> cheapest_as_accurate(const std::vector<WorkPoint>& points,
                                                       double error) {
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const WorkPoint& p = points[i];
        if (!p.valid() || !(p.error <= error))
            continue;
        if (!best || p.cost < points[*best].cost ||
            (p.cost == points[*best].cost && p.error < points[*best].error))
            best = i;
    }
    return best;
}

/// The index of the most accurate valid point (of equal error, the cheaper); none when no point
/// is valid.
inline std::optional<std::size_t> most_accurate(const std::vector<WorkPoint>& points) {
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const WorkPoint& p = points[i];
        if (!p.valid())
            continue;
        if (!best || p.error < points[*best].error ||
            (p.error == points[*best].error && p.cost < points[*best].cost))
            best = i;
    }
    return best;
}

} // namespace tamias_bench
