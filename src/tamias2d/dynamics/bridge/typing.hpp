// The engine's side of the unit-typed model layer. The engine stores plain doubles (SI); the
// adapters in dynamics/bridge/ wrap them in Boost.Units quantities, call the labelled model
// function and unwrap the result. Everything inlines, so the hot loops pay nothing for the typing
// (verification/bench measures it); the formulas themselves live only in model/. This file holds
// the wrapping itself; each other file of bridge/ adapts one concern, so that a change to one
// model module rebuilds only the engine files that evaluate it.
#pragma once

#include <type_traits>
#include <utility>

#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/units/quantities.hpp"
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::bridge {

namespace u = tamias2d::units;
namespace bu = boost::units;
namespace m = tamias2d::model;

template <class Q> inline u::Vec2<Q> typed(Vec2d v) {
    return u::vec_from_values<Q>(v.x, v.y);
}
template <class Q> inline Vec2d plain(u::Vec2<Q> v) {
    return {v.x.value(), v.y.value()};
}

// The hot-loop adapters below are templates over the value type V: double for one contact,
// Wide (math/wide.hpp) for a pack of contacts, one per lane. Body is SolverBody or WideBody.
template <class Body> using value_of = std::remove_cvref_t<decltype(std::declval<Body>().w)>;

template <class Q, class V> inline u::Over<Q, V> typed_value(V x) {
    return u::Over<Q, V>::from_value(x);
}
template <class Q, class V> inline u::Vec2<u::Over<Q, V>> typed_vec(u::Vec2<V> v) {
    return {typed_value<Q>(v.x), typed_value<Q>(v.y)};
}
template <class Q, class V> inline u::Vec2<V> plain_vec(u::Vec2<bu::quantity<Q, V>> v) {
    return {v.x.value(), v.y.value()};
}

} // namespace tamias2d::bridge
