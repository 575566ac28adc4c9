#pragma once
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd28 {
using namespace tamias2d::units;

/// \srs{DD28} A sensor and a shape overlap when their signed distance is negative: the least
/// separation of their contact points (R7's manifold) is below zero. Touching at a point, or
/// a speculative point ahead of contact, is not an overlap.
inline bool overlapping(int point_count, Length least_separation) {
    return point_count > 0 && least_separation < Length::from_value(0.0);
}

} // namespace tamias2d::model::dd28
