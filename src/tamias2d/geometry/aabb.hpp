// Operations on axis-aligned bounding boxes (m, world frame) for the broad phase. The overlap
// test is IM4's (model/im4_aabb_overlap.hpp), on plain doubles.
#pragma once

#include <algorithm>

#include "tamias2d/aabb.hpp"
#include "tamias2d/model/im4_aabb_overlap.hpp"

namespace tamias2d {

constexpr bool overlaps(const Aabb& a, const Aabb& b) {
    return model::im4::overlaps(a, b);
}

constexpr Aabb union_of(const Aabb& a, const Aabb& b) {
    return {std::min(a.min_x, b.min_x), std::min(a.min_y, b.min_y), std::max(a.max_x, b.max_x),
            std::max(a.max_y, b.max_y)};
}

/// a contains b (closed).
constexpr bool contains(const Aabb& a, const Aabb& b) {
    return a.min_x <= b.min_x && a.min_y <= b.min_y && b.max_x <= a.max_x && b.max_y <= a.max_y;
}

constexpr double perimeter(const Aabb& a) {
    return 2.0 * ((a.max_x - a.min_x) + (a.max_y - a.min_y));
}

constexpr Aabb inflated(const Aabb& a, double r) {
    return {a.min_x - r, a.min_y - r, a.max_x + r, a.max_y + r};
}

} // namespace tamias2d
