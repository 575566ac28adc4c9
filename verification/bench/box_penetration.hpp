// How deep the scene's boxes overlap, from the bodies' poses and the boxes' shapes alone: the
// same measure for every engine, whatever its contacts, skins or slops (the work-precision
// diagrams, docs/performance.md). The penetration of two overlapping boxes is their minimum
// translation distance, the shortest move of one that separates them: for two convex polygons
// it is the smallest overlap of their projections on the polygons' edge normals (their
// Minkowski difference is bounded by lines along those normals), four axes for two boxes.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "bench_engines.hpp"
#include "bench_scenes.hpp"

namespace tamias_bench {

/// A box placed in the world: centre, unit x axis (its y axis is that turned by 90 degrees) and
/// half extents.
struct PlacedBox {
    V2 c{};
    V2 u{1.0, 0.0};
    double hx = 0.5, hy = 0.5;
};

/// The box part `p` of a body at `position`, turned by `angle`.
inline PlacedBox place(const BoxPart& p, V2 position, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    const double a = angle + p.angle;
    return {{position.x + c * p.center.x - s * p.center.y,
             position.y + s * p.center.x + c * p.center.y},
            {std::cos(a), std::sin(a)},
            p.hx,
            p.hy};
}

/// m: the penetration (minimum translation distance) of two boxes; 0 when they do not overlap.
inline double penetration(const PlacedBox& a, const PlacedBox& b) {
    const V2 d{b.c.x - a.c.x, b.c.y - a.c.y};
    const auto radius = [](const PlacedBox& k, V2 n) {
        return k.hx * std::abs(k.u.x * n.x + k.u.y * n.y) +
               k.hy * std::abs(-k.u.y * n.x + k.u.x * n.y);
    };
    double depth = INFINITY;
    for (const V2 n : {a.u, V2{-a.u.y, a.u.x}, b.u, V2{-b.u.y, b.u.x}}) {
        const double overlap = radius(a, n) + radius(b, n) - std::abs(d.x * n.x + d.y * n.y);
        if (!(overlap > 0.0))
            return 0.0;
        depth = std::min(depth, overlap);
    }
    return depth;
}

/// m: the deepest penetration between any two boxes of different bodies, at least one of them
/// dynamic, with the dynamic bodies at `poses` (index: SceneDesc::bodies) and the static ones
/// where the scene puts them; infinite when a dynamic pose is not finite.
inline double deepest_penetration(const SceneDesc& s, const std::vector<Probe>& poses) {
    struct Item {
        PlacedBox box;
        int body;
    };
    std::vector<Item> moving, fixed;
    double reach = 0.0; // the largest circumradius of a dynamic box
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        const BodyDesc& b = s.bodies[i];
        if (b.dynamic && !(finite(poses[i]) && std::isfinite(poses[i].angle)))
            return INFINITY;
        for (const BoxPart& p : b.boxes) {
            if (b.dynamic) {
                moving.push_back({place(p, poses[i].p, poses[i].angle), int(i)});
                reach = std::max(reach, std::hypot(p.hx, p.hy));
            } else {
                fixed.push_back({place(p, b.position, b.angle), int(i)});
            }
        }
    }
    double deepest = 0.0;
    // Against the static boxes (few, and large): every pair.
    for (const Item& m : moving) {
        for (const Item& f : fixed)
            deepest = std::max(deepest, penetration(m.box, f.box));
    }
    // Between dynamic boxes: a grid of cells twice the largest circumradius, so that two boxes
    // that overlap have their centres in the same or neighbouring cells.
    if (moving.empty())
        return deepest;
    const double cell = 2.0 * reach;
    const auto key = [](std::int64_t x, std::int64_t y) {
        return (std::uint64_t(x) << 32) ^ std::uint64_t(std::uint32_t(y));
    };
    std::vector<std::pair<std::uint64_t, int>> cells;
    cells.reserve(moving.size());
    std::vector<std::pair<std::int64_t, std::int64_t>> at(moving.size());
    for (std::size_t k = 0; k < moving.size(); ++k) {
        at[k] = {std::int64_t(std::floor(moving[k].box.c.x / cell)),
                 std::int64_t(std::floor(moving[k].box.c.y / cell))};
        cells.push_back({key(at[k].first, at[k].second), int(k)});
    }
    std::sort(cells.begin(), cells.end());
    for (std::size_t k = 0; k < moving.size(); ++k) {
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
            for (std::int64_t dy = -1; dy <= 1; ++dy) {
                const std::uint64_t want = key(at[k].first + dx, at[k].second + dy);
                auto it = std::lower_bound(cells.begin(), cells.end(), std::make_pair(want, 0));
                for (; it != cells.end() && it->first == want; ++it) {
                    const Item& o = moving[std::size_t(it->second)];
                    if (std::size_t(it->second) > k && o.body != moving[k].body)
                        deepest = std::max(deepest, penetration(moving[k].box, o.box));
                }
            }
        }
    }
    return deepest;
}

} // namespace tamias_bench
