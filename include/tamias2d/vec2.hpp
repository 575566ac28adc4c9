/// \file
/// Two-component vectors: positions, velocities, forces and impulses in the plane (SRS A2: all
/// objects are 2D; A3/A4: x to the right, y up, angles counter-clockwise).
#pragma once

#include <utility>

namespace tamias2d {

/// A vector in the plane whose components have type `T`.
///
/// The API uses `Vec2<double>` (Vec2d), with the unit stated beside each field (m, m s^-1, N,
/// N s). The library's model layer instantiates the same template with Boost.Units quantities,
/// so that a formula such as r x F is checked for its units at compile time; nothing of that
/// reaches a program that includes only the public headers.
template <class T> struct Vec2 {
    T x{}; ///< component along the x axis (to the right)
    T y{}; ///< component along the y axis (up)

    /// Component-wise sum.
    friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
    /// Component-wise difference.
    friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
    /// The opposite vector.
    friend constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
    /// Adds `b` in place.
    constexpr Vec2& operator+=(Vec2 b) { return *this = *this + b; }
    /// Subtracts `b` in place.
    constexpr Vec2& operator-=(Vec2 b) { return *this = *this - b; }
    /// Exact component-wise equality (no tolerance).
    friend constexpr bool operator==(const Vec2&, const Vec2&) = default;
};

/// Deduces `Vec2<T>` from two components of the same type.
template <class T> Vec2(T, T) -> Vec2<T>;

/// The vector type of the public API: SI values as doubles.
using Vec2d = Vec2<double>;

namespace detail {
/// The type of a * b (a unit-typed product keeps its units).
template <class A, class B> using product_t = decltype(std::declval<A>() * std::declval<B>());
/// The type of a / b.
template <class A, class B> using quotient_t = decltype(std::declval<A>() / std::declval<B>());
} // namespace detail

/// A scalar times a vector.
template <class S, class T> constexpr Vec2<detail::product_t<S, T>> operator*(S s, Vec2<T> v) {
    return {s * v.x, s * v.y};
}
/// A vector times a scalar.
template <class T, class S> constexpr Vec2<detail::product_t<T, S>> operator*(Vec2<T> v, S s) {
    return {v.x * s, v.y * s};
}
/// A vector divided by a scalar.
template <class T, class S> constexpr Vec2<detail::quotient_t<T, S>> operator/(Vec2<T> v, S s) {
    return {v.x / s, v.y / s};
}

/// The dot product a . b.
template <class A, class B> constexpr detail::product_t<A, B> dot(Vec2<A> a, Vec2<B> b) {
    return a.x * b.x + a.y * b.y;
}

/// The z component of the 3D cross product (a, 0) x (b, 0) (right-handed, A4).
template <class A, class B> constexpr detail::product_t<A, B> cross(Vec2<A> a, Vec2<B> b) {
    return a.x * b.y - a.y * b.x;
}

/// (0, 0, w) x (r, 0): a rate or a scalar about z crossed with an in-plane vector, e.g. the
/// velocity w x r of a point at r on a body spinning at w.
template <class W, class R> constexpr Vec2<detail::product_t<W, R>> cross(W w, Vec2<R> r) {
    return {-w * r.y, w * r.x};
}

/// |v|^2 = v . v.
template <class T> constexpr auto norm_squared(Vec2<T> v) {
    return dot(v, v);
}

} // namespace tamias2d
