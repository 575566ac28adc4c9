// The stacked pyramid several tests step: `base` rows of touching 1 m boxes (density 1,
// friction 0.6) on a static ground 2 base + 10 m wide whose top face is y = 0, created ground
// first, then row by row from the bottom, each row left to right.
#pragma once

#include "tamias2d/world.hpp"

namespace tamias2d::test {

inline void build_pyramid(World& world, int base) {
    const Material wood{1.0, 0.0, 0.6};
    BodyDef ground;
    ground.type = BodyType::static_body;
    ground.position = {0.0, -0.5};
    world.create_shape(world.create_body(ground), box_shape(2.0 * base + 10.0, 1.0, wood));
    for (int row = 0; row < base; ++row) {
        const int n = base - row;
        for (int col = 0; col < n; ++col) {
            BodyDef d;
            d.position = {col - 0.5 * (n - 1), 0.5 + row};
            world.create_shape(world.create_body(d), box_shape(1.0, 1.0, wood));
        }
    }
}

} // namespace tamias2d::test
