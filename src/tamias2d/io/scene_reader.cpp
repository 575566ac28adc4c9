// The scene reader (docs/scene-format.md): the document's keys read by the field tables
// (scene_fields.hpp), bodies, joints, generators and the document itself; then the whole
// scene validated through a scratch World (validate_scene) before it is returned.
#include <array>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <istream>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "scene_fields.hpp"
#include "scene_read.hpp"
#include "tamias2d/io/scene_generators.hpp"
#include "tamias2d/validation.hpp"

namespace tamias2d::io {
namespace scene_detail {
namespace {

BodyType parse_body_type(const Ctx& ctx, const ojson& v, const std::string& ptr);

/// A value read into a member of a definition, by the member's type.
template <class T>
void read_field(const Ctx& ctx, const ojson& v, const std::string& at, const std::string& field,
                T& member) {
    if constexpr (std::is_same_v<T, std::string>)
        member = as_string(ctx, v, at, field);
    else if constexpr (std::is_same_v<T, BodyType>)
        member = parse_body_type(ctx, v, at);
    else if constexpr (std::is_same_v<T, Vec2d>)
        member = as_vec2(ctx, v, at, field);
    else if constexpr (std::is_same_v<T, bool>)
        member = as_bool(ctx, v, at, field);
    else if constexpr (std::is_same_v<T, int>)
        member = static_cast<int>(as_integer(ctx, v, at, field, INT_MIN, INT_MAX));
    else if constexpr (std::is_same_v<T, std::optional<ConstraintTuning>>) {
        // {"hertz": ..., "damping_ratio": ...}, both required (checked by the library).
        require_object(ctx, v, at, field, "an object {\"hertz\", \"damping_ratio\"}");
        check_keys(ctx, v, at, {"hertz", "damping_ratio"}, field);
        member = ConstraintTuning{req_number(ctx, v, at, "hertz", field),
                                  req_number(ctx, v, at, "damping_ratio", field)};
    } else
        member = as_number(ctx, v, at, field); // double, std::optional<double>
}

void attach_loads(SceneBody& b) {
    if (b.loads.empty())
        return;
    b.def.load = [loads = b.loads](double t) { return loads(t); };
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
                read_field(ctx, *value, child(ptr, key), std::string(key), member);
            });
        },
        j.def);
    j.body_a = as_string(ctx, require_key(ctx, v, ptr, "body_a", "a joint"), child(ptr, "body_a"),
                         "body_a");
    j.body_b = as_string(ctx, require_key(ctx, v, ptr, "body_b", "a joint"), child(ptr, "body_b"),
                         "body_b");
    return j;
}

SceneBody parse_body(Ctx& ctx, const ojson& v, const std::string& ptr) {
    SceneBody b;
    b.source = ptr;
    BodyDef& d = b.def;
    std::vector<std::string_view> keys;
    body_fields(d, [&](std::string_view key, auto&, FieldRule) { keys.push_back(key); });
    keys.insert(keys.end(), {"loads", "shapes"});
    check_keys_in(ctx, v, ptr, keys, "a body");
    body_fields(d, [&](std::string_view key, auto& member, FieldRule rule) {
        const ojson* value = find(v, key);
        if (!value)
            return;
        const std::string field(key);
        read_field(ctx, *value, child(ptr, key), field, member);
        using T = std::remove_cvref_t<decltype(member)>;
        if constexpr (std::is_same_v<T, double>) {
            if (rule.check)
                check_as_library(ctx, ptr, "", [&] { rule.check(field, member); });
        } else if constexpr (std::is_same_v<T, std::optional<double>>) {
            if (rule.check)
                check_as_library(ctx, ptr, "", [&] { rule.check(field, *member); });
        }
    });
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
    check_as_library(ctx, ptr, "dt", [&] { validate_time_step(dt); }); // DCX_dt, DCX_range
    return dt;
}

WorldDef parse_world(const Ctx& ctx, const ojson& v, const std::string& ptr) {
    require_object(ctx, v, ptr, "world", "an object of world settings");
    WorldDef w;
    std::vector<std::string_view> keys;
    world_fields(w, [&](std::string_view key, auto&) { keys.push_back(key); });
    check_keys_in(ctx, v, ptr, keys, "world settings");
    world_fields(w, [&](std::string_view key, auto& member) {
        if (const ojson* value = find(v, key))
            read_field(ctx, *value, child(ptr, key), std::string(key), member);
    });
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
} // namespace scene_detail

using namespace scene_detail;

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

} // namespace tamias2d::io
