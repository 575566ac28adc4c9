#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd02 {
using namespace tamias2d::units;

/// \srs{DD2} Linear displacement r(t) = p(t) - p(t0) (m). The SRS writes r(t) = dp/dt, which is a
/// velocity, not a length (erratum; tests/compile_fail proves that form does not type-check).
inline Vec2<Length> linear_displacement(Vec2<Length> p_t, Vec2<Length> p_t0) {
    return p_t - p_t0;
}

} // namespace tamias2d::model::dd02
