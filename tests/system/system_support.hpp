// Helpers shared by the system tests (TC1-TC11): body builders and history norms.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "tamias2d/world.hpp"

namespace tamias2d::system_test {

/// Accumulates an engine history and its oracle and returns the norm-relative error
/// ||got - want||_2 / ||want||_2 over every component of every sample.
class History {
  public:
    void add(double got, double want) {
        diff2_ += (got - want) * (got - want);
        ref2_ += want * want;
        max_abs_ = std::max(max_abs_, std::abs(got - want));
    }
    void add(Vec2d got, Vec2d want) {
        add(got.x, want.x);
        add(got.y, want.y);
    }
    double rel_error() const { return ref2_ > 0.0 ? std::sqrt(diff2_ / ref2_) : std::sqrt(diff2_); }
    double max_abs() const { return max_abs_; }

  private:
    double diff2_ = 0.0, ref2_ = 0.0, max_abs_ = 0.0;
};

/// A dynamic body with one box shape; mass and inertia follow from the density (DD1, DD14).
inline BodyId add_box(World& w, Vec2d p, Vec2d v, double width, double height, double density,
                      double restitution = 0.0) {
    BodyDef def;
    def.position = p;
    def.linear_velocity = v;
    const BodyId b = w.create_body(def);
    w.create_shape(b, box_shape(width, height, Material{density, restitution, 0.0}));
    return b;
}

/// A dynamic circle of radius r and mass m (density m / (pi r^2)).
inline BodyId add_circle(World& w, Vec2d p, Vec2d v, double r, double m, double restitution = 0.0) {
    BodyDef def;
    def.position = p;
    def.linear_velocity = v;
    const BodyId b = w.create_body(def);
    w.create_shape(b, circle_shape(r, Material{m / (std::numbers::pi * r * r), restitution, 0.0}));
    return b;
}

/// Unwraps an orientation reported in [0, 2 pi) into a continuous angle near `previous`.
inline double unwrap(double wrapped, double previous) {
    const double two_pi = 2.0 * std::numbers::pi;
    return wrapped + two_pi * std::round((previous - wrapped) / two_pi);
}

/// Semi-implicit Euler's exact discrete solution for a constant acceleration a after time t with
/// substep h: x_n = x0 + v0 t + a t^2 / 2 + a h t / 2 (the continuous solution plus its known
/// first-order error a h t / 2).
inline double discrete_position(double x0, double v0, double a, double t, double h) {
    return x0 + v0 * t + 0.5 * a * t * t + 0.5 * a * h * t;
}
inline Vec2d discrete_position(Vec2d x0, Vec2d v0, Vec2d a, double t, double h) {
    return {discrete_position(x0.x, v0.x, a.x, t, h), discrete_position(x0.y, v0.y, a.y, t, h)};
}
inline Vec2d continuous_position(Vec2d x0, Vec2d v0, Vec2d a, double t) {
    return {x0.x + v0.x * t + 0.5 * a.x * t * t, x0.y + v0.y * t + 0.5 * a.y * t * t};
}

inline double norm(Vec2d v) {
    return std::sqrt(v.x * v.x + v.y * v.y);
}

} // namespace tamias2d::system_test
