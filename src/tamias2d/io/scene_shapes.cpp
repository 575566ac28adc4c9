// The readers of a scene's materials, loads and shapes (docs/scene-format.md): each value
// checked where it is read, a shape by the library's own check (validate(ShapeDef)), and a
// violation reported at the key it concerns.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "box_polygon.hpp"
#include "scene_read.hpp"
#include "tamias2d/io/chain_runs.hpp"
#include "tamias2d/validation.hpp"

namespace tamias2d::io::scene_detail {

// ---------------------------------------------------------------------------------------------
// Materials
// ---------------------------------------------------------------------------------------------

Material parse_material_object(const Ctx& ctx, const ojson& v, const std::string& ptr, Material m) {
    require_object(ctx, v, ptr, "material", "a material object or a material name");
    check_keys(ctx, v, ptr,
               {"density", "restitution", "friction", "user_material_id", "rolling_resistance",
                "tangent_speed"},
               "a material");
    opt_number(ctx, v, ptr, "density", m.density);
    opt_number(ctx, v, ptr, "restitution", m.restitution);
    opt_number(ctx, v, ptr, "friction", m.friction);
    opt_number(ctx, v, ptr, "rolling_resistance", m.rolling_resistance); // DD46
    opt_number(ctx, v, ptr, "tangent_speed", m.tangent_speed);           // DD47
    if (const auto id = v.find("user_material_id"); id != v.end()) {     // DD42
        // (JSON reads a non-negative integer as unsigned: anything else is no id.)
        if (!id->is_number_unsigned())
            fail(ctx, child(ptr, "user_material_id"), "user_material_id",
                 "must be an integer in [0, 2^64 - 1]", format_rule);
        m.user_material_id = id->get<std::uint64_t>();
    }
    if (!(m.density > 0.0))
        fail_value(ctx, child(ptr, "density"), "density", m.density, "must be > 0", "DCX_density");
    if (!(m.restitution >= 0.0 && m.restitution <= 1.0))
        fail_value(ctx, child(ptr, "restitution"), "restitution", m.restitution,
                   "must be in [0, 1]", "DCI_CR");
    if (!(m.friction >= 0.0))
        fail_value(ctx, child(ptr, "friction"), "friction", m.friction, "must be >= 0",
                   "DCX_friction");
    if (!(m.rolling_resistance >= 0.0))
        fail_value(ctx, child(ptr, "rolling_resistance"), "rolling_resistance",
                   m.rolling_resistance, "must be >= 0", "DD46");
    check_as_library(ctx, ptr, "material.", [&] { validate(m); }); // DCX_range
    return m;
}

Material parse_material_ref(const Ctx& ctx, const ojson& v, const std::string& ptr,
                            const Material& base) {
    if (v.is_string()) {
        const std::string name = v.get<std::string>();
        const auto it = ctx.materials.find(name);
        if (it == ctx.materials.end()) {
            std::string known;
            std::size_t listed = 0;
            for (const auto& [n, m] : ctx.materials) {
                if (++listed > 10) {
                    known += ", ... (" + std::to_string(ctx.materials.size()) + " in all)";
                    break;
                }
                known += (known.empty() ? "" : ", ") + quote(n);
            }
            fail(ctx, ptr, "material",
                 "unknown material " + quote(name) +
                     (known.empty() ? std::string("; no materials are declared")
                                    : "; declared: " + known),
                 format_rule);
        }
        return it->second;
    }
    if (!v.is_object())
        fail_type(ctx, ptr, "material", v, "a material name or a material object");
    return parse_material_object(ctx, v, ptr, base);
}

Material generator_default_material(const Ctx& ctx) {
    return ctx.default_material.value_or(Material{1.0, 0.0, 0.6});
}

// ---------------------------------------------------------------------------------------------
// Loads
// ---------------------------------------------------------------------------------------------

namespace {

TimeFunction parse_time_function(const Ctx& ctx, const ojson& v, const std::string& ptr,
                                 const std::string& field) {
    TimeFunction f;
    const char* unit = field == "torque" ? "N m" : "N";
    if (v.is_number()) { // shorthand for {"kind": "constant", "value": v}
        f.value = as_number(ctx, v, ptr, field);
        check_as_library(ctx, ptr, field, [&] { // DCX_range, as World::step checks loads
            require_within(field, f.value, supported::input_max, unit);
        });
        return f;
    }
    require_object(ctx, v, ptr, field, "a number or a load object {\"kind\": ...}");
    const std::string kind =
        as_string(ctx, require_key(ctx, v, ptr, "kind", "a load"), child(ptr, "kind"), "kind");
    const std::string what = kind + " load";
    if (kind == "constant") {
        check_keys(ctx, v, ptr, {"kind", "value"}, "a constant load");
        f.kind = TimeFunction::Kind::constant;
        f.value = req_number(ctx, v, ptr, "value", what);
    } else if (kind == "sinusoid") {
        check_keys(ctx, v, ptr, {"kind", "amplitude", "omega", "phase", "offset"},
                   "a sinusoid load");
        f.kind = TimeFunction::Kind::sinusoid;
        f.amplitude = req_number(ctx, v, ptr, "amplitude", what);
        f.omega = req_number(ctx, v, ptr, "omega", what);
        opt_number(ctx, v, ptr, "phase", f.phase);
        opt_number(ctx, v, ptr, "offset", f.offset);
    } else if (kind == "step") {
        check_keys(ctx, v, ptr, {"kind", "time", "before", "after"}, "a step load");
        f.kind = TimeFunction::Kind::step;
        f.time = req_number(ctx, v, ptr, "time", what);
        opt_number(ctx, v, ptr, "before", f.before);
        f.after = req_number(ctx, v, ptr, "after", what);
    } else if (kind == "ramp") {
        check_keys(ctx, v, ptr, {"kind", "t0", "t1", "from", "to"}, "a ramp load");
        f.kind = TimeFunction::Kind::ramp;
        opt_number(ctx, v, ptr, "t0", f.t0);
        f.t1 = req_number(ctx, v, ptr, "t1", what);
        opt_number(ctx, v, ptr, "from", f.from);
        f.to = req_number(ctx, v, ptr, "to", what);
        if (!(f.t1 > f.t0))
            fail_value(ctx, child(ptr, "t1"), "t1", f.t1, "must be > t0", format_rule);
    } else {
        fail(ctx, child(ptr, "kind"), "kind",
             "unknown load kind " + quote(kind) + "; allowed: constant, sinusoid, step, ramp",
             format_rule);
    }
    // DCX_range: every value the load takes is a force (torque) within the supported range,
    // which World::step checks again on each evaluation.
    // (A pair, not a structured binding: clang before 16 lets no lambda capture one.)
    for (const auto& item : {std::pair<const char*, double>{"value", f.value},
                             {"amplitude", f.amplitude},
                             {"offset", f.offset},
                             {"before", f.before},
                             {"after", f.after},
                             {"from", f.from},
                             {"to", f.to}})
        check_as_library(ctx, ptr, "", [&] {
            require_within(item.first, item.second, supported::input_max, unit);
        });
    if (f.kind == TimeFunction::Kind::sinusoid)
        check_as_library(ctx, ptr, "", [&] {
            require_within("amplitude", std::abs(f.offset) + std::abs(f.amplitude),
                           supported::input_max, std::string(unit) + " (|offset| + |amplitude|)");
        });
    return f;
}

} // namespace

SceneLoads parse_loads(const Ctx& ctx, const ojson& v, const std::string& ptr) {
    require_object(ctx, v, ptr, "loads", "an object {\"force_x\", \"force_y\", \"torque\"}");
    check_keys(ctx, v, ptr, {"force_x", "force_y", "torque"}, "loads");
    SceneLoads loads;
    if (const ojson* f = find(v, "force_x"))
        loads.force_x = parse_time_function(ctx, *f, child(ptr, "force_x"), "force_x");
    if (const ojson* f = find(v, "force_y"))
        loads.force_y = parse_time_function(ctx, *f, child(ptr, "force_y"), "force_y");
    if (const ojson* f = find(v, "torque"))
        loads.torque = parse_time_function(ctx, *f, child(ptr, "torque"), "torque");
    return loads;
}

// ---------------------------------------------------------------------------------------------
// Shapes and bodies
// ---------------------------------------------------------------------------------------------

namespace {

Material shape_default_material(const Ctx& ctx) {
    return ctx.default_material.value_or(Material{});
}

/// The scene key a library field of a capsule, segment or chain segment names
/// ("capsule.center1.x" -> "center1.x"), "" for other fields. A length of zero means the two
/// ends coincide: it is reported at the second end (a ghost's, at the ghost).
std::string segment_key(const std::string& field) {
    for (const std::string_view kind : {"capsule.", "segment.", "chain_segment."}) {
        if (!field.starts_with(kind))
            continue;
        std::string key = field.substr(kind.size());
        if (key == "length")
            return kind == "capsule." ? "center2" : "point2";
        if (key.ends_with(".length"))
            key.resize(key.size() - 7);
        return key;
    }
    return {};
}

/// The library's check of a shape read at `ptr` (DCX_shape, DCX_range): a polygon's defects,
/// a box's included, are reported at `polygon_ptr`, the others at their key.
ShapeDef checked(const Ctx& ctx, const std::string& ptr, const std::string& polygon_ptr,
                 ShapeDef shape) {
    try {
        validate(shape);
    } catch (const ValidationError& e) {
        if (e.field.starts_with("polygon."))
            fail(ctx, polygon_ptr, e.field, e.what(), e.constraint);
        std::string key = e.field;
        if (key.starts_with("shape."))
            key.erase(0, 6);
        else if (std::string k = segment_key(key); !k.empty())
            key = std::move(k);
        fail(ctx, field_pointer(ptr, key), e.field, e.what(), e.constraint);
    }
    return shape;
}

/// Points [x, y] at `pp` (a polygon's or a chain's), each coordinate within the supported range
/// (DCX_range) before any product of them is formed.
std::vector<Vec2d> read_points(const Ctx& ctx, const ojson& pts, const std::string& pp) {
    std::vector<Vec2d> points;
    points.reserve(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const std::string at = child(pp, i);
        points.push_back(as_vec2(ctx, pts[i], at, "points"));
        for (const std::size_t k : {std::size_t{0}, std::size_t{1}}) {
            try {
                require_within(k == 0 ? "points.x" : "points.y",
                               k == 0 ? points.back().x : points.back().y, supported::input_max,
                               "m");
            } catch (const ValidationError& e) {
                fail(ctx, child(at, k), e.field, e.what(), e.constraint);
            }
        }
    }
    return points;
}

/// The point of a chain (at `pp`, n points) that a library error about its segment k names:
/// the segment runs from point k to point k + 1, its ghosts are the points before and after
/// it, or at an open end, made from the end point.
std::string chain_point(const std::string& pp, std::size_t k, std::size_t n, bool loop,
                        const std::string& field) {
    const std::string key = segment_key(field);
    const std::size_t edges = loop ? n : n - 1;
    std::size_t at = k;
    if (key.starts_with("point2") || key.starts_with("length"))
        at = (k + 1) % n;
    else if (key.starts_with("ghost1"))
        at = loop || k > 0 ? (k + n - 1) % n : k;
    else if (key.starts_with("ghost2"))
        at = loop || k + 1 < edges ? (k + 2) % n : k + 1;
    return child(pp, at);
}

/// A "chain": its one-sided segments (chain_shapes), the library's errors reported at the
/// point they concern. `budget` is what remains of the scene's max_chain_points.
std::vector<ShapeDef> parse_chain(const Ctx& ctx, const ojson& v, const std::string& ptr,
                                  const Material& material, std::size_t& budget) {
    const ojson& pts = require_key(ctx, v, ptr, "points", "a chain shape");
    const std::string pp = child(ptr, "points");
    if (!pts.is_array())
        fail_type(ctx, pp, "points", pts, "an array of [x, y] points");
    if (pts.size() > budget) // before reading them: the limit bounds the memory a load takes
        fail_value(ctx, pp, "points.size", double(pts.size()),
                   "the scene's chains may have at most " + std::to_string(max_chain_points) +
                       " points in all (docs/scene-format.md, Limits)",
                   format_rule);
    budget -= pts.size();
    const std::vector<Vec2d> points = read_points(ctx, pts, pp);
    bool loop = false;
    if (const ojson* l = find(v, "loop"))
        loop = as_bool(ctx, *l, child(ptr, "loop"), "loop");
    std::vector<ShapeDef> segments;
    try {
        segments = chain_shapes(points, loop, material);
    } catch (const ValidationError& e) {
        // "chain.points.size", or "chain.points[i]..." for point i (which repeats point i - 1).
        std::string at = pp;
        if (const auto open = e.field.find('['); open != std::string::npos)
            at = child(pp, std::stoul(e.field.substr(open + 1)));
        fail(ctx, at, e.field, e.what(), e.constraint);
    }
    for (std::size_t k = 0; k < segments.size(); ++k) {
        try {
            validate(segments[k]);
        } catch (const ValidationError& e) {
            fail(ctx, chain_point(pp, k, points.size(), loop, e.field), e.field, e.what(),
                 e.constraint);
        }
    }
    return segments;
}

/// DCX_shape: a polygon's points, read in order as a closed outline, must not cross: a crossing
/// outline (a bow tie) is a mistake in their order, which taking the convex hull would hide. A
/// simple outline, concave or not, stands for its convex hull (docs/scene-format.md).
void check_outline(const Ctx& ctx, const std::string& ptr, const std::vector<Vec2d>& p) {
    const auto side = [](Vec2d a, Vec2d b, Vec2d c) {
        const double t = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        return (t > 0.0) - (t < 0.0);
    };
    const std::size_t n = p.size();
    for (std::size_t i = 0; i + 2 < n; ++i) {
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1)
                continue; // the closing edge meets edge 0 at point 0
            const Vec2d a = p[i], b = p[i + 1], c = p[j], d = p[(j + 1) % n];
            if (side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0)
                fail(ctx, ptr, "points",
                     "points: the outline crosses itself (edge " + std::to_string(i) + "-" +
                         std::to_string(i + 1) + " crosses edge " + std::to_string(j) + "-" +
                         std::to_string((j + 1) % n) +
                         "); list the points in order around the polygon (DCX_shape)",
                     "DCX_shape");
        }
    }
}

/// A shape's "filter" (DD27), "sensor" (DD28) and "enable_pre_solve", the keys every kind of
/// shape has.
void parse_filter_and_sensor(const Ctx& ctx, const ojson& v, const std::string& ptr,
                             ShapeDef& def) {
    if (const ojson* f = find(v, "filter")) {
        const std::string fp = child(ptr, "filter");
        require_object(ctx, *f, fp, "filter", "a filter object");
        check_keys(ctx, *f, fp, {"category_bits", "mask_bits", "group_index"}, "a filter");
        const auto bits = [&](std::string_view key, std::uint32_t& out, long long lo,
                              long long hi) {
            if (const ojson* b = find(*f, key))
                out = std::uint32_t(as_integer(ctx, *b, child(fp, key), std::string(key), lo, hi));
        };
        bits("category_bits", def.filter.category_bits, 0, 0xFFFFFFFFll);
        bits("mask_bits", def.filter.mask_bits, 0, 0xFFFFFFFFll);
        if (const ojson* gi = find(*f, "group_index"))
            def.filter.group_index = std::int32_t(as_integer(
                ctx, *gi, child(fp, "group_index"), "group_index", -2147483648ll, 2147483647ll));
    }
    if (const ojson* s = find(v, "sensor"))
        def.is_sensor = as_bool(ctx, *s, child(ptr, "sensor"), "sensor");
    if (const ojson* s = find(v, "enable_pre_solve"))
        def.enable_pre_solve = as_bool(ctx, *s, child(ptr, "enable_pre_solve"), "enable_pre_solve");
}

std::vector<ShapeDef> parse_shape_geometry(const Ctx& ctx, const ojson& v, const std::string& ptr,
                                           std::size_t& chain_budget) {
    require_object(ctx, v, ptr, "shape", "a shape object {\"type\": ...}");
    const std::string type =
        as_string(ctx, require_key(ctx, v, ptr, "type", "a shape"), child(ptr, "type"), "type");
    Material material = shape_default_material(ctx);
    const auto read_material = [&] {
        if (const ojson* m = find(v, "material"))
            material = parse_material_ref(ctx, *m, child(ptr, "material"), material);
    };
    const auto req_vec2 = [&](std::string_view key, const std::string& what) {
        return as_vec2(ctx, require_key(ctx, v, ptr, key, what), child(ptr, key), std::string(key));
    };
    try {
        if (type == "box") {
            check_keys(ctx, v, ptr,
                       {"type", "width", "height", "center", "angle", "material", "filter",
                        "sensor", "enable_pre_solve"},
                       "a box shape");
            const double w = req_length(ctx, v, ptr, "width", "a box shape");
            const double h = req_length(ctx, v, ptr, "height", "a box shape");
            Vec2d center{};
            double angle = 0.0;
            opt_vec2(ctx, v, ptr, "center", center);
            opt_number(ctx, v, ptr, "angle", angle);
            read_material();
            // Checked as a box (its sizes named as the file names them), held as its polygon.
            return {box_polygon(checked(ctx, ptr, ptr, box_shape(w, h, material, center, angle)))};
        }
        if (type == "circle") {
            check_keys(
                ctx, v, ptr,
                {"type", "radius", "center", "material", "filter", "sensor", "enable_pre_solve"},
                "a circle shape");
            const double r = req_length(ctx, v, ptr, "radius", "a circle shape");
            Vec2d center{};
            opt_vec2(ctx, v, ptr, "center", center);
            read_material();
            return {checked(ctx, ptr, ptr, circle_shape(r, material, center))};
        }
        if (type == "polygon") {
            check_keys(ctx, v, ptr,
                       {"type", "points", "material", "filter", "sensor", "enable_pre_solve"},
                       "a polygon shape");
            const ojson& pts = require_key(ctx, v, ptr, "points", "a polygon shape");
            const std::string pp = child(ptr, "points");
            if (!pts.is_array())
                fail_type(ctx, pp, "points", pts, "an array of [x, y] points");
            if (pts.size() < 3 || pts.size() > 64)
                fail_value(ctx, pp, "points.size", double(pts.size()),
                           "must be >= 3 (and at most 64 points, whose hull has <= 8)",
                           "DCX_shape");
            const std::vector<Vec2d> points = read_points(ctx, pts, pp);
            check_outline(ctx, pp, points);
            read_material();
            try {
                return {checked(ctx, ptr, pp, polygon_shape(points, material))};
            } catch (const ValidationError& e) {
                fail_from(ctx, pp, e, false);
            }
        }
        if (type == "capsule") {
            check_keys(ctx, v, ptr,
                       {"type", "center1", "center2", "radius", "material", "filter", "sensor",
                        "enable_pre_solve"},
                       "a capsule shape");
            const Vec2d c1 = req_vec2("center1", "a capsule shape");
            const Vec2d c2 = req_vec2("center2", "a capsule shape");
            const double r = req_length(ctx, v, ptr, "radius", "a capsule shape");
            read_material();
            // Built unchecked so that `checked` reports a defect at its key (capsule_shape
            // would throw first, naming no key of the file).
            ShapeDef def{};
            def.geometry.type = ShapeType::capsule;
            def.geometry.capsule = {c1, c2, r};
            def.material = material;
            return {checked(ctx, ptr, ptr, def)};
        }
        if (type == "segment") {
            check_keys(
                ctx, v, ptr,
                {"type", "point1", "point2", "material", "filter", "sensor", "enable_pre_solve"},
                "a segment shape");
            ShapeDef def{};
            def.geometry.type = ShapeType::segment;
            def.geometry.segment = {req_vec2("point1", "a segment shape"),
                                    req_vec2("point2", "a segment shape")};
            read_material();
            def.material = material;
            return {checked(ctx, ptr, ptr, def)};
        }
        if (type == "chain") {
            check_keys(
                ctx, v, ptr,
                {"type", "points", "loop", "material", "filter", "sensor", "enable_pre_solve"},
                "a chain shape");
            read_material();
            return parse_chain(ctx, v, ptr, material, chain_budget);
        }
        if (type == "chain_segment") {
            check_keys(ctx, v, ptr,
                       {"type", "ghost1", "point1", "point2", "ghost2", "material", "filter",
                        "sensor", "enable_pre_solve"},
                       "a chain_segment shape");
            ShapeDef def{};
            def.geometry.type = ShapeType::chain_segment;
            def.geometry.chain_segment = {req_vec2("ghost1", "a chain_segment shape"),
                                          req_vec2("point1", "a chain_segment shape"),
                                          req_vec2("point2", "a chain_segment shape"),
                                          req_vec2("ghost2", "a chain_segment shape")};
            read_material();
            def.material = material;
            return {checked(ctx, ptr, ptr, def)};
        }
    } catch (const ValidationError& e) {
        // The library's own shape checks (after ours): reported at the shape.
        fail_from(ctx, ptr, e, false);
    }
    fail(ctx, child(ptr, "type"), "type",
         "unknown shape type " + quote(type) +
             "; allowed: box, circle, polygon, capsule, segment, chain, chain_segment",
         format_rule);
}

} // namespace

std::vector<ShapeDef> parse_shape(Ctx& ctx, const ojson& v, const std::string& ptr) {
    std::vector<ShapeDef> defs = parse_shape_geometry(ctx, v, ptr, ctx.chain_budget);
    ShapeDef common;
    parse_filter_and_sensor(ctx, v, ptr, common);
    for (ShapeDef& def : defs) {
        def.filter = common.filter;
        def.is_sensor = common.is_sensor;
        def.enable_pre_solve = common.enable_pre_solve;
    }
    return defs;
}

} // namespace tamias2d::io::scene_detail
