#pragma once
#include <span>

#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd01 {
using namespace tamias2d::units;

struct PointMass {
    Mass m;
    Vec2<Length> p;
};

/// \srs{DD1} Centre of mass p_CM = sum_i m_i p_i / M, M = sum_i m_i (> 0). Also combines
/// several shapes of one body, each given as its mass at its own centroid.
inline Vec2<Length> center_of_mass(std::span<const PointMass> particles) {
    Mass M{};
    Vec2<decltype(Mass{} * Length{})> moment{};
    for (const PointMass& q : particles) {
        M += q.m;
        moment += q.m * q.p;
    }
    return moment / M;
}

} // namespace tamias2d::model::dd01
