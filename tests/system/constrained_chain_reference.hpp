// An independent reference for planar chains of rigid links joined by pins (a pendulum, a double
// pendulum, an N-link chain): the constrained equations of motion that IM6's soft step
// approximates, written in maximal coordinates and solved exactly at every evaluation. Shares no
// code with the engine: Eigen assembles the mass matrix, the pins' Jacobian and the KKT system;
// GSL's rk8pd integrates it without Baumgarte stabilisation, so the reference's own constraint
// and energy drifts measure its accuracy and are reported with every trajectory.
#pragma once

#include <vector>

#include <Eigen/Dense>

namespace tamias2d::system_test {

/// One rigid link: mass (kg), moment of inertia about its centre of mass (kg m^2), and its two
/// pins in its own frame (m, from the centre, at angle 0).
struct ChainLink {
    double mass = 0.0;
    double inertia = 0.0;
    Eigen::Vector2d parent_pin{0.0, 0.0}; ///< held on the pivot (link 1) or the previous link
    Eigen::Vector2d child_pin{0.0, 0.0};  ///< the next link hangs here
};

/// A trajectory sampled at t = k dt, k = 0..samples, and the reference's own errors over it.
struct ChainTrajectory {
    double dt = 0.0;
    std::vector<Eigen::VectorXd> states; ///< y = (q, u), see ChainReference
    double max_pin_gap = 0.0;            ///< m: the largest |C(q)| of any pin
    double max_pin_speed = 0.0;          ///< m s^-1: the largest |J u| of any pin
    double max_energy_drift = 0.0;       ///< J: the largest |E(t) - E(0)|
};

/// Link i (0-based) has q = (x_i, y_i, phi_i) (centre of mass, m; angle, rad) and u = (vx_i,
/// vy_i, omega_i); y = (q_0 .. q_{N-1}, u_0 .. u_{N-1}). Pin 0 holds link 0's parent pin on the
/// fixed pivot, pin k > 0 holds link k's parent pin on link k-1's child pin: C_k(q) = 0, two
/// rows each. Gravity is (0, -g).
class ChainReference {
  public:
    ChainReference(std::vector<ChainLink> links, Eigen::Vector2d pivot, double g);

    int size() const { return static_cast<int>(links_.size()); }
    const ChainLink& link(int i) const { return links_[static_cast<std::size_t>(i)]; }

    /// A state satisfying the constraints and their time derivative: the links at angles phi
    /// (rad) turning at omega (rad s^-1, default 0), each centre placed from the pins.
    Eigen::VectorXd state(const std::vector<double>& phi,
                          const std::vector<double>& omega = {}) const;
    /// The world position (m) of link i's parent pin: the pivot for i = 0. Reads only the
    /// positions, so y may be a state or q alone.
    Eigen::Vector2d parent_pin_position(const Eigen::VectorXd& y, int i) const;

    Eigen::VectorXd constraints(const Eigen::VectorXd& q) const; ///< C(q), 2N
    Eigen::MatrixXd jacobian(const Eigen::VectorXd& q) const;    ///< dC/dq, 2N x 3N
    /// The accelerations from [M J^T; J 0] [a; -lambda] = [f; -Jdot u] (dense LU).
    Eigen::VectorXd accelerations(const Eigen::VectorXd& y) const;
    /// Kinetic (DD15, with rotation) plus potential (DD16, origin as reference) energy, J.
    double energy(const Eigen::VectorXd& y) const;

    /// Integrates from y0 with GSL rk8pd at the given absolute and relative tolerance and
    /// returns samples + 1 states t = 0, dt, ..., samples dt.
    ChainTrajectory integrate(const Eigen::VectorXd& y0, double dt, int samples,
                              double tolerance = 1e-12) const;

  private:
    std::vector<ChainLink> links_;
    Eigen::Vector2d pivot_;
    double g_;
};

} // namespace tamias2d::system_test
