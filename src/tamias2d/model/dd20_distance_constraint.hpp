#pragma once
#include <cmath>

#include "tamias2d/model/dd08_collision_impulse.hpp"
#include "tamias2d/model/dd09_chasles_theorem.hpp"
#include "tamias2d/model/im3_collision_response.hpp"
#include "tamias2d/model/im6_motion_with_joints.hpp"
#include "tamias2d/units/angle.hpp"
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd20 {
using namespace tamias2d::units;
using dd08::InverseInertia;
using im3::Velocities;

/// \srs{DD20} The separation of the two anchors, d = (p_B + r_B) - (p_A + r_A), as its length
/// |d| and unit axis n = d / |d| (n = (1, 0) for anchors that coincide, where any axis holds).
struct Axis {
    Length length;
    Vec2<double> n;
};
inline Axis axis(Vec2<Length> d) {
    const Length length = norm(d);
    if (!(length.value() > 0.0))
        return {length, {1.0, 0.0}};
    return {length, {d.x / length, d.y / length}};
}

/// \srs{DD20} Position error C = |d| - L against the rest length L.
inline Length position_error(Axis a, Length rest_length) {
    return a.length - rest_length;
}

/// \srs{DD20} Velocity error Cdot = n . (v_B + omega_B x r_B - v_A - omega_A x r_A) (DD9 along
/// n at each anchor, from the moment arms r x n).
inline Velocity velocity_error(const Velocities& A, Length arm_A, const Velocities& B, Length arm_B,
                               Vec2<double> n) {
    return dd09::point_velocity_along(B.v, B.omega, arm_B, n) -
           dd09::point_velocity_along(A.v, A.omega, arm_A, n);
}

/// \srs{DD20} The impulse lambda = -mass_scale (Cdot + b) / K - impulse_scale lambda_acc along
/// n, K being DD8's denominator for the two anchors' moment arms (IM6's soft form; rigid:
/// mass_scale 1, impulse_scale 0; a spring of given stiffness and damping: their softness).
inline Impulse impulse(InverseInertia A, InverseInertia B, Length arm_A, Length arm_B, Velocity rhs,
                       Dimensionless mass_scale, Dimensionless impulse_scale, Impulse accumulated) {
    const InverseMass K = dd08::effective_mass_inverse(A, B, arm_A, arm_B);
    return im6::soft_impulse(mass_scale, -(rhs / K), impulse_scale, accumulated);
}

/// \srs{DD20} lambda n on B at its anchor and -lambda n on A (T2), as IM3 applies an impulse.
inline void apply(Velocities& A, Velocities& B, InverseInertia a, InverseInertia b, Length arm_A,
                  Length arm_B, Vec2<double> n, Impulse lambda) {
    im3::apply_impulse(B, A, b, a, arm_B, arm_A, n, lambda);
}

} // namespace tamias2d::model::dd20
