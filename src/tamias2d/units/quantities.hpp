// Boost.Units quantity aliases used by every model module (SRS Table of Units, section 2.1).
//
// Plane angle is a base dimension in Boost.Units, so the rotational quantities carry radians
// explicitly: torque is N m rad^-1, moment of inertia kg m^2 rad^-2, angular momentum
// kg m^2 s^-1 rad^-1. That keeps T4 (tau = I alpha) dimensionally exact; the price is an
// explicit `per_radian` where a cross product r x F turns into a torque (see moment_arm.hpp).
#pragma once

#include <boost/units/quantity.hpp>
#include <boost/units/systems/si/acceleration.hpp>
#include <boost/units/systems/si/angular_acceleration.hpp>
#include <boost/units/systems/si/angular_momentum.hpp>
#include <boost/units/systems/si/angular_velocity.hpp>
#include <boost/units/systems/si/area.hpp>
#include <boost/units/systems/si/dimensionless.hpp>
#include <boost/units/systems/si/energy.hpp>
#include <boost/units/systems/si/force.hpp>
#include <boost/units/systems/si/frequency.hpp>
#include <boost/units/systems/si/length.hpp>
#include <boost/units/systems/si/mass.hpp>
#include <boost/units/systems/si/moment_of_inertia.hpp>
#include <boost/units/systems/si/momentum.hpp>
#include <boost/units/systems/si/plane_angle.hpp>
#include <boost/units/systems/si/surface_density.hpp>
#include <boost/units/systems/si/time.hpp>
#include <boost/units/systems/si/torque.hpp>
#include <boost/units/systems/si/velocity.hpp>

namespace tamias2d::units {

namespace bu = boost::units;
namespace si = boost::units::si;

using Dimensionless = bu::quantity<si::dimensionless>;
using Length = bu::quantity<si::length>;
using Area = bu::quantity<si::area>;
using Mass = bu::quantity<si::mass>;
using Time = bu::quantity<si::time>;
using Velocity = bu::quantity<si::velocity>;
using Acceleration = bu::quantity<si::acceleration>;
using Force = bu::quantity<si::force>;
/// Impulse J = m dv (N s) has the dimension of momentum.
using Impulse = bu::quantity<si::momentum>;
using Momentum = bu::quantity<si::momentum>;
using Energy = bu::quantity<si::energy>;
using Angle = bu::quantity<si::plane_angle>;
using AngularVelocity = bu::quantity<si::angular_velocity>;
using AngularAcceleration = bu::quantity<si::angular_acceleration>;
using AngularMomentum = bu::quantity<si::angular_momentum>;
using Torque = bu::quantity<si::torque>;
using MomentOfInertia = bu::quantity<si::moment_of_inertia>;
/// A rate (s^-1): the damping rates of DD17 and DD18.
using Rate = bu::quantity<si::frequency>;
/// Mass per unit area (kg m^-2): the density of a 2D shape.
using AreaDensity = bu::quantity<si::surface_density>;

/// Inverse mass (kg^-1) and inverse moment of inertia (rad^2 kg^-1 m^-2): static bodies have 0.
using InverseMass = decltype(1.0 / Mass{});
using InverseMomentOfInertia = decltype(1.0 / MomentOfInertia{});

/// The quantity Q over another value type V: the solver's hot loop runs the same model
/// functions on a pack of lanes (math/wide.hpp), one contact per lane, with the same units.
template <class Q, class V> using Over = bu::quantity<typename Q::unit_type, V>;

inline constexpr auto metre = si::meter;
inline constexpr auto kilogram = si::kilogram;
inline constexpr auto second = si::second;
inline constexpr auto newton = si::newton;
inline constexpr auto joule = si::joule;
inline constexpr auto radian = si::radian;

/// Wraps a plain double in a quantity without a runtime cost (used at the engine's call sites).
template <class Q> constexpr Q from_value(double v) {
    return Q::from_value(v);
}

} // namespace tamias2d::units
