#include "svg_draw.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace tamias2d::cli {

namespace {

/// Shortest round-trip-free text of a coordinate: 6 significant digits are finer than a
/// pixel at any zoom a picture of a scene needs.
std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string rgb(Color c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%06x", unsigned(c.rgb & 0xffffffu));
    return buf;
}

std::string points_attr(std::span<const Vec2d> v) {
    std::string s;
    for (const Vec2d& p : v) {
        if (!s.empty())
            s += ' ';
        s += num(p.x) + ',' + num(p.y);
    }
    return s;
}

} // namespace

void SvgDraw::grow(Vec2d p, double r) {
    if (empty_) {
        min_x_ = max_x_ = p.x;
        min_y_ = max_y_ = p.y;
        empty_ = false;
    }
    min_x_ = std::min(min_x_, p.x - r);
    min_y_ = std::min(min_y_, p.y - r);
    max_x_ = std::max(max_x_, p.x + r);
    max_y_ = std::max(max_y_, p.y + r);
}

void SvgDraw::polygon(std::span<const Vec2d> vertices, Color color) {
    for (const Vec2d& p : vertices)
        grow(p);
    elements_.push_back({"<polygon points=\"" + points_attr(vertices) +
                             "\" fill=\"none\" stroke=\"" + rgb(color) + "\"/>",
                         {},
                         0.0,
                         {}});
    ++counts_.polygons;
}

void SvgDraw::solid_polygon(std::span<const Vec2d> vertices, Color color) {
    for (const Vec2d& p : vertices)
        grow(p);
    elements_.push_back({"<polygon points=\"" + points_attr(vertices) + "\" fill=\"" + rgb(color) +
                             "\" fill-opacity=\"0.5\" stroke=\"" + rgb(color) + "\"/>",
                         {},
                         0.0,
                         {}});
    ++counts_.solid_polygons;
}

void SvgDraw::solid_circle(Vec2d center, double radius, double angle, Color color) {
    grow(center, radius);
    const Vec2d rim{center.x + radius * std::cos(angle), center.y + radius * std::sin(angle)};
    elements_.push_back({"<circle cx=\"" + num(center.x) + "\" cy=\"" + num(center.y) + "\" r=\"" +
                             num(radius) + "\" fill=\"" + rgb(color) +
                             "\" fill-opacity=\"0.5\" stroke=\"" + rgb(color) + "\"/><line x1=\"" +
                             num(center.x) + "\" y1=\"" + num(center.y) + "\" x2=\"" + num(rim.x) +
                             "\" y2=\"" + num(rim.y) + "\" stroke=\"" + rgb(color) + "\"/>",
                         {},
                         0.0,
                         {}});
    ++counts_.circles;
}

void SvgDraw::solid_capsule(Vec2d p1, Vec2d p2, double radius, Color color) {
    grow(p1, radius);
    grow(p2, radius);
    // A line with round caps as wide as the capsule is the capsule; its outline on top.
    elements_.push_back({"<line x1=\"" + num(p1.x) + "\" y1=\"" + num(p1.y) + "\" x2=\"" +
                             num(p2.x) + "\" y2=\"" + num(p2.y) + "\" stroke=\"" + rgb(color) +
                             "\" stroke-opacity=\"0.5\" stroke-linecap=\"round\" "
                             "style=\"stroke-width:" +
                             num(2.0 * radius) + "\"/>",
                         {},
                         0.0,
                         {}});
    ++counts_.capsules;
}

void SvgDraw::segment(Vec2d p1, Vec2d p2, Color color) {
    grow(p1);
    grow(p2);
    elements_.push_back({"<line x1=\"" + num(p1.x) + "\" y1=\"" + num(p1.y) + "\" x2=\"" +
                             num(p2.x) + "\" y2=\"" + num(p2.y) + "\" stroke=\"" + rgb(color) +
                             "\"/>",
                         {},
                         0.0,
                         {}});
    ++counts_.segments;
}

void SvgDraw::transform(Vec2d origin, double angle, double length) {
    grow(origin, length);
    const double c = std::cos(angle), s = std::sin(angle);
    const Vec2d ex{origin.x + length * c, origin.y + length * s};
    const Vec2d ey{origin.x - length * s, origin.y + length * c};
    elements_.push_back({"<line x1=\"" + num(origin.x) + "\" y1=\"" + num(origin.y) + "\" x2=\"" +
                             num(ex.x) + "\" y2=\"" + num(ex.y) +
                             "\" stroke=\"#ff0000\"/><line x1=\"" + num(origin.x) + "\" y1=\"" +
                             num(origin.y) + "\" x2=\"" + num(ey.x) + "\" y2=\"" + num(ey.y) +
                             "\" stroke=\"#00ff00\"/>",
                         {},
                         0.0,
                         {}});
    ++counts_.transforms;
}

void SvgDraw::point(Vec2d p, double size, Color color) {
    grow(p);
    elements_.push_back({{}, p, size, rgb(color)});
    ++counts_.points;
}

void SvgDraw::write(std::ostream& out, const std::string& title) const {
    double x0 = -0.5, y0 = -0.5, x1 = 0.5, y1 = 0.5;
    if (!empty_) {
        x0 = min_x_;
        y0 = min_y_;
        x1 = max_x_;
        y1 = max_y_;
    }
    const double span = std::max({x1 - x0, y1 - y0, 1e-9});
    const double margin = 0.05 * span;
    x0 -= margin;
    y0 -= margin;
    x1 += margin;
    y1 += margin;
    const double w = x1 - x0, h = y1 - y0;
    const double px_per_m = width_px_ / w;
    std::string esc;
    for (const char ch : title) {
        if (ch == '<')
            esc += "&lt;";
        else if (ch == '&')
            esc += "&amp;";
        else if (ch == '>')
            esc += "&gt;";
        else
            esc += ch;
    }
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width_px_) << "\" height=\""
        << num(h * px_per_m) << "\" viewBox=\"" << num(x0) << ' ' << num(-y1) << ' ' << num(w)
        << ' ' << num(h) << "\">\n<title>" << esc << "</title>\n"
        << "<rect x=\"" << num(x0) << "\" y=\"" << num(-y1) << "\" width=\"" << num(w)
        << "\" height=\"" << num(h)
        << "\" fill=\"#202020\"/>\n"
        // Lines one pixel wide, in world units (the scale is the same along both axes).
        << "<style>line,polygon,circle{stroke-width:" << num(1.0 / px_per_m) << "}</style>\n"
        << "<g transform=\"scale(1,-1)\">\n";
    for (const Element& e : elements_) {
        if (e.point_size > 0.0) {
            out << "<circle cx=\"" << num(e.at.x) << "\" cy=\"" << num(e.at.y) << "\" r=\""
                << num(0.5 * e.point_size / px_per_m) << "\" fill=\"" << e.fill << "\"/>\n";
        } else {
            out << e.text << '\n';
        }
    }
    out << "</g>\n</svg>\n";
}

} // namespace tamias2d::cli
