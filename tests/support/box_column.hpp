// A column several tests rest: `height` touching 1 m boxes (density 1, friction 0.6, C_R 0) on a
// static ground 20 m wide whose top face is y = 0, box k's centre at (0, k + 0.5), created
// ground first, then from the bottom up.
#pragma once

#include <vector>

#include "tamias2d/world.hpp"

namespace tamias2d::test {

/// Builds the column into `world`; returns its boxes, the lowest first.
inline std::vector<BodyId> build_box_column(World& world, int height) {
    const Material wood{1.0, 0.0, 0.6};
    BodyDef ground;
    ground.type = BodyType::static_body;
    ground.position = {0.0, -0.5};
    world.create_shape(world.create_body(ground), box_shape(20.0, 1.0, wood));
    std::vector<BodyId> boxes;
    for (int k = 0; k < height; ++k) {
        BodyDef d;
        d.position = {0.0, k + 0.5};
        boxes.push_back(world.create_body(d));
        world.create_shape(boxes.back(), box_shape(1.0, 1.0, wood));
    }
    return boxes;
}

} // namespace tamias2d::test
