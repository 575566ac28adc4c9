#pragma once
#include "tamias2d/model/dd03_linear_velocity.hpp"
#include "tamias2d/model/dd04_linear_acceleration.hpp"
#include "tamias2d/model/t1_newtons_second_law.hpp"

namespace tamias2d::model::im1 {
using namespace tamias2d::units;

/// \srs{IM1} The ODE of translational motion: a_i(t) = dv_i/dt = g + F_i(t) / m_i.
/// (GD2 and T1: gravity contributes m g to the force, hence g to the acceleration.)
inline Vec2<Acceleration> acceleration(Vec2<Acceleration> g, Vec2<Force> F, Mass m) {
    return g + t1::acceleration(F, m);
}

struct TranslationalState {
    Vec2<Length> p;
    Vec2<Velocity> v;
};

/// \srs{IM1} The velocity half of the step: v(t + dt) = v(t) + a(t) dt (DD4).
inline Vec2<Velocity> velocity_half(Vec2<Velocity> v, Vec2<Acceleration> a, Time dt) {
    return v + dd04::velocity_change_over(a, dt);
}

/// \srs{IM1} The position half, with the velocity at the step's end: p + v(t + dt) dt (DD3).
/// The engine runs the two halves with its contact and joint iterations between them.
inline Vec2<Length> position_half(Vec2<Length> p, Vec2<Velocity> v_end, Time dt) {
    return p + dd03::displacement_over(v_end, dt);
}

/// \srs{IM1} One step of the semi-implicit (symplectic) Euler scheme for IM1, first order: the
/// velocity half, then the position half with the new velocity. The velocity is updated first
/// so the scheme conserves a discrete energy for conservative forces (no drift in orbits or
/// springs), which explicit Euler does not.
inline TranslationalState step(TranslationalState s, Vec2<Acceleration> a, Time dt) {
    const Vec2<Velocity> v = velocity_half(s.v, a, dt);
    return {position_half(s.p, v, dt), v};
}

} // namespace tamias2d::model::im1
