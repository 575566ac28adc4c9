/// \file
/// A box as a scene holds it: the polygon of its four corners, with the vertex order, normals
/// and centroid polygon_shape derives from them. A scene writes a box as that polygon's points
/// (scene_to_json), and reading them back derives the same data from the same corners, so the
/// written form reproduces the box bit for bit. (box_shape's own centroid is its centre, which
/// its rounded corners do not give back to the last bit: read back as a polygon, such a box had
/// another centroid, by about 1e-17 m, and simulated differently.)
#pragma once

#include <span>

#include "tamias2d/errors.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/validation.hpp"

namespace tamias2d::io {

/// The polygon of a box_shape's corners, with its material, filter and sensor flag. A box the
/// library refuses (a sliver: validate(ShapeDef)) is returned as it is, for the World to refuse
/// with its own message; a box it accepts, polygon_shape accepts too (the one sliver rule,
/// DCX_shape).
inline ShapeDef box_polygon(const ShapeDef& box) {
    try {
        validate(box);
    } catch (const ValidationError&) {
        return box;
    }
    ShapeDef polygon = box;
    polygon.geometry =
        polygon_shape(std::span(box.geometry.polygon.vertices).first(4), box.material).geometry;
    return polygon;
}

} // namespace tamias2d::io
