// A two-component vector of one Boost.Units quantity type (SRS A2: all objects are 2D).
// Products keep their units: dot(Vec2<Length>, Vec2<Force>) is an energy, cross(r, F) a
// scalar of unit m N (the z component of the 3D cross product, A4 right-handed).
#pragma once

#include <cmath>
#include <type_traits>
#include <utility>

#include <boost/units/cmath.hpp>

#include "tamias2d/units/quantities.hpp"

namespace tamias2d::units {

template <class Q> struct Vec2 {
    Q x{};
    Q y{};

    friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
    friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
    friend constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
    constexpr Vec2& operator+=(Vec2 b) { return *this = *this + b; }
    constexpr Vec2& operator-=(Vec2 b) { return *this = *this - b; }
    friend constexpr bool operator==(const Vec2&, const Vec2&) = default;
};

template <class Q> Vec2(Q, Q) -> Vec2<Q>;

template <class A, class B> using product_t = decltype(std::declval<A>() * std::declval<B>());
template <class A, class B> using quotient_t = decltype(std::declval<A>() / std::declval<B>());

/// Scalar (quantity or double) times vector.
template <class S, class Q> constexpr Vec2<product_t<S, Q>> operator*(S s, Vec2<Q> v) {
    return {s * v.x, s * v.y};
}
template <class Q, class S> constexpr Vec2<product_t<Q, S>> operator*(Vec2<Q> v, S s) {
    return {v.x * s, v.y * s};
}
template <class Q, class S> constexpr Vec2<quotient_t<Q, S>> operator/(Vec2<Q> v, S s) {
    return {v.x / s, v.y / s};
}

template <class A, class B> constexpr product_t<A, B> dot(Vec2<A> a, Vec2<B> b) {
    return a.x * b.x + a.y * b.y;
}

/// z component of (a, 0) x (b, 0).
template <class A, class B> constexpr product_t<A, B> cross(Vec2<A> a, Vec2<B> b) {
    return a.x * b.y - a.y * b.x;
}

/// (0, 0, w) x (r, 0): a scalar about z crossed with an in-plane vector.
template <class W, class R> constexpr Vec2<product_t<W, R>> cross(W w, Vec2<R> r) {
    return {-w * r.y, w * r.x};
}

template <class Q> constexpr auto norm_squared(Vec2<Q> v) {
    return dot(v, v);
}
template <class Q> Q norm(Vec2<Q> v) {
    return boost::units::sqrt(norm_squared(v));
}

/// Strips units: the engine's storage is plain doubles (see docs/design.md).
template <class Q> constexpr std::pair<double, double> values(Vec2<Q> v) {
    return {v.x.value(), v.y.value()};
}
template <class Q> constexpr Vec2<Q> vec_from_values(double x, double y) {
    return {Q::from_value(x), Q::from_value(y)};
}

} // namespace tamias2d::units
