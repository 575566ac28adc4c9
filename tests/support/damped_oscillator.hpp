// The underdamped harmonic oscillator x'' = -omega^2 x - 2 zeta omega x' (omega = 2 pi f,
// 0 <= zeta < 1) in closed form: the oracle of every spring test (joint springs are
// spring-dampers of exactly this law for their effective mass, SRS IM6), shared by the joint
// tests of every kind.
#pragma once

#include <cmath>
#include <numbers>

namespace tamias2d::test {

struct DampedOscillator {
    double hertz, zeta;
    double omega() const { return 2.0 * std::numbers::pi * hertz; }
    double omega_d() const { return omega() * std::sqrt(1.0 - zeta * zeta); }
    /// x(t) released at rest from x0.
    double from_rest(double x0, double t) const {
        const double w = omega(), wd = omega_d();
        return x0 * std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
    }
    /// x(t) from x = 0 with speed v0.
    double from_speed(double v0, double t) const {
        return v0 / omega_d() * std::exp(-zeta * omega() * t) * std::sin(omega_d() * t);
    }
};

} // namespace tamias2d::test
