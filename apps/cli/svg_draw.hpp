// An SVG writer for World::draw: a DebugDraw that keeps the primitives it is handed and writes
// them as one SVG picture, y up, framed on what was drawn.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "tamias2d/debug_draw.hpp"

namespace tamias2d::cli {

class SvgDraw : public DebugDraw {
  public:
    /// `width_px`: the picture's width in pixels (its height follows the drawing's aspect).
    explicit SvgDraw(double width_px = 1000.0) : width_px_(width_px) {}

    void polygon(std::span<const Vec2d> vertices, Color color) override;
    void solid_polygon(std::span<const Vec2d> vertices, Color color) override;
    void solid_circle(Vec2d center, double radius, double angle, Color color) override;
    void solid_capsule(Vec2d p1, Vec2d p2, double radius, Color color) override;
    void segment(Vec2d p1, Vec2d p2, Color color) override;
    void transform(Vec2d origin, double angle, double length) override;
    void point(Vec2d p, double size, Color color) override;

    /// How many primitives of each kind were drawn (the tool prints them).
    struct Counts {
        std::size_t polygons = 0, solid_polygons = 0, circles = 0, capsules = 0, segments = 0,
                    transforms = 0, points = 0;
    };
    const Counts& counts() const { return counts_; }

    /// The picture: the world box of everything drawn (a 1 m square around the origin when
    /// nothing was), a 5 % margin, a dark background; `title` in its <title>.
    void write(std::ostream& out, const std::string& title) const;

  private:
    /// One element: its SVG text in world coordinates, written inside a y-flipping group; the
    /// points' radii are in pixels and scaled when written (marked by `point_size` > 0).
    struct Element {
        std::string text;
        Vec2d at{};
        double point_size = 0.0;
        std::string fill;
    };
    void grow(Vec2d p, double r = 0.0);
    double width_px_;
    std::vector<Element> elements_;
    Counts counts_{};
    double min_x_ = 0.0, min_y_ = 0.0, max_x_ = 0.0, max_y_ = 0.0;
    bool empty_ = true;
};

} // namespace tamias2d::cli
