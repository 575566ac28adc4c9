// The public Vec2 (tamias2d/vec2.hpp) with Boost.Units quantities as components: products keep
// their units, so dot(Vec2<Length>, Vec2<Force>) is an energy and cross(r, F) a scalar of unit
// m N (the z component of the 3D cross product, A4 right-handed).
#pragma once

#include <boost/units/cmath.hpp>

#include "tamias2d/units/quantities.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// |v| of a unit-typed vector (here, not in the public header, because it needs Boost.Units'
/// sqrt; found by argument-dependent lookup like the operators).
template <class Q> Q norm(Vec2<Q> v) {
    return boost::units::sqrt(norm_squared(v));
}

} // namespace tamias2d

namespace tamias2d::units {

using tamias2d::cross;
using tamias2d::dot;
using tamias2d::norm;
using tamias2d::norm_squared;
using tamias2d::Vec2;
using tamias2d::detail::product_t;
using tamias2d::detail::quotient_t;

/// Strips units: the engine's storage is plain doubles (see docs/design.md).
template <class Q> constexpr std::pair<double, double> values(Vec2<Q> v) {
    return {v.x.value(), v.y.value()};
}
template <class Q> constexpr Vec2<Q> vec_from_values(double x, double y) {
    return {Q::from_value(x), Q::from_value(y)};
}

} // namespace tamias2d::units
