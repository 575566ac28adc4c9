// Erratum (GD2, SRS 2.2 Table of Symbols; srs/errata.yaml E02): the unit vectors i-hat and
// j-hat are given the unit m. A unit vector is dimensionless: with i-hat in metres, a speed
// times i-hat is in m^2 s^-1, not a velocity, and GD2's "-g_x i-hat" would be in m^2 s^-2, not
// an acceleration.
#include "tamias2d/units/vec2.hpp"

using namespace tamias2d::units;

Vec2<Acceleration> gd2_gravity_from_unit_vectors() {
    const Acceleration g_y = 9.81 * metre / (second * second);
    const Velocity speed = 2.51 * metre / second;
#ifdef TAMIAS_WRONG_FORM
    const Vec2<Length> i_hat{1.0 * metre, 0.0 * metre};
    const Vec2<Length> j_hat{0.0 * metre, 1.0 * metre};
    const Vec2<Velocity> v = speed * i_hat;
    const Vec2<Acceleration> g = -g_y * j_hat;
#else
    const Vec2<double> i_hat{1.0, 0.0};
    const Vec2<double> j_hat{0.0, 1.0};
    const Vec2<Velocity> v = speed * i_hat;
    const Vec2<Acceleration> g = -g_y * j_hat;
#endif
    return g + v / (1.0 * second);
}
