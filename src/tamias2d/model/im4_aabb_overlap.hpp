#pragma once
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::im4 {

namespace detail {
/// A coordinate as a length: the engine's plain SI doubles are wrapped, quantities kept.
constexpr units::Length as_length(double x) {
    return units::Length::from_value(x);
}
template <class L> constexpr L as_length(L x) {
    return x;
}
} // namespace detail

/// An axis-aligned box by its corners, with unit-typed coordinates.
template <class L> struct Aabb { L min_x, min_y, max_x, max_y; };

/// \srs{IM4} Collision detection of rectangles by axis-aligned bounding boxes: boxes overlap
/// when they overlap on both axes (strictly: touching boxes do not overlap, as in the SRS).
/// Any box type with min_x, min_y, max_x, max_y serves: Aabb<Length> in the tests, the engine's
/// plain-double tamias2d::Aabb in the broad phase, whose coordinates are compared as lengths.
template <class Box> constexpr bool overlaps(const Box& a, const Box& b) {
    using detail::as_length;
    return as_length(a.min_x) < as_length(b.max_x) && as_length(a.max_x) > as_length(b.min_x) &&
           as_length(a.min_y) < as_length(b.max_y) && as_length(a.max_y) > as_length(b.min_y);
}

/// \srs{IM4} The SRS's own inputs, read correctly: (x, y) is the centre of mass (as IM4 says),
/// w the width and h the HEIGHT (IM4 calls both "width"), so the box spans x +- w/2. The
/// seed's inequalities treat (x, y) as the lower-left corner instead: erratum.
template <class L> constexpr Aabb<L> from_centre(L x, L y, L w, L h) {
    return {x - 0.5 * w, y - 0.5 * h, x + 0.5 * w, y + 0.5 * h};
}

} // namespace tamias2d::model::im4
