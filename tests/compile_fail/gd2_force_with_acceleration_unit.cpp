// Erratum (GD2; srs/errata.yaml E10): GD2 defines F_g = m g but lists its unit as m s^-2, the
// unit of g. m g is a force (N = kg m s^-2); a quantity in m s^-2 cannot hold it.
#include "tamias2d/model/gd2_gravity.hpp"

using namespace tamias2d::units;

double gd2_force_y() {
    const Mass m = 56.2 * kilogram;
    const Acceleration g_y = 9.81 * metre / (second * second);
    const Vec2<Acceleration> g = tamias2d::model::gd2::gravity_vector(0.0 * g_y, g_y);
#ifdef TAMIAS_WRONG_FORM
    const Vec2<Acceleration> F_g = tamias2d::model::gd2::gravitational_force(m, g); // "m s^-2"
#else
    const Vec2<Force> F_g = tamias2d::model::gd2::gravitational_force(m, g);
#endif
    return F_g.y.value();
}
