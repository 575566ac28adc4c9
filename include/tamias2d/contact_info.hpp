// What the user learns about contacts after each step (SRS R7, R8).
#pragma once

#include "tamias2d/handles.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

struct ContactPointInfo {
    Vec2d point{};                ///< m, world frame
    double separation = 0.0;      ///< m, negative when overlapping (measured before the step)
    double normal_impulse = 0.0;  ///< N s, total over the step (DD8's j when A5-A7 hold)
    double tangent_impulse = 0.0; ///< N s, friction (LC2)
};

/// A touching pair. `normal` is a unit vector from shape_a into shape_b.
struct ContactInfo {
    ShapeId shape_a;
    ShapeId shape_b;
    BodyId body_a;
    BodyId body_b;
    Vec2d normal{};
    int point_count = 0;
    ContactPointInfo points[2]{};
};

/// A pair that began or ended touching during the last step.
struct ContactEvent {
    ShapeId shape_a;
    ShapeId shape_b;
    BodyId body_a;
    BodyId body_b;
};

} // namespace tamias2d
