#include "tamias2d/io/scene.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <istream>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "tamias2d/errors.hpp"
#include "tamias2d/io/chain_runs.hpp"
#include "tamias2d/io/scene_generators.hpp"
#include "tamias2d/math/sincos.hpp"
#include "tamias2d/validation.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d::io {

using ojson = nlohmann::ordered_json;

// ---------------------------------------------------------------------------------------------
// Time functions
// ---------------------------------------------------------------------------------------------

double TimeFunction::operator()(double t) const {
    switch (kind) {
    case Kind::constant:
        return value;
    case Kind::sinusoid:
        return offset + amplitude * math::sincos(omega * t + phase).sin; // the same bits everywhere
    case Kind::step:
        return t < time ? before : after;
    case Kind::ramp:
        if (t <= t0)
            return from;
        if (t >= t1)
            return to;
        return from + (to - from) * ((t - t0) / (t1 - t0));
    }
    return 0.0;
}

Load SceneLoads::operator()(double t) const {
    Load l;
    if (force_x)
        l.force.x = (*force_x)(t);
    if (force_y)
        l.force.y = (*force_y)(t);
    if (torque)
        l.torque = (*torque)(t);
    return l;
}

// ---------------------------------------------------------------------------------------------
// Errors
// ---------------------------------------------------------------------------------------------

namespace {

/// What a message quotes of a user's text: control characters escaped as JSON writes them (a
/// key or name with a newline stays on one line, and a terminal sees no escape sequence), and
/// at most `max` bytes of it, cut at a character boundary, the rest counted.
std::string printable(std::string_view s, std::size_t max) {
    std::string out;
    std::size_t kept = 0;
    for (; kept < s.size() && out.size() < max; ++kept) {
        const auto c = static_cast<unsigned char>(s[kept]);
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c < 0x20 || c == 0x7f) {
            static constexpr char hex[] = "0123456789abcdef";
            out += "\\u00";
            out += hex[c >> 4];
            out += hex[c & 15];
        } else {
            out += static_cast<char>(c);
        }
    }
    while (kept < s.size() && kept > 0 && (static_cast<unsigned char>(s[kept]) & 0xc0) == 0x80) {
        --kept; // not inside a UTF-8 sequence
        out.pop_back();
    }
    if (kept < s.size())
        out += "... (" + std::to_string(s.size()) + " bytes)";
    return out;
}

/// A JSON pointer as messages show it: each token printable and short, and a deep pointer
/// (nesting up to the parser's limit) shortened to its first and last levels.
std::string shown_pointer(std::string_view pointer) {
    constexpr std::size_t token_max = 32, keep = 6;
    std::vector<std::string> tokens;
    for (std::size_t start = 1; start <= pointer.size();) {
        std::size_t end = pointer.find('/', start);
        if (end == std::string_view::npos)
            end = pointer.size();
        tokens.push_back(printable(pointer.substr(start, end - start), token_max));
        start = end + 1;
    }
    std::string out;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        if (tokens.size() > 2 * keep && i == keep) {
            out += "/[... " + std::to_string(tokens.size() - 2 * keep) + " levels ...]";
            i = tokens.size() - keep - 1;
            continue;
        }
        out += "/" + tokens[i];
    }
    return out;
}

std::string where(const std::string& origin, const std::string& pointer, int line, int column) {
    const std::string file = printable(origin, 256);
    if (line > 0)
        return file + ":" + std::to_string(line) + ":" + std::to_string(column);
    return file + ": " + (pointer.empty() ? std::string("(root)") : shown_pointer(pointer));
}

} // namespace

SceneError::SceneError(std::string origin_, std::string pointer_, int line_, int column_,
                       std::string field_, std::string constraint_, std::string detail_)
    : std::runtime_error(where(origin_, pointer_, line_, column_) + ": " + detail_),
      origin(std::move(origin_)), pointer(std::move(pointer_)), line(line_), column(column_),
      field(std::move(field_)), constraint(std::move(constraint_)), detail(std::move(detail_)) {}

namespace {

// Rules of the scene format that are no SRS data constraint carry this in place of a label.
constexpr const char* format_rule = "scene format";

/// A user's string (key, name, kind) in a message: 'text', escaped and shortened.
std::string quote(std::string_view s) {
    return "'" + printable(s, 64) + "'";
}

/// RFC 6901 escaping of one reference token.
std::string escape_token(std::string_view key) {
    std::string out;
    for (const char c : key) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

std::string child(const std::string& ptr, std::string_view key) {
    return ptr + "/" + escape_token(key);
}
std::string child(const std::string& ptr, std::size_t index) {
    return ptr + "/" + std::to_string(index);
}

/// The parser's state: the origin for messages and the named materials.
struct Ctx {
    std::string origin;
    std::map<std::string, Material> materials;
    std::optional<Material> default_material;    // materials["default"]
    std::map<std::string, std::string> names;    // body name -> pointer of first use
    std::size_t chain_budget = max_chain_points; // chain points the scene may still have
};

[[noreturn]] void fail(const Ctx& ctx, const std::string& ptr, std::string field,
                       std::string message, std::string constraint = {}) {
    throw SceneError(ctx.origin, ptr, 0, 0, std::move(field),
                     constraint == format_rule ? std::string{} : std::move(constraint),
                     std::move(message));
}

/// "radius = -1: must be > 0 (DCX_shape)"
[[noreturn]] void fail_value(const Ctx& ctx, const std::string& ptr, const std::string& field,
                             double value, const std::string& rule, const std::string& constraint) {
    fail(ctx, ptr, field, detail::validation_message(field, value, rule, constraint), constraint);
}

/// The pointer of a library field name under `base`, whose keys it names ("container.width" ->
/// base/container/width, "center.x" -> base/center/0).
std::string field_pointer(std::string ptr, std::string f) {
    if (f.empty()) // the value at base itself
        return ptr;
    for (const std::string_view suffix : {".x", ".y"}) {
        if (f.size() > suffix.size() && f.ends_with(suffix)) {
            f.resize(f.size() - suffix.size());
            return child(ptr, f) + (suffix == ".x" ? "/0" : "/1");
        }
    }
    std::size_t start = 0;
    for (std::size_t dot; (dot = f.find('.', start)) != std::string::npos; start = dot + 1)
        ptr = child(ptr, std::string_view(f).substr(start, dot - start));
    return child(ptr, std::string_view(f).substr(start));
}

/// Maps a ValidationError from the library or a generator to the scene: `base` is the pointer
/// of the object whose keys the error's field names (see field_pointer).
[[noreturn]] void fail_from(const Ctx& ctx, const std::string& base, const ValidationError& e,
                            bool map_field) {
    fail(ctx, map_field ? field_pointer(base, e.field) : base, e.field, e.what(), e.constraint);
}

/// Runs the library's own check of what was read at `base` (validation.hpp: each criterion in
/// one place), reporting a violation at the key its field names, less `prefix` ("body.").
template <class Check>
void check_as_library(const Ctx& ctx, const std::string& base, std::string_view prefix,
                      Check&& check) {
    try {
        check();
    } catch (const ValidationError& e) {
        std::string key = e.field;
        if (key.starts_with(prefix))
            key.erase(0, prefix.size());
        if (key.starts_with("linear_velocity")) // BodyDef's name of the scene's "velocity"
            key.replace(0, 15, "velocity");
        fail(ctx, field_pointer(base, key), e.field, e.what(), e.constraint);
    }
}

const char* type_name(const ojson& v) {
    switch (v.type()) {
    case ojson::value_t::null:
        return "null";
    case ojson::value_t::boolean:
        return "a boolean";
    case ojson::value_t::string:
        return "a string";
    case ojson::value_t::array:
        return "an array";
    case ojson::value_t::object:
        return "an object";
    case ojson::value_t::number_integer:
    case ojson::value_t::number_unsigned:
    case ojson::value_t::number_float:
        return "a number";
    default:
        return "an unsupported value";
    }
}

[[noreturn]] void fail_type(const Ctx& ctx, const std::string& ptr, const std::string& field,
                            const ojson& v, const std::string& expected) {
    fail(ctx, ptr, field,
         (field.empty() ? std::string{} : field + ": ") + "expected " + expected + ", got " +
             type_name(v),
         format_rule);
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1] ? 1 : 0)});
            diag = up;
        }
    }
    return row[b.size()];
}

using Keys = std::initializer_list<std::string_view>;

/// Rejects keys outside `allowed` (in document order), suggesting the nearest allowed key.
template <class Allowed>
void check_keys_in(const Ctx& ctx, const ojson& obj, const std::string& ptr, const Allowed& allowed,
                   const std::string& what) {
    for (const auto& [key, value] : obj.items()) {
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end())
            continue;
        std::string best;
        std::size_t best_d = 3;
        std::string list;
        for (const std::string_view a : allowed) {
            list += (list.empty() ? "" : ", ") + std::string(a);
            const std::size_t d = edit_distance(key, a);
            if (d < best_d) {
                best_d = d;
                best = a;
            }
        }
        fail(ctx, child(ptr, key), key,
             "unknown key " + quote(key) + " in " + what +
                 (best.empty() ? std::string{} : " (did you mean '" + best + "'?)") +
                 "; allowed: " + list,
             format_rule);
    }
}
void check_keys(const Ctx& ctx, const ojson& obj, const std::string& ptr, Keys allowed,
                const std::string& what) {
    check_keys_in(ctx, obj, ptr, allowed, what);
}

const ojson& require_object(const Ctx& ctx, const ojson& v, const std::string& ptr,
                            const std::string& field, const std::string& what) {
    if (!v.is_object())
        fail_type(ctx, ptr, field, v, what);
    return v;
}

const ojson* find(const ojson& obj, std::string_view key) {
    const auto it = obj.find(std::string(key));
    return it == obj.end() ? nullptr : &*it;
}

const ojson& require_key(const Ctx& ctx, const ojson& obj, const std::string& ptr,
                         std::string_view key, const std::string& what) {
    if (const ojson* v = find(obj, key))
        return *v;
    fail(ctx, child(ptr, key), std::string(key),
         "missing required key '" + std::string(key) + "' (" + what + ")", format_rule);
}

double as_number(const Ctx& ctx, const ojson& v, const std::string& ptr, const std::string& field) {
    if (!v.is_number())
        fail_type(ctx, ptr, field, v, "a number");
    const double d = v.get<double>();
    if (!std::isfinite(d))
        fail_value(ctx, ptr, field, d, "must be a finite number", "DCX_finite");
    return d;
}

Vec2d as_vec2(const Ctx& ctx, const ojson& v, const std::string& ptr, const std::string& field) {
    if (!v.is_array() || v.size() != 2)
        fail(ctx, ptr, field,
             field + ": expected an array [x, y] of two numbers, got " +
                 (v.is_array() ? "an array of " + std::to_string(v.size()) + " elements"
                               : std::string(type_name(v))),
             format_rule);
    return {as_number(ctx, v[0], child(ptr, std::size_t{0}), field + ".x"),
            as_number(ctx, v[1], child(ptr, std::size_t{1}), field + ".y")};
}

long long as_integer(const Ctx& ctx, const ojson& v, const std::string& ptr,
                     const std::string& field, long long lo, long long hi) {
    if (!v.is_number())
        fail_type(ctx, ptr, field, v, "an integer");
    const std::string range =
        "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (v.is_number_unsigned()) {
        const auto u = v.get<unsigned long long>();
        if (u > static_cast<unsigned long long>(hi) ||
            (lo > 0 && u < static_cast<unsigned long long>(lo)))
            fail_value(ctx, ptr, field, double(u), range, format_rule);
        return static_cast<long long>(u);
    }
    if (v.is_number_integer()) {
        const auto i = v.get<long long>();
        if (i < lo || i > hi)
            fail_value(ctx, ptr, field, double(i), range, format_rule);
        return i;
    }
    // A double converts to long long only below 2^63: double(LLONG_MAX) is 2^63 itself, so
    // the range is checked on the integer, after the conversion is known to be defined.
    const double d = v.get<double>();
    if (!(d == std::floor(d)) || !(d >= -0x1p63 && d < 0x1p63))
        fail_value(ctx, ptr, field, d, range, format_rule);
    const auto i = static_cast<long long>(d);
    if (i < lo || i > hi)
        fail_value(ctx, ptr, field, d, range, format_rule);
    return i;
}

std::string as_string(const Ctx& ctx, const ojson& v, const std::string& ptr,
                      const std::string& field) {
    if (!v.is_string())
        fail_type(ctx, ptr, field, v, "a string");
    return v.get<std::string>();
}

bool as_bool(const Ctx& ctx, const ojson& v, const std::string& ptr, const std::string& field) {
    if (!v.is_boolean())
        fail_type(ctx, ptr, field, v, "true or false");
    return v.get<bool>();
}

/// Optional members: leave `out` unchanged when the key is absent.
void opt_number(const Ctx& ctx, const ojson& obj, const std::string& ptr, std::string_view key,
                double& out) {
    if (const ojson* v = find(obj, key))
        out = as_number(ctx, *v, child(ptr, key), std::string(key));
}
void opt_vec2(const Ctx& ctx, const ojson& obj, const std::string& ptr, std::string_view key,
              Vec2d& out) {
    if (const ojson* v = find(obj, key))
        out = as_vec2(ctx, *v, child(ptr, key), std::string(key));
}
double req_number(const Ctx& ctx, const ojson& obj, const std::string& ptr, std::string_view key,
                  const std::string& what) {
    return as_number(ctx, require_key(ctx, obj, ptr, key, what), child(ptr, key), std::string(key));
}

/// DCX_shape (the SRS's DCI_L, corrected): a shape dimension is > 0; DCX_range: within the
/// supported sizes.
double req_length(const Ctx& ctx, const ojson& obj, const std::string& ptr, std::string_view key,
                  const std::string& what) {
    const double v = req_number(ctx, obj, ptr, key, what);
    check_as_library(ctx, ptr, "", [&] { validate_size(key, v); });
    return v;
}

// ---------------------------------------------------------------------------------------------
// Materials
// ---------------------------------------------------------------------------------------------

Material parse_material_object(const Ctx& ctx, const ojson& v, const std::string& ptr, Material m) {
    require_object(ctx, v, ptr, "material", "a material object or a material name");
    check_keys(ctx, v, ptr, {"density", "restitution", "friction"}, "a material");
    opt_number(ctx, v, ptr, "density", m.density);
    opt_number(ctx, v, ptr, "restitution", m.restitution);
    opt_number(ctx, v, ptr, "friction", m.friction);
    if (!(m.density > 0.0))
        fail_value(ctx, child(ptr, "density"), "density", m.density, "must be > 0", "DCX_density");
    if (!(m.restitution >= 0.0 && m.restitution <= 1.0))
        fail_value(ctx, child(ptr, "restitution"), "restitution", m.restitution,
                   "must be in [0, 1]", "DCI_CR");
    if (!(m.friction >= 0.0))
        fail_value(ctx, child(ptr, "friction"), "friction", m.friction, "must be >= 0",
                   "DCX_friction");
    check_as_library(ctx, ptr, "material.", [&] { validate(m); }); // DCX_range
    return m;
}

/// A "material" member: a name from "materials" or an inline object (missing fields take the
/// defaults in `base`).
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

Material shape_default_material(const Ctx& ctx) {
    return ctx.default_material.value_or(Material{});
}

Material generator_default_material(const Ctx& ctx) {
    return ctx.default_material.value_or(Material{1.0, 0.0, 0.6});
}

// ---------------------------------------------------------------------------------------------
// Loads
// ---------------------------------------------------------------------------------------------

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

void attach_loads(SceneBody& b) {
    if (b.loads.empty())
        return;
    b.def.load = [loads = b.loads](double t) { return loads(t); };
}

// ---------------------------------------------------------------------------------------------
// Shapes and bodies
// ---------------------------------------------------------------------------------------------

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

/// A shape's "filter" (DD27) and "sensor" (DD28), the keys every kind of shape has.
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
}

std::vector<ShapeDef> parse_shape_geometry(const Ctx& ctx, const ojson& v, const std::string& ptr,
                                           std::size_t& chain_budget);

/// A "shapes" entry: one shape, or a chain's segments, each with the entry's filter and sensor.
std::vector<ShapeDef> parse_shape(Ctx& ctx, const ojson& v, const std::string& ptr) {
    std::vector<ShapeDef> defs = parse_shape_geometry(ctx, v, ptr, ctx.chain_budget);
    ShapeDef common;
    parse_filter_and_sensor(ctx, v, ptr, common);
    for (ShapeDef& def : defs) {
        def.filter = common.filter;
        def.is_sensor = common.is_sensor;
    }
    return defs;
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
            check_keys(
                ctx, v, ptr,
                {"type", "width", "height", "center", "angle", "material", "filter", "sensor"},
                "a box shape");
            const double w = req_length(ctx, v, ptr, "width", "a box shape");
            const double h = req_length(ctx, v, ptr, "height", "a box shape");
            Vec2d center{};
            double angle = 0.0;
            opt_vec2(ctx, v, ptr, "center", center);
            opt_number(ctx, v, ptr, "angle", angle);
            read_material();
            return {checked(ctx, ptr, ptr, box_shape(w, h, material, center, angle))};
        }
        if (type == "circle") {
            check_keys(ctx, v, ptr, {"type", "radius", "center", "material", "filter", "sensor"},
                       "a circle shape");
            const double r = req_length(ctx, v, ptr, "radius", "a circle shape");
            Vec2d center{};
            opt_vec2(ctx, v, ptr, "center", center);
            read_material();
            return {checked(ctx, ptr, ptr, circle_shape(r, material, center))};
        }
        if (type == "polygon") {
            check_keys(ctx, v, ptr, {"type", "points", "material", "filter", "sensor"},
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
                       {"type", "center1", "center2", "radius", "material", "filter", "sensor"},
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
            check_keys(ctx, v, ptr, {"type", "point1", "point2", "material", "filter", "sensor"},
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
            check_keys(ctx, v, ptr, {"type", "points", "loop", "material", "filter", "sensor"},
                       "a chain shape");
            read_material();
            return parse_chain(ctx, v, ptr, material, chain_budget);
        }
        if (type == "chain_segment") {
            check_keys(
                ctx, v, ptr,
                {"type", "ghost1", "point1", "point2", "ghost2", "material", "filter", "sensor"},
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

BodyType parse_body_type(const Ctx& ctx, const ojson& v, const std::string& ptr) {
    const std::string t = as_string(ctx, v, ptr, "type");
    if (t == "dynamic")
        return BodyType::dynamic;
    if (t == "static")
        return BodyType::static_body;
    if (t == "kinematic")
        return BodyType::kinematic;
    fail(ctx, ptr, "type",
         "unknown body type " + quote(t) + "; allowed: dynamic, static, kinematic", format_rule);
}

void claim_name(Ctx& ctx, const std::string& name, const std::string& ptr) {
    if (name.empty())
        return;
    const auto [it, fresh] = ctx.names.emplace(name, ptr);
    if (!fresh)
        fail(ctx, ptr, "name",
             "body name " + quote(name) + " is already used by " + shown_pointer(it->second) +
                 " (names must be unique)",
             format_rule);
}

// A joint's keys are its definition's fields under the same names: one table per kind, walked
// by the parser, the writer and the key check alike, so the three cannot disagree. A visitor is
// called as v(key, member, required).

template <class V> void joint_fields(RevoluteJointDef& d, V&& v) {
    v("anchor", d.anchor, true);
    v("enable_limit", d.enable_limit, false);
    v("lower_angle", d.lower_angle, false);
    v("upper_angle", d.upper_angle, false);
    v("enable_motor", d.enable_motor, false);
    v("motor_speed", d.motor_speed, false);
    v("max_motor_torque", d.max_motor_torque, false);
    v("enable_spring", d.enable_spring, false);
    v("hertz", d.hertz, false);
    v("damping_ratio", d.damping_ratio, false);
}
template <class V> void joint_fields(DistanceJointDef& d, V&& v) {
    v("anchor_a", d.anchor_a, true);
    v("anchor_b", d.anchor_b, true);
    v("length", d.length, false);
    v("hertz", d.hertz, false);
    v("damping_ratio", d.damping_ratio, false);
    v("enable_limit", d.enable_limit, false);
    v("min_length", d.min_length, false);
    v("max_length", d.max_length, false);
}
template <class V> void joint_fields(PrismaticJointDef& d, V&& v) {
    v("anchor", d.anchor, true);
    v("axis", d.axis, true);
    v("enable_limit", d.enable_limit, false);
    v("lower_translation", d.lower_translation, false);
    v("upper_translation", d.upper_translation, false);
    v("enable_motor", d.enable_motor, false);
    v("motor_speed", d.motor_speed, false);
    v("max_motor_force", d.max_motor_force, false);
    v("enable_spring", d.enable_spring, false);
    v("hertz", d.hertz, false);
    v("damping_ratio", d.damping_ratio, false);
}
template <class V> void joint_fields(WeldJointDef& d, V&& v) {
    v("anchor", d.anchor, true);
    v("linear_hertz", d.linear_hertz, false);
    v("linear_damping_ratio", d.linear_damping_ratio, false);
    v("angular_hertz", d.angular_hertz, false);
    v("angular_damping_ratio", d.angular_damping_ratio, false);
}
template <class V> void joint_fields(WheelJointDef& d, V&& v) {
    v("anchor", d.anchor, true);
    v("axis", d.axis, true);
    v("enable_spring", d.enable_spring, false);
    v("hertz", d.hertz, false);
    v("damping_ratio", d.damping_ratio, false);
    v("enable_limit", d.enable_limit, false);
    v("lower_translation", d.lower_translation, false);
    v("upper_translation", d.upper_translation, false);
    v("enable_motor", d.enable_motor, false);
    v("motor_speed", d.motor_speed, false);
    v("max_motor_torque", d.max_motor_torque, false);
}
template <class V> void joint_fields(MotorJointDef& d, V&& v) {
    v("linear_offset", d.linear_offset, false);
    v("angular_offset", d.angular_offset, false);
    v("max_force", d.max_force, false);
    v("max_torque", d.max_torque, false);
    v("correction_factor", d.correction_factor, false);
}
/// The fields every two-body joint has.
template <class Def, class V> void all_joint_fields(Def& d, V&& v) {
    joint_fields(d, v);
    v("collide_connected", d.collide_connected, false);
    v("break_force", d.break_force, false);
}

/// The "type" names, in SceneJoint::Definition's order.
constexpr std::array<std::string_view, std::variant_size_v<SceneJoint::Definition>> joint_types{
    "revolute", "distance", "prismatic", "weld", "wheel", "motor"};

/// A default definition of the kind named `type`; false for an unknown name.
template <std::size_t I = 0> bool make_joint_def(std::string_view type, SceneJoint::Definition& d) {
    if constexpr (I < std::variant_size_v<SceneJoint::Definition>) {
        if (type == joint_types[I]) {
            d.emplace<I>();
            return true;
        }
        return make_joint_def<I + 1>(type, d);
    } else {
        return false;
    }
}

/// A "joints" entry: {"type": ..., "body_a", "body_b", and the fields of its kind's
/// definition (joint_fields)}. The names are resolved, and the joint checked (DCX_joint), by
/// validate_scene.
SceneJoint parse_joint(Ctx& ctx, const ojson& v, const std::string& ptr) {
    require_object(ctx, v, ptr, "", "a joint object");
    SceneJoint j;
    j.source = ptr;
    const std::string type =
        as_string(ctx, require_key(ctx, v, ptr, "type", "a joint"), child(ptr, "type"), "type");
    if (!make_joint_def(type, j.def)) {
        std::string names;
        for (const std::string_view t : joint_types)
            names += (names.empty() ? "\"" : ", \"") + std::string(t) + "\"";
        fail(ctx, child(ptr, "type"), "type",
             "unknown joint type " + quote(type) + "; expected one of " + names, format_rule);
    }
    const std::string what = "a " + type + " joint";
    std::visit(
        [&](auto& def) {
            std::vector<std::string_view> keys{"type", "body_a", "body_b"};
            all_joint_fields(def, [&](std::string_view key, auto&, bool) { keys.push_back(key); });
            check_keys_in(ctx, v, ptr, keys, what);
            all_joint_fields(def, [&](std::string_view key, auto& member, bool required) {
                const ojson* value = required ? &require_key(ctx, v, ptr, key, what) : find(v, key);
                if (!value)
                    return;
                const std::string at = child(ptr, key), field(key);
                using T = std::remove_cvref_t<decltype(member)>;
                if constexpr (std::is_same_v<T, Vec2d>)
                    member = as_vec2(ctx, *value, at, field);
                else if constexpr (std::is_same_v<T, bool>)
                    member = as_bool(ctx, *value, at, field);
                else
                    member = as_number(ctx, *value, at, field);
            });
        },
        j.def);
    j.body_a = as_string(ctx, require_key(ctx, v, ptr, "body_a", "a joint"), child(ptr, "body_a"),
                         "body_a");
    j.body_b = as_string(ctx, require_key(ctx, v, ptr, "body_b", "a joint"), child(ptr, "body_b"),
                         "body_b");
    return j;
}

/// Creates the scene joint in `world` with the bodies of its names.
JointId create_scene_joint(World& world, const SceneJoint& j, BodyId a, BodyId b) {
    return std::visit(
        [&](auto def) {
            def.body_a = a;
            def.body_b = b;
            return world.create_joint(def);
        },
        j.def);
}

SceneBody parse_body(Ctx& ctx, const ojson& v, const std::string& ptr) {
    check_keys(ctx, v, ptr,
               {"name", "type", "position", "angle", "velocity", "angular_velocity", "mass",
                "inertia", "gravity_scale", "linear_damping", "angular_damping", "fixed_rotation",
                "bullet", "enable_sleep", "awake", "force", "torque", "loads", "shapes"},
               "a body");
    SceneBody b;
    b.source = ptr;
    BodyDef& d = b.def;
    if (const ojson* n = find(v, "name"))
        d.name = as_string(ctx, *n, child(ptr, "name"), "name");
    if (const ojson* t = find(v, "type"))
        d.type = parse_body_type(ctx, *t, child(ptr, "type"));
    opt_vec2(ctx, v, ptr, "position", d.position);        // DCI_p
    opt_number(ctx, v, ptr, "angle", d.angle);            // DCI_phi: any real, wrapped on output
    opt_vec2(ctx, v, ptr, "velocity", d.linear_velocity); // DCI_v
    opt_number(ctx, v, ptr, "angular_velocity", d.angular_velocity); // DCI_omega
    opt_vec2(ctx, v, ptr, "force", d.force);                         // DCI_F
    opt_number(ctx, v, ptr, "torque", d.torque);                     // DCI_tau
    opt_number(ctx, v, ptr, "gravity_scale", d.gravity_scale);
    if (const ojson* f = find(v, "fixed_rotation"))
        d.fixed_rotation = as_bool(ctx, *f, child(ptr, "fixed_rotation"), "fixed_rotation");
    if (const ojson* f = find(v, "bullet")) // DD29
        d.bullet = as_bool(ctx, *f, child(ptr, "bullet"), "bullet");
    if (const ojson* e = find(v, "enable_sleep"))
        d.enable_sleep = as_bool(ctx, *e, child(ptr, "enable_sleep"), "enable_sleep");
    if (const ojson* a = find(v, "awake"))
        d.awake = as_bool(ctx, *a, child(ptr, "awake"), "awake");
    if (const ojson* m = find(v, "mass")) {
        const double mass = as_number(ctx, *m, child(ptr, "mass"), "mass");
        if (!(mass > 0.0))
            fail_value(ctx, child(ptr, "mass"), "mass", mass, "must be > 0", "DCI_m");
        d.mass = mass;
    }
    if (const ojson* i = find(v, "inertia")) {
        const double inertia = as_number(ctx, *i, child(ptr, "inertia"), "inertia");
        if (!(inertia > 0.0))
            fail_value(ctx, child(ptr, "inertia"), "inertia", inertia, "must be > 0", "DCI_I");
        d.inertia = inertia;
    }
    for (const auto& [key, rate] :
         {std::pair<const char*, double*>{"linear_damping", &d.linear_damping},
          {"angular_damping", &d.angular_damping}}) {
        if (const ojson* c = find(v, key)) {
            *rate = as_number(ctx, *c, child(ptr, key), key);
            if (!(*rate >= 0.0))
                fail_value(ctx, child(ptr, key), key, *rate, "must be >= 0", "DCX_damping");
        }
    }
    if (const ojson* l = find(v, "loads"))
        b.loads = parse_loads(ctx, *l, child(ptr, "loads"));
    if (const ojson* s = find(v, "shapes")) {
        const std::string sp = child(ptr, "shapes");
        if (!s->is_array())
            fail_type(ctx, sp, "shapes", *s, "an array of shapes");
        for (std::size_t i = 0; i < s->size(); ++i)
            for (ShapeDef& def : parse_shape(ctx, (*s)[i], child(sp, i)))
                b.shapes.push_back(std::move(def));
    }
    if (d.type == BodyType::dynamic && b.shapes.empty() && !d.mass)
        fail(ctx, child(ptr, "shapes"), "shapes",
             "a dynamic body needs at least one shape or a \"mass\" (DCI_m)", "DCI_m");
    // Segments and chains have no area: alone they would leave the library's arbitrary 1 kg.
    const auto has_area = [](const ShapeDef& def) {
        const ShapeType t = def.geometry.type;
        return t == ShapeType::circle || t == ShapeType::polygon || t == ShapeType::capsule;
    };
    if (d.type == BodyType::dynamic && !d.mass &&
        !std::any_of(b.shapes.begin(), b.shapes.end(), has_area))
        fail(ctx, child(ptr, "shapes"), "shapes",
             "a dynamic body whose shapes are all segments or chains (no area, so no mass) "
             "needs a \"mass\" (DCI_m)",
             "DCI_m");
    check_as_library(ctx, ptr, "body.", [&] { validate(d); }); // DCX_range, at the key
    claim_name(ctx, d.name, child(ptr, "name"));
    attach_loads(b);
    return b;
}

// ---------------------------------------------------------------------------------------------
// Generators
// ---------------------------------------------------------------------------------------------

int gen_int(const Ctx& ctx, const ojson& v, const std::string& ptr, std::string_view key, int dflt,
            int lo, int hi) {
    if (const ojson* x = find(v, key))
        return static_cast<int>(as_integer(ctx, *x, child(ptr, key), std::string(key), lo, hi));
    return dflt;
}

std::vector<SceneBody> parse_generator(Ctx& ctx, const ojson& v, const std::string& ptr) {
    const std::string kind =
        as_string(ctx, v.at("generator"), child(ptr, "generator"), "generator");
    std::string name;
    if (const ojson* n = find(v, "name"))
        name = as_string(ctx, *n, child(ptr, "name"), "name");
    std::vector<SceneBody> bodies;
    try {
        if (kind == "pyramid") {
            check_keys(ctx, v, ptr,
                       {"generator", "name", "base", "box", "gap", "origin", "ground_width",
                        "ground_height", "material"},
                       "a pyramid generator");
            PyramidParams p;
            if (!name.empty())
                p.name = name;
            p.base = gen_int(ctx, v, ptr, "base", p.base, 1, PyramidParams::max_base);
            opt_number(ctx, v, ptr, "box", p.box);
            opt_number(ctx, v, ptr, "gap", p.gap);
            opt_vec2(ctx, v, ptr, "origin", p.origin);
            opt_number(ctx, v, ptr, "ground_width", p.ground_width);
            opt_number(ctx, v, ptr, "ground_height", p.ground_height);
            p.material = generator_default_material(ctx);
            if (const ojson* m = find(v, "material"))
                p.material = parse_material_ref(ctx, *m, child(ptr, "material"), p.material);
            bodies = generate_pyramid(p);
        } else if (kind == "rain") {
            check_keys(ctx, v, ptr,
                       {"generator", "name", "count", "box", "spacing", "jitter", "drop_height",
                        "seed", "container", "material"},
                       "a rain generator");
            RainParams p;
            if (!name.empty())
                p.name = name;
            p.count = gen_int(ctx, v, ptr, "count", p.count, 0, RainParams::max_count);
            opt_number(ctx, v, ptr, "box", p.box);
            opt_number(ctx, v, ptr, "spacing", p.spacing);
            opt_number(ctx, v, ptr, "jitter", p.jitter);
            opt_number(ctx, v, ptr, "drop_height", p.drop_height);
            if (const ojson* s = find(v, "seed"))
                p.seed = static_cast<std::uint64_t>(as_integer(
                    ctx, *s, child(ptr, "seed"), "seed", 0, std::numeric_limits<long long>::max()));
            if (const ojson* c = find(v, "container")) {
                const std::string cp = child(ptr, "container");
                require_object(ctx, *c, cp, "container", "a container object");
                check_keys(ctx, *c, cp, {"width", "height", "wall", "origin"}, "a container");
                opt_number(ctx, *c, cp, "width", p.container.width);
                opt_number(ctx, *c, cp, "height", p.container.height);
                opt_number(ctx, *c, cp, "wall", p.container.wall);
                opt_vec2(ctx, *c, cp, "origin", p.container.origin);
            }
            p.material = generator_default_material(ctx);
            if (const ojson* m = find(v, "material"))
                p.material = parse_material_ref(ctx, *m, child(ptr, "material"), p.material);
            bodies = generate_rain(p);
        } else if (kind == "elastic_pair") {
            check_keys(ctx, v, ptr,
                       {"generator", "name", "box", "speed", "distance", "density", "restitution"},
                       "an elastic_pair generator");
            ElasticPairParams p;
            if (!name.empty())
                p.name = name;
            opt_number(ctx, v, ptr, "box", p.box);
            opt_number(ctx, v, ptr, "speed", p.speed);
            opt_number(ctx, v, ptr, "distance", p.distance);
            opt_number(ctx, v, ptr, "density", p.density);
            opt_number(ctx, v, ptr, "restitution", p.restitution);
            bodies = generate_elastic_pair(p);
        } else {
            fail(ctx, child(ptr, "generator"), "generator",
                 "unknown generator " + quote(kind) + "; allowed: pyramid, rain, elastic_pair",
                 format_rule);
        }
    } catch (const ValidationError& e) {
        // Generator parameters are named by their keys ("container.width").
        fail_from(ctx, ptr, e, true);
    }
    for (SceneBody& b : bodies) {
        b.source = ptr;
        b.generated = true;
        claim_name(ctx, b.def.name, ptr);
    }
    return bodies;
}

// ---------------------------------------------------------------------------------------------
// The document
// ---------------------------------------------------------------------------------------------

double parse_dt(const Ctx& ctx, const ojson& v, const std::string& ptr) {
    double dt = 0.0;
    if (v.is_string()) { // "1/60"
        const std::string s = v.get<std::string>();
        const auto slash = s.find('/');
        double num = 0.0;
        double den = 0.0;
        const auto parse = [](std::string_view t, double& out) {
            const auto r = std::from_chars(t.data(), t.data() + t.size(), out);
            return r.ec == std::errc{} && r.ptr == t.data() + t.size();
        };
        if (slash == std::string::npos || !parse(std::string_view(s).substr(0, slash), num) ||
            !parse(std::string_view(s).substr(slash + 1), den) || !(den != 0.0))
            fail(ctx, ptr, "dt",
                 "dt: expected a number of seconds or a fraction string such as \"1/60\", got " +
                     quote(s),
                 format_rule);
        dt = num / den;
        if (!std::isfinite(dt))
            fail_value(ctx, ptr, "dt", dt, "must be a finite number", "DCX_finite");
    } else {
        dt = as_number(ctx, v, ptr, "dt");
    }
    if (!(dt > 0.0))
        fail_value(ctx, ptr, "dt", dt, "must be > 0", "DCX_dt");
    check_as_library(ctx, ptr, "dt", [&] { validate_time_step(dt); }); // DCX_range
    return dt;
}

WorldDef parse_world(const Ctx& ctx, const ojson& v, const std::string& ptr) {
    require_object(ctx, v, ptr, "world", "an object of world settings");
    check_keys(ctx, v, ptr,
               {"gravity", "substeps", "contact_hertz", "contact_damping_ratio",
                "contact_push_max_velocity", "linear_slop", "speculative_distance",
                "manifold_reuse_distance", "contact_regions", "restitution_threshold",
                "enable_sleep", "time_to_sleep", "linear_sleep_tolerance",
                "angular_sleep_tolerance", "enable_continuous"},
               "world settings");
    WorldDef w;
    opt_vec2(ctx, v, ptr, "gravity", w.gravity); // DCI_g
    // Its range (DCX_dt) is the World's to check, in validate_scene.
    if (const ojson* s = find(v, "substeps"))
        w.substeps = static_cast<int>(as_integer(ctx, *s, child(ptr, "substeps"), "substeps",
                                                 std::numeric_limits<int>::min(),
                                                 std::numeric_limits<int>::max()));
    opt_number(ctx, v, ptr, "contact_hertz", w.contact_hertz);
    opt_number(ctx, v, ptr, "contact_damping_ratio", w.contact_damping_ratio);
    opt_number(ctx, v, ptr, "contact_push_max_velocity", w.contact_push_max_velocity);
    opt_number(ctx, v, ptr, "linear_slop", w.linear_slop);
    opt_number(ctx, v, ptr, "speculative_distance", w.speculative_distance);
    opt_number(ctx, v, ptr, "manifold_reuse_distance", w.manifold_reuse_distance);
    // Its range is the World's to check, in validate_scene.
    if (const ojson* r = find(v, "contact_regions"))
        w.contact_regions = static_cast<int>(
            as_integer(ctx, *r, child(ptr, "contact_regions"), "contact_regions",
                       std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
    opt_number(ctx, v, ptr, "restitution_threshold", w.restitution_threshold);
    if (const ojson* e = find(v, "enable_sleep"))
        w.enable_sleep = as_bool(ctx, *e, child(ptr, "enable_sleep"), "enable_sleep");
    opt_number(ctx, v, ptr, "time_to_sleep", w.time_to_sleep);
    opt_number(ctx, v, ptr, "linear_sleep_tolerance", w.linear_sleep_tolerance);
    opt_number(ctx, v, ptr, "angular_sleep_tolerance", w.angular_sleep_tolerance);
    if (const ojson* e = find(v, "enable_continuous"))
        w.enable_continuous =
            as_bool(ctx, *e, child(ptr, "enable_continuous"), "enable_continuous");
    return w;
}

void parse_materials(Ctx& ctx, const ojson& v, const std::string& ptr, Scene& scene) {
    require_object(ctx, v, ptr, "materials", "an object of named materials");
    for (const auto& [name, m] : v.items()) {
        const std::string mp = child(ptr, name);
        const Material mat = parse_material_object(ctx, m, mp, Material{});
        ctx.materials[name] = mat;
        scene.materials[name] = mat;
        if (name == "default")
            ctx.default_material = mat;
    }
}

// ---------------------------------------------------------------------------------------------
// JSON text -> DOM, with positions for syntax errors and detection of duplicate keys
// ---------------------------------------------------------------------------------------------

class DomBuilder {
  public:
    using number_integer_t = ojson::number_integer_t;
    using number_unsigned_t = ojson::number_unsigned_t;
    using number_float_t = ojson::number_float_t;
    using string_t = ojson::string_t;
    using binary_t = ojson::binary_t;

    static constexpr std::size_t max_depth = 128;

    ojson root;
    // Failure report.
    bool failed = false;
    std::size_t position = 0; // chars read when a syntax error happened (0: no position)
    std::string message;
    std::string pointer;    // for duplicate keys and nesting
    std::string last_token; // the token the parser stopped at

    bool null() { return put(nullptr); }
    bool boolean(bool b) { return put(b); }
    bool number_integer(number_integer_t v) { return put(v); }
    bool number_unsigned(number_unsigned_t v) { return put(v); }
    bool number_float(number_float_t v, const string_t&) { return put(v); }
    bool string(string_t& s) { return put(s); }
    bool binary(binary_t&) { return error_at_pointer("binary values are not JSON"); }
    bool start_object(std::size_t) { return open(ojson::object()); }
    bool start_array(std::size_t) { return open(ojson::array()); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }
    bool key(string_t& k) {
        if (stack_.back()->contains(k)) {
            pointer = current_pointer() + "/" + escape_token(k);
            return error_at_pointer("duplicate key " + quote(k));
        }
        key_ = k;
        return true;
    }
    bool parse_error(std::size_t pos, const std::string& token,
                     const nlohmann::detail::exception& e) {
        failed = true;
        position = pos;
        last_token = token;
        std::string what = e.what();
        const auto syntax = what.find("syntax error");
        if (syntax != std::string::npos) {
            what.erase(0, syntax);
        } else if (const auto close = what.find("] "); close != std::string::npos) {
            what.erase(0, close + 2);
        }
        // The parser quotes the whole token it stopped in ("last read: '...'"), which may be a
        // string of megabytes: keep its start.
        if (const auto lr = what.find("last read: '"); lr != std::string::npos) {
            const std::size_t start = lr + 12;
            std::size_t end = what.find("'; expected", start);
            if (end == std::string::npos)
                end = what.rfind('\'');
            if (end != std::string::npos && end > start)
                what.replace(start, end - start, printable(what.substr(start, end - start), 40));
        }
        if (what.starts_with("number overflow"))
            what += " (DCX_finite)";
        message = what;
        return false;
    }

  private:
    std::vector<ojson*> stack_;
    std::vector<std::string> path_;
    std::string key_;

    std::string segment() const {
        if (stack_.empty())
            return {};
        return stack_.back()->is_array() ? std::to_string(stack_.back()->size())
                                         : escape_token(key_);
    }
    std::string current_pointer() const {
        std::string p;
        for (const std::string& s : path_)
            p += "/" + s;
        return p;
    }
    template <class V> ojson* insert(V&& v) {
        if (stack_.empty()) {
            root = std::forward<V>(v);
            return &root;
        }
        ojson& top = *stack_.back();
        if (top.is_array()) {
            top.push_back(std::forward<V>(v));
            return &top.back();
        }
        ojson& slot = top[key_];
        slot = std::forward<V>(v);
        return &slot;
    }
    template <class V> bool put(V&& v) {
        insert(std::forward<V>(v));
        return true;
    }
    bool open(ojson container) {
        if (stack_.size() >= max_depth) {
            pointer = current_pointer();
            return error_at_pointer("nesting deeper than " + std::to_string(max_depth) + " levels");
        }
        std::string seg = segment();
        ojson* p = insert(std::move(container));
        if (!stack_.empty())
            path_.push_back(std::move(seg));
        stack_.push_back(p);
        return true;
    }
    bool close() {
        stack_.pop_back();
        if (!path_.empty()) // the root has no segment
            path_.pop_back();
        return true;
    }
    bool error_at_pointer(std::string msg) {
        failed = true;
        message = std::move(msg);
        return false;
    }
};

/// 1-based line and column of the byte at `at`.
std::pair<int, int> line_column(std::string_view text, std::size_t at) {
    const auto nl_before = text.substr(0, at).rfind('\n');
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
    const int column =
        static_cast<int>(nl_before == std::string_view::npos ? at + 1 : at - nl_before);
    return {line, column};
}

ojson parse_json(std::string_view text, const std::string& origin) {
    // The parser takes a NUL byte for the end of the input, so that a scene followed by one and
    // garbage would load. JSON text has no NUL (in a string it must be escaped): reject it.
    if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
        const auto [line, column] = line_column(text, nul);
        throw SceneError(origin, "", line, column, "", "",
                         "syntax error: a NUL byte (JSON text has none)");
    }
    DomBuilder dom;
    const bool ok = ojson::sax_parse(text.begin(), text.end(), &dom);
    if (ok && !dom.failed)
        return std::move(dom.root);
    if (dom.position > 0) {
        // Line and column (1-based) of the character at which the parser stopped, or of the
        // end of the input. For an unexpected string or an overflowing number the parser has
        // read the whole token: point at its start instead.
        std::size_t at = std::min(dom.position - 1, text.size());
        const std::string& tok = dom.last_token;
        const bool whole_token = (tok.size() >= 2 && tok.front() == '"' && tok.back() == '"') ||
                                 dom.message.starts_with("number overflow");
        if (whole_token && tok.size() <= dom.position && dom.position <= text.size() &&
            text.substr(dom.position - tok.size(), tok.size()) == tok)
            at = dom.position - tok.size();
        const auto [line, column] = line_column(text, at);
        throw SceneError(origin, "", line, column, "",
                         dom.message.ends_with("(DCX_finite)") ? "DCX_finite" : "", dom.message);
    }
    throw SceneError(origin, dom.pointer, 0, 0, "", "", dom.message);
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Public functions
// ---------------------------------------------------------------------------------------------

namespace {

/// How many shapes from `s` on are chain segments in a row (0 when shapes[s] is not one).
std::size_t chain_run(const std::vector<ShapeDef>& shapes, std::size_t s) {
    std::size_t n = 0;
    while (s + n < shapes.size() && shapes[s + n].geometry.type == ShapeType::chain_segment)
        ++n;
    return n;
}

/// "the scene is larger than the limit of N bytes": the one message of the size limit.
[[noreturn]] void fail_size(const std::string& origin, std::size_t max_bytes) {
    const std::string mib = max_bytes % (1 << 20) == 0
                                ? " (" + std::to_string(max_bytes >> 20) + " MiB)"
                                : std::string{};
    throw SceneError(origin, "", 0, 0, "", "",
                     "the scene is larger than the size limit of " + std::to_string(max_bytes) +
                         " bytes" + mib + " (docs/scene-format.md, Limits)");
}

/// The whole stream, in chunks, refused as soon as it exceeds max_bytes: never more than that
/// (and one chunk) is held, whatever the source.
std::string read_limited(std::istream& in, const std::string& origin, std::size_t max_bytes) {
    std::string text;
    std::array<char, 1 << 16> chunk;
    while (in) {
        in.read(chunk.data(), std::streamsize(chunk.size()));
        const auto n = static_cast<std::size_t>(in.gcount());
        if (n > max_bytes - text.size()) // text.size() <= max_bytes: no wrap-around
            fail_size(origin, max_bytes);
        text.append(chunk.data(), n);
    }
    if (in.bad())
        throw SceneError(origin, "", 0, 0, "", "",
                         std::string("cannot read the scene: ") + std::strerror(errno));
    return text;
}

} // namespace

Scene parse_scene(std::string_view json, std::string_view origin_view, std::size_t max_bytes) {
    Ctx ctx;
    ctx.origin = std::string(origin_view);
    if (json.size() > max_bytes)
        fail_size(ctx.origin, max_bytes);
    const ojson root = parse_json(json, ctx.origin);
    const std::string ptr;
    require_object(ctx, root, ptr, "", "a scene object {\"dt\", \"steps\", \"bodies\", ...}");
    check_keys(ctx, root, ptr,
               {"version", "description", "world", "dt", "steps", "output_every", "materials",
                "bodies", "joints"},
               "a scene");
    Scene scene;
    if (const ojson* v = find(root, "version")) {
        const long long version = as_integer(ctx, *v, "/version", "version", 1, 1);
        (void)version;
    }
    if (const ojson* d = find(root, "description"))
        scene.description = as_string(ctx, *d, "/description", "description");
    if (const ojson* w = find(root, "world"))
        scene.world = parse_world(ctx, *w, "/world");
    scene.dt = parse_dt(ctx, require_key(ctx, root, ptr, "dt", "a scene"), "/dt");
    scene.steps = static_cast<int>(as_integer(ctx, require_key(ctx, root, ptr, "steps", "a scene"),
                                              "/steps", "steps", 0, 100000000));
    if (const ojson* o = find(root, "output_every"))
        scene.output_every =
            static_cast<int>(as_integer(ctx, *o, "/output_every", "output_every", 0, 100000000));
    if (const ojson* m = find(root, "materials"))
        parse_materials(ctx, *m, "/materials", scene);

    const ojson& bodies = require_key(ctx, root, ptr, "bodies", "a scene");
    if (!bodies.is_array())
        fail_type(ctx, "/bodies", "bodies", bodies, "an array of bodies and generators");
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const std::string bp = child(std::string("/bodies"), i);
        const ojson& b = bodies[i];
        require_object(ctx, b, bp, "", "a body object or a generator object");
        if (b.contains("generator")) {
            for (SceneBody& g : parse_generator(ctx, b, bp))
                scene.bodies.push_back(std::move(g));
        } else {
            scene.bodies.push_back(parse_body(ctx, b, bp));
        }
        if (scene.bodies.size() > max_scene_bodies)
            fail(ctx, bp, "bodies",
                 "the scene's bodies number " + std::to_string(scene.bodies.size()) +
                     " with this entry: at most " + std::to_string(max_scene_bodies) +
                     " bodies, written and generated, in one scene");
    }
    if (const ojson* joints = find(root, "joints")) {
        if (!joints->is_array())
            fail_type(ctx, "/joints", "joints", *joints, "an array of joints");
        for (std::size_t i = 0; i < joints->size(); ++i)
            scene.joints.push_back(
                parse_joint(ctx, (*joints)[i], child(std::string("/joints"), i)));
    }
    validate_scene(scene, ctx.origin);
    return scene;
}

Scene load_scene(const std::filesystem::path& path, std::size_t max_bytes) {
    const std::string origin = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw SceneError(origin, "", 0, 0, "", "",
                         std::string("cannot open the scene file: ") + std::strerror(errno));
    return parse_scene(read_limited(in, origin, max_bytes), origin, max_bytes);
}

Scene load_scene(std::istream& in, std::string_view origin, std::size_t max_bytes) {
    const std::string name(origin);
    return parse_scene(read_limited(in, name, max_bytes), name, max_bytes);
}

void validate_scene(const Scene& scene, std::string_view origin_view) {
    Ctx ctx;
    ctx.origin = std::string(origin_view);
    if (!(std::isfinite(scene.dt) && scene.dt > 0.0))
        fail_value(ctx, "/dt", "dt", scene.dt, "must be finite and > 0", "DCX_dt");
    check_as_library(ctx, "/dt", "dt", [&] { validate_time_step(scene.dt); }); // DCX_range
    if (scene.steps < 0)
        fail_value(ctx, "/steps", "steps", scene.steps, "must be >= 0", format_rule);
    if (scene.output_every < 0)
        fail_value(ctx, "/output_every", "output_every", scene.output_every, "must be >= 0",
                   format_rule);
    std::optional<World> world;
    std::map<std::string, BodyId> by_name;
    try {
        world.emplace(scene.world);
    } catch (const ValidationError& e) {
        // The library names world settings "world.<key>[.x|.y]".
        ValidationError mapped = e;
        if (mapped.field.starts_with("world."))
            mapped.field.erase(0, 6);
        fail_from(ctx, "/world", mapped, mapped.field.find('/') == std::string::npos);
    }
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const SceneBody& b = scene.bodies[i];
        const std::string at = b.source.empty() ? child(std::string("/bodies"), i) : b.source;
        const std::string who =
            b.def.name.empty() ? std::string{} : " (body " + quote(b.def.name) + ")";
        try {
            const BodyId id = world->create_body(b.def);
            if (!b.def.name.empty())
                by_name.emplace(b.def.name, id);
            for (std::size_t s = 0; s < b.shapes.size();) {
                // A chain's segments go in at once (create_chain: linear in their number);
                // one that fails is found again shape by shape, for its pointer.
                const std::size_t run = chain_run(b.shapes, s);
                try {
                    if (run > 1) {
                        world->create_chain(id, std::span(b.shapes).subspan(s, run));
                        s += run;
                        continue;
                    }
                } catch (const ValidationError&) {
                }
                for (const std::size_t end = s + std::max<std::size_t>(run, 1); s < end; ++s) {
                    try {
                        world->create_shape(id, b.shapes[s]);
                    } catch (const ValidationError& e) {
                        fail(ctx, b.generated ? at : child(child(at, "shapes"), s), e.field,
                             std::string(e.what()) + who, e.constraint);
                    }
                }
            }
        } catch (const ValidationError& e) {
            fail(ctx, at, e.field, std::string(e.what()) + who, e.constraint);
        }
    }
    for (const SceneJoint& j : scene.joints) {
        BodyId ids[2];
        for (const auto& [key, name, id] :
             {std::tuple{"body_a", &j.body_a, &ids[0]}, {"body_b", &j.body_b, &ids[1]}}) {
            const auto it = by_name.find(*name);
            if (it == by_name.end())
                fail(ctx, child(j.source, key), key, "no body is named " + quote(*name),
                     format_rule);
            *id = it->second;
        }
        try {
            create_scene_joint(*world, j, ids[0], ids[1]);
        } catch (const ValidationError& e) {
            std::string field = e.field;
            if (field.starts_with("joint."))
                field.erase(0, 6);
            fail(ctx, field_pointer(j.source, field), field, e.what(), e.constraint);
        }
    }
}

std::vector<BodyId> build_world(const Scene& scene, World& world) {
    validate_scene(scene);
    std::vector<BodyId> ids;
    ids.reserve(scene.bodies.size());
    for (const SceneBody& b : scene.bodies) {
        BodyDef def = b.def;
        if (!b.loads.empty()) // the data wins over a function set by hand (see scene.hpp)
            def.load = [loads = b.loads](double t) { return loads(t); };
        const BodyId id = world.create_body(def);
        for (std::size_t s = 0; s < b.shapes.size();) {
            const std::size_t run = chain_run(b.shapes, s);
            if (run > 1) {
                world.create_chain(id, std::span(b.shapes).subspan(s, run));
                s += run;
            } else {
                world.create_shape(id, b.shapes[s++]);
            }
        }
        ids.push_back(id);
    }
    std::map<std::string, BodyId> by_name;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        by_name.emplace(scene.bodies[i].def.name, ids[i]);
    for (const SceneJoint& j : scene.joints) // validate_scene found both names
        create_scene_joint(world, j, by_name.at(j.body_a), by_name.at(j.body_b));
    return ids;
}

// ---------------------------------------------------------------------------------------------
// Scene -> JSON
// ---------------------------------------------------------------------------------------------

namespace {

ojson vec(Vec2d v) {
    return ojson::array({v.x, v.y});
}

ojson material_json(const Material& m) {
    ojson j = ojson::object();
    j["density"] = m.density;
    j["restitution"] = m.restitution;
    j["friction"] = m.friction;
    return j;
}

ojson time_function_json(const TimeFunction& f) {
    ojson j = ojson::object();
    switch (f.kind) {
    case TimeFunction::Kind::constant:
        j["kind"] = "constant";
        j["value"] = f.value;
        break;
    case TimeFunction::Kind::sinusoid:
        j["kind"] = "sinusoid";
        j["amplitude"] = f.amplitude;
        j["omega"] = f.omega;
        j["phase"] = f.phase;
        j["offset"] = f.offset;
        break;
    case TimeFunction::Kind::step:
        j["kind"] = "step";
        j["time"] = f.time;
        j["before"] = f.before;
        j["after"] = f.after;
        break;
    case TimeFunction::Kind::ramp:
        j["kind"] = "ramp";
        j["t0"] = f.t0;
        j["t1"] = f.t1;
        j["from"] = f.from;
        j["to"] = f.to;
        break;
    }
    return j;
}

const char* body_type_name(BodyType t) {
    switch (t) {
    case BodyType::static_body:
        return "static";
    case BodyType::kinematic:
        return "kinematic";
    case BodyType::dynamic:
        return "dynamic";
    }
    return "dynamic";
}

/// A shape's geometry keys; a chain segment alone, with its ghosts.
ojson geometry_json(const Geometry& g) {
    switch (g.type) {
    case ShapeType::circle:
        return {{"type", "circle"}, {"radius", g.circle.radius}, {"center", vec(g.circle.center)}};
    case ShapeType::polygon: {
        ojson pts = ojson::array();
        for (int k = 0; k < g.polygon.count; ++k)
            pts.push_back(vec(g.polygon.vertices[std::size_t(k)]));
        return {{"type", "polygon"}, {"points", std::move(pts)}};
    }
    case ShapeType::capsule:
        return {{"type", "capsule"},
                {"center1", vec(g.capsule.center1)},
                {"center2", vec(g.capsule.center2)},
                {"radius", g.capsule.radius}};
    case ShapeType::segment:
        return {{"type", "segment"},
                {"point1", vec(g.segment.point1)},
                {"point2", vec(g.segment.point2)}};
    case ShapeType::chain_segment:
        break;
    }
    return {{"type", "chain_segment"},
            {"ghost1", vec(g.chain_segment.ghost1)},
            {"point1", vec(g.chain_segment.point1)},
            {"point2", vec(g.chain_segment.point2)},
            {"ghost2", vec(g.chain_segment.ghost2)}};
}

} // namespace

std::string scene_to_json(const Scene& scene, int indent) {
    ojson j = ojson::object();
    j["version"] = 1;
    if (!scene.description.empty())
        j["description"] = scene.description;
    const WorldDef& w = scene.world;
    j["world"] = {{"gravity", vec(w.gravity)},
                  {"substeps", w.substeps},
                  {"contact_hertz", w.contact_hertz},
                  {"contact_damping_ratio", w.contact_damping_ratio},
                  {"contact_push_max_velocity", w.contact_push_max_velocity},
                  {"linear_slop", w.linear_slop},
                  {"speculative_distance", w.speculative_distance},
                  {"manifold_reuse_distance", w.manifold_reuse_distance},
                  {"contact_regions", w.contact_regions},
                  {"restitution_threshold", w.restitution_threshold},
                  {"enable_sleep", w.enable_sleep},
                  {"time_to_sleep", w.time_to_sleep},
                  {"linear_sleep_tolerance", w.linear_sleep_tolerance},
                  {"angular_sleep_tolerance", w.angular_sleep_tolerance},
                  {"enable_continuous", w.enable_continuous}};
    j["dt"] = scene.dt;
    j["steps"] = scene.steps;
    j["output_every"] = scene.output_every;
    if (!scene.materials.empty()) {
        ojson mats = ojson::object();
        for (const auto& [name, m] : scene.materials)
            mats[name] = material_json(m);
        j["materials"] = std::move(mats);
    }
    ojson bodies = ojson::array();
    // Chains beyond the limit parse_scene sets are written segment by segment.
    std::size_t chain_budget = max_chain_points;
    for (const SceneBody& b : scene.bodies) {
        const BodyDef& d = b.def;
        ojson o = ojson::object();
        if (!d.name.empty())
            o["name"] = d.name;
        o["type"] = body_type_name(d.type);
        o["position"] = vec(d.position);
        o["angle"] = d.angle;
        o["velocity"] = vec(d.linear_velocity);
        o["angular_velocity"] = d.angular_velocity;
        if (d.mass)
            o["mass"] = *d.mass;
        if (d.inertia)
            o["inertia"] = *d.inertia;
        o["gravity_scale"] = d.gravity_scale;
        o["linear_damping"] = d.linear_damping;
        o["angular_damping"] = d.angular_damping;
        o["fixed_rotation"] = d.fixed_rotation;
        if (d.bullet) // (left out when false, so scenes without bullets write as before)
            o["bullet"] = true;
        o["enable_sleep"] = d.enable_sleep;
        o["awake"] = d.awake;
        o["force"] = vec(d.force);
        o["torque"] = d.torque;
        if (!b.loads.empty()) {
            ojson l = ojson::object();
            if (b.loads.force_x)
                l["force_x"] = time_function_json(*b.loads.force_x);
            if (b.loads.force_y)
                l["force_y"] = time_function_json(*b.loads.force_y);
            if (b.loads.torque)
                l["torque"] = time_function_json(*b.loads.torque);
            o["loads"] = std::move(l);
        }
        ojson shapes = ojson::array();
        // An entry: its geometry's keys, then the keys every shape has.
        const auto add = [&shapes](ojson sj, const ShapeDef& s) {
            sj["material"] = material_json(s.material);
            if (!(s.filter == Filter{})) // (the default filter is left out)
                sj["filter"] = {{"category_bits", s.filter.category_bits},
                                {"mask_bits", s.filter.mask_bits},
                                {"group_index", s.filter.group_index}};
            if (s.is_sensor)
                sj["sensor"] = true;
            shapes.push_back(std::move(sj));
        };
        for (std::size_t i = 0; i < b.shapes.size();) {
            const ShapeDef& s = b.shapes[i];
            const Geometry& g = s.geometry;
            if (g.type != ShapeType::chain_segment) {
                add(geometry_json(g), s);
                ++i;
                continue;
            }
            const ChainRun run = chain_run_at(b.shapes, i);
            if (run.reproduced && run.points.size() <= chain_budget) {
                ojson pts = ojson::array();
                for (const Vec2d p : run.points)
                    pts.push_back(vec(p));
                add({{"type", "chain"}, {"points", std::move(pts)}, {"loop", run.loop}}, s);
                chain_budget -= run.points.size();
            } else {
                for (std::size_t k = i; k < i + run.count; ++k)
                    add(geometry_json(b.shapes[k].geometry), b.shapes[k]);
            }
            i += run.count;
        }
        o["shapes"] = std::move(shapes);
        bodies.push_back(std::move(o));
    }
    j["bodies"] = std::move(bodies);
    if (!scene.joints.empty()) {
        ojson joints = ojson::array();
        for (const SceneJoint& sj : scene.joints) {
            ojson o = ojson::object();
            o["type"] = joint_types[sj.def.index()];
            o["body_a"] = sj.body_a;
            o["body_b"] = sj.body_b;
            SceneJoint::Definition def = sj.def; // the field tables take mutable members
            std::visit(
                [&](auto& d) {
                    all_joint_fields(d, [&](std::string_view key, auto& member, bool) {
                        using T = std::remove_cvref_t<decltype(member)>;
                        if constexpr (std::is_same_v<T, Vec2d>)
                            o[std::string(key)] = vec(member);
                        else if constexpr (std::is_same_v<T, std::optional<double>>) {
                            if (member)
                                o[std::string(key)] = *member;
                        } else if constexpr (std::is_same_v<T, bool>)
                            o[std::string(key)] = member;
                        else if (std::isfinite(member)) // infinite (no bound): the default
                            o[std::string(key)] = member;
                    });
                },
                def);
            joints.push_back(std::move(o));
        }
        j["joints"] = std::move(joints);
    }
    return j.dump(indent);
}

} // namespace tamias2d::io
