/// \file
/// A world's definitions as a scene (io::scene_from_world): a world saved as a scene file when a
/// snapshot (World::snapshot) is more than is wanted.
#pragma once

#include "tamias2d/io/export.hpp"
#include "tamias2d/io/scene.hpp"

namespace tamias2d {

class World;

namespace io {

/// The scene that builds `world` as it is now (World::definitions): its settings, each live
/// body with its pose, velocities, persistent loads and settings now and its shapes, each joint
/// with its anchors where they are now. The state at this moment, not its history: contacts and
/// their warm-start impulses, joint impulses, sleep timers and the broad phase are not in a
/// scene, so a world built from it continues plausibly rather than bit for bit (bit for bit
/// when `world` has not stepped yet: World::definitions). dt, steps and output_every are the
/// scene's defaults (1/60 s, 0, 0): the world does not know them. A body a joint names keeps
/// its name if it is unique, else is named "body<index>" (a scene names a joint's bodies); other
/// bodies keep theirs. A body's load function stays in its BodyDef (build_world uses it), but a
/// function has no scene form: scene_to_json does not write it. A target joint (a drag by the
/// mouse) has no scene form either and is left out. Throws nothing.
TAMIAS2D_IO_EXPORT Scene scene_from_world(const World& world);

} // namespace io
} // namespace tamias2d
