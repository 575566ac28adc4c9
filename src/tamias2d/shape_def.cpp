#include "tamias2d/shape_def.hpp"

#include "tamias2d/geometry/shape_factory.hpp"

namespace tamias2d {

ShapeDef box_shape(double width, double height, Material material, Vec2d center, double angle) {
    return {to_geometry(make_box_of_size(width, height, center, angle)), material};
}

ShapeDef circle_shape(double radius, Material material, Vec2d center) {
    return {to_geometry(make_circle(radius, center)), material};
}

ShapeDef polygon_shape(std::span<const Vec2d> points, Material material) {
    return {to_geometry(make_polygon(points)), material};
}

ShapeDef capsule_shape(Vec2d center1, Vec2d center2, double radius, Material material) {
    return {to_geometry(make_capsule(center1, center2, radius)), material};
}

ShapeDef segment_shape(Vec2d point1, Vec2d point2, Material material) {
    return {to_geometry(make_segment(point1, point2)), material};
}

std::vector<ShapeDef> chain_shapes(std::span<const Vec2d> points, bool loop, Material material) {
    std::vector<ShapeDef> out;
    for (const ChainSegment& s : make_chain(points, loop))
        out.push_back({to_geometry(s), material});
    return out;
}

} // namespace tamias2d
