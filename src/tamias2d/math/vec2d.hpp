// Plain-double geometry for the engine's hot paths: the engine stores SI values as doubles and
// wraps them in Boost.Units quantities only where it calls the model layer (inlined, free).
#pragma once

#include <cmath>

#include "tamias2d/model/dd32_rotation.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// A rotation by angle phi (radians, CCW positive, A4) as its cosine and sine.
struct Rot {
    double c = 1.0;
    double s = 0.0;
    /// \srs{DD32} R(phi), the model's (the project's own sincos, not the C library's).
    static Rot from_angle(double phi) {
        const model::dd32::Rotation r = model::dd32::rotation(units::from_value<units::Angle>(phi));
        return {r.cos.value(), r.sin.value()};
    }
};

/// R v for a rotation given by its cosine and sine, values of type V (double, or a pack of lanes
/// turning four vectors at once: joints/pin_packs.cpp).
template <class V> constexpr Vec2<V> rotate(V c, V s, Vec2<V> v) {
    return {c * v.x - s * v.y, s * v.x + c * v.y};
}
constexpr Vec2d rotate(Rot q, Vec2d v) {
    return rotate(q.c, q.s, v);
}
constexpr Vec2d inv_rotate(Rot q, Vec2d v) {
    return {q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y};
}

/// A rigid transform: rotate, then translate.
struct Transform {
    Vec2d p{};
    Rot q{};
};

constexpr Vec2d transform_point(const Transform& t, Vec2d v) {
    return rotate(t.q, v) + t.p;
}
constexpr Vec2d inv_transform_point(const Transform& t, Vec2d v) {
    return inv_rotate(t.q, v - t.p);
}

/// The in-plane perpendicular (CCW): cross(w, v) for w = 1 (of a vector or a pack of lanes).
template <class T> constexpr Vec2<T> left_perp(Vec2<T> v) {
    return {-v.y, v.x};
}
template <class T> constexpr Vec2<T> right_perp(Vec2<T> v) {
    return {v.y, -v.x};
}

inline double length(Vec2d v) {
    return std::sqrt(v.x * v.x + v.y * v.y);
}

/// Unit vector along v, or (0, 0) for a zero vector.
inline Vec2d normalize(Vec2d v) {
    const double l = length(v);
    return l > 0.0 ? Vec2d{v.x / l, v.y / l} : Vec2d{};
}

} // namespace tamias2d
