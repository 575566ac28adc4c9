// Erratum (DD5; srs/errata.yaml E05): the seed defines the angular displacement as
// theta(t) = d phi(t)/dt with the unit rad. The derivative of an orientation is an angular
// velocity (rad s^-1); the correct form is theta(t) = phi(t) - phi(t0).
#include "tamias2d/model/dd05_angular_displacement.hpp"

using namespace tamias2d::units;

Angle dd05_displacement() {
    const Angle phi_t0 = 0.25 * radian;
    const Angle phi_t = 1.75 * radian;
#ifdef TAMIAS_WRONG_FORM
    // theta = d phi / dt, as a finite difference: an angular velocity assigned to an angle.
    const Time dt = 0.5 * second;
    const Angle theta = (phi_t - phi_t0) / dt;
    return theta;
#else
    return tamias2d::model::dd05::angular_displacement(phi_t, phi_t0);
#endif
}
