/// \file
/// Scene files: a whole simulation (world settings, run length, bodies, shapes, materials, loads
/// and generated stacks) as one JSON document. The format is specified in docs/scene-format.md.
///
/// Loading is all or nothing (SRS R4): the document is parsed, type-checked and validated in
/// full, including a dry run of every body and shape through a scratch World, before any Scene is
/// returned. An error is a SceneError naming the place (JSON pointer, or line and column for a
/// syntax error), the field, the value and the data constraint it breaks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "tamias2d/body_def.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/io/export.hpp"
#include "tamias2d/joint_def.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/world_def.hpp"

namespace tamias2d {

class World;

namespace io {

/// A scalar function of time f(t) (t in s) for one load component (IM1's F_i(t), IM2's
/// tau_i(t)). Only the fields of its kind are used; the others keep their defaults.
struct TAMIAS2D_IO_EXPORT TimeFunction {
    /// The form of f(t).
    enum class Kind : std::uint8_t { constant, sinusoid, step, ramp };
    Kind kind = Kind::constant; ///< which of the forms below applies
    double value = 0.0;         ///< constant: f(t) = value
    double amplitude = 0.0;     ///< sinusoid: f(t) = offset + amplitude sin(omega t + phase)
    double omega = 0.0;         ///< rad s^-1
    double phase = 0.0;         ///< rad
    double offset = 0.0;        ///< (sinusoid)
    double time = 0.0;          ///< step: f(t) = before for t < time, after for t >= time
    double before = 0.0;        ///< (step)
    double after = 0.0;         ///< (step)
    double t0 = 0.0;            ///< ramp: from at t <= t0, to at t >= t1, linear in between
    double t1 = 1.0;            ///< (ramp), t1 > t0
    double from = 0.0;          ///< (ramp)
    double to = 0.0;            ///< (ramp)

    double operator()(double t) const; ///< f(t), t in s
    /// Same kind and same parameters.
    friend bool operator==(const TimeFunction&, const TimeFunction&) = default;
};

/// Time-varying loads of one body, each component optional; they add to BodyDef::force and
/// BodyDef::torque.
struct TAMIAS2D_IO_EXPORT SceneLoads {
    std::optional<TimeFunction> force_x;                           ///< N
    std::optional<TimeFunction> force_y;                           ///< N
    std::optional<TimeFunction> torque;                            ///< N m
    bool empty() const { return !force_x && !force_y && !torque; } ///< no component set
    Load operator()(double t) const; ///< the load at t (s); absent components are 0
    /// Same components, each the same function.
    friend bool operator==(const SceneLoads&, const SceneLoads&) = default;
};

/// One body of a scene. `def.load` is set from `loads` when the scene is parsed; build_world
/// uses `loads` when it is not empty (replacing `def.load`), else `def.load` as it is.
struct SceneBody {
    BodyDef def;                  ///< the body as World::create_body takes it
    std::vector<ShapeDef> shapes; ///< its shapes, in file order (a chain as its segments)
    SceneLoads loads;             ///< its time-varying loads, if any
    /// Where the body came from: the JSON pointer of its entry ("/bodies/3"), or of the
    /// generator that made it. Used in error messages.
    std::string source;
    bool generated = false; ///< made by a generator (then `source` is the generator's pointer)
};

/// One joint of a scene, between two named bodies.
struct SceneJoint {
    /// The definition, of the kind the "type" key names ("revolute", "distance", "prismatic",
    /// "weld", "wheel", "motor", "filter"); its body handles are set by build_world from the
    /// names.
    using Definition = std::variant<RevoluteJointDef, DistanceJointDef, PrismaticJointDef,
                                    WeldJointDef, WheelJointDef, MotorJointDef, FilterJointDef>;
    Definition def;     ///< the joint's definition (bodies unset: build_world sets them)
    std::string body_a; ///< the name of its first body (BodyDef::name, unique)
    std::string body_b; ///< the name of its second body
    std::string source; ///< the JSON pointer of its entry ("/joints/0"), for error messages
};

/// A whole simulation as a scene file states it: the world, the run, the bodies.
struct Scene {
    std::string description; ///< free text
    WorldDef world;          ///< the world's settings
    double dt = 1.0 / 60.0;  ///< s, > 0 (DCX_dt)
    int steps = 0;           ///< number of steps a run takes, >= 0
    int output_every = 0;    ///< write states every K steps (0: only the final state)
    /// Named materials as declared (shapes hold their resolved Material).
    std::map<std::string, Material> materials;
    std::vector<SceneBody> bodies;  ///< generated bodies expanded in place, in file order
    std::vector<SceneJoint> joints; ///< in file order, created after every body
};

/// A scene that cannot be loaded. what() is one line:
///   "scene.json: /bodies/3/shapes/0/radius: radius = -1: must be > 0 (DCX_shape)"
///   "scene.json:4:17: syntax error: unexpected ','; expected '[', '{', or a literal"
struct TAMIAS2D_IO_EXPORT SceneError : std::runtime_error {
    std::string origin;     ///< file name or other origin given to the parser
    std::string pointer;    ///< JSON pointer (RFC 6901) of the offending value, "" for the root
    int line = 0;           ///< 1-based, syntax errors only (0 otherwise)
    int column = 0;         ///< 1-based, syntax errors only
    std::string field;      ///< the offending field, e.g. "radius" ("" when not a field)
    std::string constraint; ///< data-constraint label (e.g. "DCX_shape"), "" if none applies
    std::string detail;     ///< the message without origin and place

    /// Builds what() from the parts: "origin: pointer: detail", or "origin:line:column: detail".
    SceneError(std::string origin_, std::string pointer_, int line_, int column_,
               std::string field_, std::string constraint_, std::string detail_);
};

/// The largest scene text read or parsed by default: 64 MiB (docs/scene-format.md, "Limits").
/// It holds about 65 000 bodies written out as scene_to_json writes them (150 000 without
/// indentation); loading takes up to about 12 times the text in memory (document, scene and
/// the dry run's World), so the limit keeps a load below 1 GB. Larger scenes are better made by
/// generators; the functions below take a larger limit where one is meant.
inline constexpr std::size_t max_scene_bytes = std::size_t{64} << 20;

/// The most points the "chain" shapes of one scene may have in all (docs/scene-format.md,
/// "Limits"). A point is a few bytes of text but a shape in the Scene and in the dry run's World
/// (about 2 kB together): 100 000 points take about 200 MB to load (a chain attaches in time
/// linear in its points: World::create_chain).
inline constexpr std::size_t max_chain_points = 100000;

/// The most bodies a scene may hold in all, written out and generated (docs/scene-format.md,
/// "Limits"): the largest generator (rain of 200 000 boxes, 1.1 GB to validate) with room for
/// the rest. Six pyramids of base 500 in one scene (751 500 bodies, 1.9 GB) are refused at the
/// generator that passes the limit, before a World is built.
inline constexpr std::size_t max_scene_bodies = 250000;

/// Reads and parses a scene file (origin in messages: the path as given). The file is read in
/// chunks and refused as soon as it exceeds `max_bytes`, so that an endless source (/dev/zero,
/// a pipe) is refused promptly and with bounded memory.
TAMIAS2D_IO_EXPORT Scene load_scene(const std::filesystem::path& path,
                                    std::size_t max_bytes = max_scene_bytes);

/// Reads a scene from a stream (standard input, a pipe) as load_scene reads a file; `origin`
/// names it in error messages.
TAMIAS2D_IO_EXPORT Scene load_scene(std::istream& in, std::string_view origin,
                                    std::size_t max_bytes = max_scene_bytes);

/// Parses and validates a scene from JSON text; `origin` names it in error messages. A text
/// longer than `max_bytes` is refused.
TAMIAS2D_IO_EXPORT Scene parse_scene(std::string_view json, std::string_view origin = "<scene>",
                                     std::size_t max_bytes = max_scene_bytes);

/// Checks a Scene (parsed or hand-made) by building it into a scratch World: throws SceneError
/// at the body's `source` if the World rejects any body or shape.
TAMIAS2D_IO_EXPORT void validate_scene(const Scene& scene, std::string_view origin = "<scene>");

/// Creates the scene's bodies and shapes, then its joints, in `world` (whose settings the
/// caller made from scene.world) and returns the body handles in scene order. The scene is
/// validated first (validate_scene), so on error `world` is left unchanged.
TAMIAS2D_IO_EXPORT std::vector<BodyId> build_world(const Scene& scene, World& world);

/// The scene as canonical JSON: generators expanded, materials inlined, boxes written as
/// polygons, the segments of a chain as one "chain" (each segment that is not exactly the
/// segment of a chain through its neighbours, or beyond max_chain_points, as a "chain_segment"
/// with its ghosts). parse_scene(scene_to_json(s)) reproduces s (loads, materials and
/// geometry, bit for bit), so the written form simulates with the same state hashes: a scene's
/// polygons, its boxes included, are what polygon_shape derives from their points (a box read
/// or generated is held as the polygon of its corners), and a box is accepted exactly when its
/// polygon is, both by the one sliver rule (DCX_shape). A polygon made otherwise by hand (a
/// box_shape, whose centroid is its centre) reads back as what its points give. (A text beyond
/// max_scene_bytes needs a larger limit passed to parse_scene.)
TAMIAS2D_IO_EXPORT std::string scene_to_json(const Scene& scene, int indent = 2);

} // namespace io
} // namespace tamias2d
