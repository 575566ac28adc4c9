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

/// \srs{IM1} One step of the semi-implicit (symplectic) Euler scheme for IM1, first order:
/// v(t + dt) = v(t) + a(t) dt (DD4), then p(t + dt) = p(t) + v(t + dt) dt (DD3).
/// The velocity is updated first so the scheme conserves a discrete energy for conservative
/// forces (no drift in orbits or springs), which explicit Euler does not.
inline TranslationalState step(TranslationalState s, Vec2<Acceleration> a, Time dt) {
    const Vec2<Velocity> v = s.v + dd04::velocity_change_over(a, dt);
    return {s.p + dd03::displacement_over(v, dt), v};
}

} // namespace tamias2d::model::im1
