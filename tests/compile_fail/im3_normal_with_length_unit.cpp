// Erratum (IM3; srs/errata.yaml E03): IM3 states j in N s and the collision normal n in m.
// Then the update v_A + j n / m_A adds m^2 s^-1 to a velocity, and
// omega_A + (r_AP x j n) / I_A adds m s^-1 to an angular velocity. (Computing j with DD8 and
// n in m gives kg s^-1 instead of N s and hides the first error: two wrong units cancel.)
// n is a dimensionless unit vector.
#include "tamias2d/model/im3_collision_response.hpp"

using namespace tamias2d::units;

tamias2d::model::im3::Velocities im3_update() {
    const Mass m_A = 2.0 * kilogram;
    const auto I_A = 0.5 * kilogram * metre * metre / (radian * radian);
    const Impulse j = 3.0 * newton * second;
    const Vec2<Length> r_AP{0.0 * metre, 1.0 * metre};
    tamias2d::model::im3::Velocities A{{1.0 * metre / second, 0.0 * metre / second},
                                       0.0 * radian / second};
#ifdef TAMIAS_WRONG_FORM
    const Vec2<Length> n{1.0 * metre, 0.0 * metre};
    A.v = A.v + j * n / m_A;
    A.omega = A.omega + per_radian(cross(r_AP, j * n)) / I_A;
#else
    const tamias2d::model::dd08::Normal n{1.0, 0.0};
    A.v = A.v + j * n / m_A;
    A.omega = A.omega + per_radian(cross(r_AP, j * n)) / I_A;
#endif
    return A;
}
