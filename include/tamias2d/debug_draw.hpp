/// \file
/// Seeing a live world: World::draw hands its shapes, joints, contacts, boxes and centres of
/// mass to a DebugDraw as primitives (polygons, circles, capsules, segments, points, frames),
/// which a game turns into lines and fills of its own renderer.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "tamias2d/aabb.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// An sRGB colour, 8 bits a channel: 0xRRGGBB.
struct Color {
    std::uint32_t rgb = 0; ///< red in bits 16-23, green in 8-15, blue in 0-7
    constexpr std::uint8_t red() const { return std::uint8_t(rgb >> 16); }  ///< 0-255
    constexpr std::uint8_t green() const { return std::uint8_t(rgb >> 8); } ///< 0-255
    constexpr std::uint8_t blue() const { return std::uint8_t(rgb); }       ///< 0-255
    /// Channel by channel.
    friend constexpr bool operator==(Color, Color) = default;
};

/// The colours World::draw gives each thing, by its state. A shape takes the first that
/// applies: sensor, then its body's bullet, static, kinematic, sleeping or awake colour.
struct DrawColors {
    Color static_body{0x7fe57f};    ///< a shape of a static body
    Color kinematic{0x7f7fe5};      ///< a shape of a kinematic body
    Color awake{0xe5b2b2};          ///< a shape of an awake dynamic body
    Color sleeping{0x999999};       ///< a shape of a sleeping dynamic body
    Color sensor{0xe5e54c};         ///< a sensor shape (DD28), whatever its body
    Color bullet{0xe5994c};         ///< a shape of a bullet (BodyDef::bullet)
    Color joint{0x80cccc};          ///< a joint's segments
    Color contact_point{0xff3333};  ///< a contact point (ContactInfo::points)
    Color contact_normal{0xe5e5e5}; ///< a contact's normal, drawn from its point
    Color aabb{0xe54ce5};           ///< a shape's broad-phase box
    Color mass_center{0xffffff};    ///< a body's centre of mass (the frame's origin)
};

/// What World::draw draws, and where its primitives go. Override the calls a renderer needs;
/// the others do nothing. Every position is in metres, in the world frame (y up, SRS A3), so
/// a renderer applies its own camera. World::draw calls them in a fixed order (shapes,
/// boxes, joints, contacts, centres of mass; each in index order), from the calling thread.
struct DebugDraw {
    virtual ~DebugDraw() = default;

    // --- what to draw ---
    bool draw_shapes = true;           ///< every shape, filled, in its state's colour
    bool draw_joints = true;           ///< each joint as segments between its bodies' anchors
    bool draw_contacts = false;        ///< each touching contact's points (World::contacts)
    bool draw_contact_normals = false; ///< each contact point's normal, contact_normal_length long
    bool draw_aabbs = false;           ///< each shape's broad-phase (fattened) box
    bool draw_mass_centers = false;    ///< each body's centre of mass and rotation
    /// m: the length of a drawn contact normal (> 0, finite).
    double contact_normal_length = 0.25;
    /// m: the length of a mass-centre frame's axes, passed to transform() (> 0, finite).
    double axis_length = 0.2;
    /// Only what lies in this box (m, world frame) is drawn: shapes and their boxes whose
    /// broad-phase boxes overlap it (found through the broad phase), joints with an anchor in
    /// it, contact points and centres of mass in it. Empty: everything.
    std::optional<Aabb> bounds;
    DrawColors colors{}; ///< the colour of each thing drawn, by its state

    // --- the primitives ---
    /// A closed polygon outline (a shape's box: 4 vertices, counter-clockwise).
    virtual void polygon(std::span<const Vec2d> vertices, Color color) {
        (void)vertices;
        (void)color;
    }
    /// A filled convex polygon, vertices counter-clockwise (a polygon shape).
    virtual void solid_polygon(std::span<const Vec2d> vertices, Color color) {
        (void)vertices;
        (void)color;
    }
    /// A filled circle; `angle` (rad) is its body's orientation, for a spoke that shows spin.
    virtual void solid_circle(Vec2d center, double radius, double angle, Color color) {
        (void)center;
        (void)radius;
        (void)angle;
        (void)color;
    }
    /// A filled capsule: the points within `radius` of the segment p1 -> p2.
    virtual void solid_capsule(Vec2d p1, Vec2d p2, double radius, Color color) {
        (void)p1;
        (void)p2;
        (void)radius;
        (void)color;
    }
    /// A line segment (a segment or chain shape, a joint's line, a contact normal).
    virtual void segment(Vec2d p1, Vec2d p2, Color color) {
        (void)p1;
        (void)p2;
        (void)color;
    }
    /// A frame at `origin` turned by `angle` (rad): its x and y axes, `length` (m) long.
    virtual void transform(Vec2d origin, double angle, double length) {
        (void)origin;
        (void)angle;
        (void)length;
    }
    /// A dot of `size` pixels (a contact point): its size is the renderer's, not the world's.
    virtual void point(Vec2d p, double size, Color color) {
        (void)p;
        (void)size;
        (void)color;
    }
    /// A label at `p` (World::draw makes none; a game's own overlays may).
    virtual void text(Vec2d p, std::string_view s, Color color) {
        (void)p;
        (void)s;
        (void)color;
    }
};

} // namespace tamias2d
