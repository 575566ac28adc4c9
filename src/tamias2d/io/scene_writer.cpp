// The scene writer: a Scene as canonical JSON (scene.hpp, scene_to_json), its keys in the
// order of the field tables the reader walks (scene_fields.hpp).
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "json_dom.hpp"
#include "scene_fields.hpp"
#include "tamias2d/io/chain_runs.hpp"

namespace tamias2d::io {

using scene_detail::ojson;

namespace {

ojson vec(Vec2d v) {
    return ojson::array({v.x, v.y});
}

ojson material_json(const Material& m) {
    ojson j = ojson::object();
    j["density"] = m.density;
    j["restitution"] = m.restitution;
    j["friction"] = m.friction;
    if (m.user_material_id != 0) // (DD42; scenes without one are written as before)
        j["user_material_id"] = m.user_material_id;
    if (m.rolling_resistance != 0.0) // (DD46, DD47: the same)
        j["rolling_resistance"] = m.rolling_resistance;
    if (m.tangent_speed != 0.0)
        j["tangent_speed"] = m.tangent_speed;
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

/// A member of a definition as JSON, by its type.
template <class T> ojson field_json(const T& member) {
    if constexpr (std::is_same_v<T, Vec2d>)
        return vec(member);
    else if constexpr (std::is_same_v<T, BodyType>)
        return std::string(to_string(member));
    else
        return member;
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

/// A body's shapes: each shape an entry of its geometry's keys, then the keys every shape has;
/// a run of chain segments that a chain makes again as one "chain" while `chain_budget` (the
/// points parse_scene allows) lasts, else segment by segment.
ojson shapes_json(const std::vector<ShapeDef>& shapes, std::size_t& chain_budget) {
    ojson out = ojson::array();
    const auto add = [&out](ojson sj, const ShapeDef& s) {
        sj["material"] = material_json(s.material);
        if (!(s.filter == Filter{})) // (the default filter is left out)
            sj["filter"] = {{"category_bits", s.filter.category_bits},
                            {"mask_bits", s.filter.mask_bits},
                            {"group_index", s.filter.group_index}};
        if (s.is_sensor)
            sj["sensor"] = true;
        if (!s.enable_pre_solve) // (scenes whose shapes all allow it are written as before)
            sj["enable_pre_solve"] = false;
        out.push_back(std::move(sj));
    };
    for (std::size_t i = 0; i < shapes.size();) {
        const ShapeDef& s = shapes[i];
        const Geometry& g = s.geometry;
        if (g.type != ShapeType::chain_segment) {
            add(geometry_json(g), s);
            ++i;
            continue;
        }
        const ChainRun run = chain_run_at(shapes, i);
        if (run.reproduced && run.points.size() <= chain_budget) {
            ojson pts = ojson::array();
            for (const Vec2d p : run.points)
                pts.push_back(vec(p));
            add({{"type", "chain"}, {"points", std::move(pts)}, {"loop", run.loop}}, s);
            chain_budget -= run.points.size();
        } else {
            for (std::size_t k = i; k < i + run.count; ++k)
                add(geometry_json(shapes[k].geometry), shapes[k]);
        }
        i += run.count;
    }
    return out;
}

/// A body entry: its definition's keys (the body field table), its loads and its shapes.
ojson body_json(const SceneBody& b, std::size_t& chain_budget) {
    // The default of each flag the table leaves out when it has it (BodyDef{}'s), by key.
    std::vector<std::pair<std::string_view, bool>> default_flags;
    BodyDef defaults;
    scene_detail::body_fields(
        defaults, [&](std::string_view key, const auto& member, scene_detail::FieldRule) {
            if constexpr (std::is_same_v<std::remove_cvref_t<decltype(member)>, bool>)
                default_flags.emplace_back(key, member);
        });
    const auto default_flag = [&](std::string_view key) {
        for (const auto& [k, value] : default_flags)
            if (k == key)
                return value;
        return false;
    };
    ojson o = ojson::object();
    scene_detail::body_fields(
        b.def, [&](std::string_view key, const auto& member, scene_detail::FieldRule rule) {
            using T = std::remove_cvref_t<decltype(member)>;
            if constexpr (std::is_same_v<T, std::optional<double>>) {
                if (member)
                    o[std::string(key)] = *member;
            } else if constexpr (std::is_same_v<T, std::string>) {
                if (!(rule.omit_default && member.empty()))
                    o[std::string(key)] = member;
            } else if constexpr (std::is_same_v<T, bool>) {
                if (!(rule.omit_default && member == default_flag(key)))
                    o[std::string(key)] = member;
            } else {
                o[std::string(key)] = field_json(member);
            }
        });
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
    o["shapes"] = shapes_json(b.shapes, chain_budget);
    return o;
}

/// A joint entry: its type, its bodies' names and its kind's keys (the joint field tables).
ojson joint_json(const SceneJoint& sj) {
    ojson o = ojson::object();
    o["type"] = scene_detail::joint_types[sj.def.index()];
    o["body_a"] = sj.body_a;
    o["body_b"] = sj.body_b;
    SceneJoint::Definition def = sj.def; // the field tables take mutable members
    std::visit(
        [&](auto& d) {
            scene_detail::all_joint_fields(d, [&](std::string_view key, auto& member, bool) {
                using T = std::remove_cvref_t<decltype(member)>;
                if constexpr (std::is_same_v<T, Vec2d>)
                    o[std::string(key)] = vec(member);
                else if constexpr (std::is_same_v<T, std::optional<double>>) {
                    if (member)
                        o[std::string(key)] = *member;
                } else if constexpr (std::is_same_v<T, std::optional<ConstraintTuning>>) {
                    if (member)
                        o[std::string(key)] = {{"hertz", member->hertz},
                                               {"damping_ratio", member->damping_ratio}};
                } else if constexpr (std::is_same_v<T, bool>)
                    o[std::string(key)] = member;
                else if (std::isfinite(member)) // infinite (no bound): the default
                    o[std::string(key)] = member;
            });
        },
        def);
    return o;
}

} // namespace

std::string scene_to_json(const Scene& scene, int indent) {
    ojson j = ojson::object();
    j["version"] = 1;
    if (!scene.description.empty())
        j["description"] = scene.description;
    ojson world = ojson::object();
    scene_detail::world_fields(scene.world, [&world](std::string_view key, const auto& member) {
        world[std::string(key)] = field_json(member);
    });
    j["world"] = std::move(world);
    j["dt"] = scene.dt;
    j["steps"] = scene.steps;
    j["output_every"] = scene.output_every;
    if (!scene.materials.empty()) {
        ojson mats = ojson::object();
        for (const auto& [name, m] : scene.materials)
            scene_detail::append_member(mats, name, material_json(m)); // a map's keys differ
        j["materials"] = std::move(mats);
    }
    ojson bodies = ojson::array();
    // Chains beyond the limit parse_scene sets are written segment by segment.
    std::size_t chain_budget = max_chain_points;
    for (const SceneBody& b : scene.bodies)
        bodies.push_back(body_json(b, chain_budget));
    j["bodies"] = std::move(bodies);
    if (!scene.joints.empty()) {
        ojson joints = ojson::array();
        for (const SceneJoint& sj : scene.joints)
            joints.push_back(joint_json(sj));
        j["joints"] = std::move(joints);
    }
    return j.dump(indent);
}

} // namespace tamias2d::io
