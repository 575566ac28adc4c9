#include "tamias2d/shape_def.hpp"

#include "tamias2d/geometry/shape_factory.hpp"

namespace tamias2d {

ShapeDef box_shape(double width, double height, Material material, Vec2d center, double angle) {
    return {to_geometry(make_box(0.5 * width, 0.5 * height, center, angle)), material};
}

ShapeDef circle_shape(double radius, Material material, Vec2d center) {
    return {to_geometry(make_circle(radius, center)), material};
}

ShapeDef polygon_shape(std::span<const Vec2d> points, Material material) {
    return {to_geometry(make_polygon(points)), material};
}

} // namespace tamias2d
