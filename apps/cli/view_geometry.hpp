// Shapes and points as the player's drawing code (apps/cli/player/player.js, TamiasDraw)
// reads them: written by `tamias2d view` into its pages and by the live sandbox's binding.
#pragma once

#include <nlohmann/json.hpp>

#include "tamias2d/world.hpp"

namespace tamias2d::view {

/// [x, y].
nlohmann::json point_json(Vec2d v);

/// One geometry in its body frame, by its keys: circle {c, r}, polygon {p: [x0, y0, ...]},
/// capsule {cap: [x1, y1, x2, y2], r}, segment {seg: ends}, chain edge {edge: ends} (its
/// ghosts matter to collisions only).
nlohmann::json geometry_json(const Geometry& g);

/// A world point in the body's frame (relative to the body origin, as shapes are placed).
Vec2d to_body_frame(const World& world, BodyId id, Vec2d p);

} // namespace tamias2d::view
