// Erratum (DD2; srs/errata.yaml E04): the seed defines the linear displacement as
// r(t) = dp(t)/dt with the unit m. The derivative of a position is a velocity (m s^-1), so the
// seed's equation contradicts its own unit; the correct form is r(t) = p(t) - p(t0).
#include "tamias2d/model/dd02_linear_displacement.hpp"

using namespace tamias2d::units;

Vec2<Length> dd02_displacement() {
    const Vec2<Length> p_t0{1.0 * metre, 2.0 * metre};
    const Vec2<Length> p_t{1.5 * metre, 1.0 * metre};
#ifdef TAMIAS_WRONG_FORM
    // r = dp/dt, as a finite difference over dt: a velocity assigned to a length.
    const Time dt = 0.5 * second;
    const Length r_x = (p_t.x - p_t0.x) / dt;
    const Length r_y = (p_t.y - p_t0.y) / dt;
    return {r_x, r_y};
#else
    return tamias2d::model::dd02::linear_displacement(p_t, p_t0);
#endif
}
