#include "system/constrained_chain_reference.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

namespace tamias2d::system_test {

namespace {

Eigen::Vector2d rotate(double phi, const Eigen::Vector2d& v) {
    const double c = std::cos(phi), s = std::sin(phi);
    return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

/// d/dphi of rotate(phi, v) is perp(rotate(phi, v)): the velocity of a body point per rad s^-1.
Eigen::Vector2d perp(const Eigen::Vector2d& a) {
    return {-a.y(), a.x()};
}

int chain_ode(double, const double y[], double dydt[], void* params) {
    const auto& chain = *static_cast<const ChainReference*>(params);
    const Eigen::Index n = 3 * chain.size();
    const Eigen::Map<const Eigen::VectorXd> state(y, 2 * n);
    Eigen::Map<Eigen::VectorXd> derivative(dydt, 2 * n);
    derivative.head(n) = state.tail(n);
    derivative.tail(n) = chain.accelerations(state);
    return GSL_SUCCESS;
}

} // namespace

ChainReference::ChainReference(std::vector<ChainLink> links, Eigen::Vector2d pivot, double g)
    : links_(std::move(links)), pivot_(pivot), g_(g) {
    if (links_.empty())
        throw std::invalid_argument("a chain needs at least one link");
}

Eigen::VectorXd ChainReference::state(const std::vector<double>& phi,
                                      const std::vector<double>& omega) const {
    const int N = size();
    if (static_cast<int>(phi.size()) != N ||
        (!omega.empty() && static_cast<int>(omega.size()) != N))
        throw std::invalid_argument("one angle (and angular velocity) per link");
    Eigen::VectorXd y = Eigen::VectorXd::Zero(6 * N);
    Eigen::Vector2d pin = pivot_, pin_velocity{0.0, 0.0};
    for (int i = 0; i < N; ++i) {
        const double w = omega.empty() ? 0.0 : omega[static_cast<std::size_t>(i)];
        // The centre hangs from the pin, and moves with it plus its turn about it.
        const Eigen::Vector2d r = rotate(phi[static_cast<std::size_t>(i)], link(i).parent_pin);
        const Eigen::Vector2d x = pin - r, v = pin_velocity - w * perp(r);
        y.segment<3>(3 * i) << x.x(), x.y(), phi[static_cast<std::size_t>(i)];
        y.segment<3>(3 * N + 3 * i) << v.x(), v.y(), w;
        const Eigen::Vector2d s = rotate(phi[static_cast<std::size_t>(i)], link(i).child_pin);
        pin = x + s;
        pin_velocity = v + w * perp(s);
    }
    return y;
}

Eigen::Vector2d ChainReference::parent_pin_position(const Eigen::VectorXd& y, int i) const {
    if (i == 0)
        return pivot_;
    const Eigen::Index j = 3 * (i - 1);
    return Eigen::Vector2d{y[j], y[j + 1]} + rotate(y[j + 2], link(i - 1).child_pin);
}

Eigen::VectorXd ChainReference::constraints(const Eigen::VectorXd& q) const {
    const int N = size();
    Eigen::VectorXd c(2 * N);
    for (int k = 0; k < N; ++k) {
        const Eigen::Vector2d x{q[3 * k], q[3 * k + 1]};
        c.segment<2>(2 * k) =
            x + rotate(q[3 * k + 2], link(k).parent_pin) - parent_pin_position(q, k);
    }
    return c;
}

Eigen::MatrixXd ChainReference::jacobian(const Eigen::VectorXd& q) const {
    const int N = size();
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(2 * N, 3 * N);
    for (int k = 0; k < N; ++k) {
        J.block<2, 2>(2 * k, 3 * k).setIdentity();
        J.block<2, 1>(2 * k, 3 * k + 2) = perp(rotate(q[3 * k + 2], link(k).parent_pin));
        if (k > 0) {
            J.block<2, 2>(2 * k, 3 * (k - 1)) = -Eigen::Matrix2d::Identity();
            J.block<2, 1>(2 * k, 3 * (k - 1) + 2) =
                -perp(rotate(q[3 * (k - 1) + 2], link(k - 1).child_pin));
        }
    }
    return J;
}

Eigen::VectorXd ChainReference::accelerations(const Eigen::VectorXd& y) const {
    const int N = size(), n = 3 * N, c = 2 * N;
    const Eigen::VectorXd q = y.head(n), u = y.tail(n);
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + c, n + c);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + c);
    for (int i = 0; i < N; ++i) {
        K(3 * i, 3 * i) = K(3 * i + 1, 3 * i + 1) = link(i).mass;
        K(3 * i + 2, 3 * i + 2) = link(i).inertia;
        rhs[3 * i + 1] = -link(i).mass * g_;
    }
    const Eigen::MatrixXd J = jacobian(q);
    K.topRightCorner(n, c) = J.transpose();
    K.bottomLeftCorner(c, n) = J;
    // Jdot u: a point r of a body turning at omega accelerates by -omega^2 r beyond J's terms.
    for (int k = 0; k < N; ++k) {
        const double w = u[3 * k + 2];
        Eigen::Vector2d jdot_u = -w * w * rotate(q[3 * k + 2], link(k).parent_pin);
        if (k > 0) {
            const double w_prev = u[3 * (k - 1) + 2];
            jdot_u += w_prev * w_prev * rotate(q[3 * (k - 1) + 2], link(k - 1).child_pin);
        }
        rhs.segment<2>(n + 2 * k) = -jdot_u;
    }
    return K.partialPivLu().solve(rhs).head(n);
}

double ChainReference::energy(const Eigen::VectorXd& y) const {
    const int N = size();
    double e = 0.0;
    for (int i = 0; i < N; ++i) {
        const Eigen::Index v = 3 * N + 3 * i;
        e += 0.5 * link(i).mass * (y[v] * y[v] + y[v + 1] * y[v + 1]) +
             0.5 * link(i).inertia * y[v + 2] * y[v + 2] + link(i).mass * g_ * y[3 * i + 1];
    }
    return e;
}

ChainTrajectory ChainReference::integrate(const Eigen::VectorXd& y0, double dt, int samples,
                                          double tolerance) const {
    const int n = 3 * size();
    // GSL passes its parameters as void*; chain_ode only reads them.
    gsl_odeiv2_system sys{chain_ode, nullptr, static_cast<std::size_t>(2 * n),
                          const_cast<ChainReference*>(this)};
    gsl_odeiv2_driver* driver =
        gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, dt / 16.0, tolerance, tolerance);
    ChainTrajectory out;
    out.dt = dt;
    out.states.reserve(static_cast<std::size_t>(samples) + 1);
    Eigen::VectorXd y = y0;
    const double e0 = energy(y0);
    double t = 0.0;
    for (int k = 0; k <= samples; ++k) {
        if (k > 0) {
            const int status = gsl_odeiv2_driver_apply(driver, &t, k * dt, y.data());
            if (status != GSL_SUCCESS) {
                gsl_odeiv2_driver_free(driver);
                throw std::runtime_error("rk8pd failed: " + std::string(gsl_strerror(status)));
            }
        }
        const Eigen::VectorXd gap = constraints(y.head(n));
        const Eigen::VectorXd speed = jacobian(y.head(n)) * y.tail(n);
        for (int p = 0; p < size(); ++p) {
            out.max_pin_gap = std::max(out.max_pin_gap, gap.segment<2>(2 * p).norm());
            out.max_pin_speed = std::max(out.max_pin_speed, speed.segment<2>(2 * p).norm());
        }
        out.max_energy_drift = std::max(out.max_energy_drift, std::abs(energy(y) - e0));
        out.states.push_back(y);
    }
    gsl_odeiv2_driver_free(driver);
    return out;
}

} // namespace tamias2d::system_test
