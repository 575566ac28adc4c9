// A body as the world stores it (internal). Public access goes through World and BodyId.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tamias2d/body_def.hpp"
#include "tamias2d/math/vec2d.hpp"

namespace tamias2d {

struct Body {
    std::uint32_t generation = 0;
    bool alive = false;
    BodyType type = BodyType::dynamic;
    std::string name;

    Transform xf{};     ///< body origin and rotation
    double angle = 0.0; ///< rad, unwrapped phi (wrapped only on output)
    Vec2d center{};     ///< m, centre of mass, world frame (the SRS's p)
    Vec2d local_center{};
    Vec2d v{};      ///< m s^-1
    double w = 0.0; ///< rad s^-1

    Vec2d force{};       ///< N, persistent
    double torque = 0.0; ///< N m, persistent
    Vec2d force_once{};  ///< N, next step only
    double torque_once = 0.0;
    LoadFunction load;

    double mass = 0.0, inv_mass = 0.0;
    double inertia = 0.0, inv_inertia = 0.0;
    std::optional<double> mass_override, inertia_override;
    double gravity_scale = 1.0;
    bool fixed_rotation = false;

    std::vector<std::uint32_t> shapes;
};

} // namespace tamias2d
