/// \file
/// What the user learns about contacts after each step (SRS R7, R8).
#pragma once

#include "tamias2d/handles.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// One point of a contact manifold.
struct ContactPointInfo {
    Vec2d point{};               ///< m, world frame
    double separation = 0.0;     ///< m, negative when overlapping (measured before the step)
    double normal_impulse = 0.0; ///< N s, total over the step (DD8's j when A5-A7 hold)
    /// N s, friction (LC2), along t = (n.y, -n.x) (n: ContactInfo::normal); like the normal
    /// impulse, it acts on body_b as given and on body_a with the opposite sign.
    double tangent_impulse = 0.0;
};

/// A touching pair. `normal` is a unit vector from shape_a into shape_b.
struct ContactInfo {
    ShapeId shape_a;              ///< the first shape of the pair
    ShapeId shape_b;              ///< the second shape of the pair
    BodyId body_a;                ///< the body carrying shape_a
    BodyId body_b;                ///< the body carrying shape_b
    Vec2d normal{};               ///< unit, from shape_a into shape_b (DD4's n)
    int point_count = 0;          ///< 1 or 2: how many of `points` hold a point
    ContactPointInfo points[2]{}; ///< the manifold's points (two for a face-to-face contact)
};

/// A pair that began or ended touching during the last step.
struct ContactEvent {
    ShapeId shape_a; ///< the first shape of the pair
    ShapeId shape_b; ///< the second shape of the pair
    BodyId body_a;   ///< the body carrying shape_a (as it was when the event happened)
    BodyId body_b;   ///< the body carrying shape_b
};

/// \srs{DD28} A shape that began or ended overlapping a sensor during the last step.
struct SensorEvent {
    ShapeId sensor;      ///< the sensor shape
    ShapeId visitor;     ///< the shape that entered or left it
    BodyId sensor_body;  ///< the body carrying the sensor (as it was when the event happened)
    BodyId visitor_body; ///< the body carrying the visitor
};

} // namespace tamias2d
