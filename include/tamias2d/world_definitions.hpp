/// \file
/// The definitions that build a world as it is now (World::definitions): what a scene file
/// (io::scene_from_world) or an editor keeps when a snapshot is more than it wants.
#pragma once

#include <variant>
#include <vector>

#include "tamias2d/body_def.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/joint_def.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/world_def.hpp"

namespace tamias2d {

/// A joint's definition, of whichever kind it is.
using JointDefinition =
    std::variant<RevoluteJointDef, DistanceJointDef, TargetJointDef, PrismaticJointDef,
                 WeldJointDef, WheelJointDef, MotorJointDef, FilterJointDef>;

/// A body as World::create_body takes it, with its shapes as create_shape takes them.
struct BodyDefinition {
    BodyId id;                    ///< the body in the world the definitions were read from
    BodyDef def;                  ///< its state now (pose, velocities, loads, settings)
    std::vector<ShapeDef> shapes; ///< its shapes, in their order on the body
};

/// The world's settings, bodies (in handle index order) and joints (in handle index order),
/// the joints' bodies named by the handles of `bodies`.
struct WorldDefinitions {
    WorldDef world;                      ///< the settings (gravity as it is now)
    std::vector<BodyDefinition> bodies;  ///< the live bodies, in handle index order
    std::vector<JointDefinition> joints; ///< the live joints, in handle index order
};

} // namespace tamias2d
