#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd34 {
using namespace tamias2d::units;

/// \srs{DD34} The gap between two shapes that are each a core (a point, a segment or a convex
/// polygon) grown by a radius (a circle: its centre and radius; a capsule: its core segment and
/// radius; a polygon, a segment: radius 0): the distance between the cores, less both radii,
/// d = |p_B - p_A| - r_A - r_B, with p_A, p_B the cores' closest points. Positive: apart, by
/// that much; zero or negative: they touch or overlap. The closest points of the shapes
/// themselves lie on the line between the cores' closest points, r_A and r_B in from them.
inline Length rounded_gap(Length core_distance, Length radius_a, Length radius_b) {
    return core_distance - radius_a - radius_b;
}

} // namespace tamias2d::model::dd34
