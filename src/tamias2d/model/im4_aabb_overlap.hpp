#pragma once

namespace tamias2d::model::im4 {

/// An axis-aligned box by its corners, with unit-typed coordinates.
template <class L> struct Aabb { L min_x, min_y, max_x, max_y; };

/// \srs{IM4} Collision detection of rectangles by axis-aligned bounding boxes: boxes overlap
/// when they overlap on both axes (strictly: touching boxes do not overlap, as in the SRS).
/// Any box type with min_x, min_y, max_x, max_y serves: Aabb<Length> in the tests, the engine's
/// plain-double tamias2d::Aabb in the broad phase.
template <class Box> constexpr bool overlaps(const Box& a, const Box& b) {
    return a.min_x < b.max_x && a.max_x > b.min_x && a.min_y < b.max_y && a.max_y > b.min_y;
}

/// \srs{IM4} The SRS's own inputs, read correctly: (x, y) is the centre of mass (as IM4 says),
/// w the width and h the HEIGHT (IM4 calls both "width"), so the box spans x +- w/2. The
/// seed's inequalities treat (x, y) as the lower-left corner instead: erratum.
template <class L> constexpr Aabb<L> from_centre(L x, L y, L w, L h) {
    return {x - 0.5 * w, y - 0.5 * h, x + 0.5 * w, y + 0.5 * h};
}

} // namespace tamias2d::model::im4
