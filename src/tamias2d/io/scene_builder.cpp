// The scene builder: the checked creation of a scene's bodies, shapes and joints in a World
// (validate_scene's dry run in a scratch World, build_world's in the caller's), and the loads'
// time functions.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <span>
#include <tuple>
#include <variant>
#include <vector>

#include "scene_read.hpp"
#include "tamias2d/math/sincos.hpp"
#include "tamias2d/validation.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d::io {

using namespace scene_detail;

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

namespace {

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

/// How many shapes from `s` on are chain segments in a row (0 when shapes[s] is not one).
std::size_t chain_run(const std::vector<ShapeDef>& shapes, std::size_t s) {
    std::size_t n = 0;
    while (s + n < shapes.size() && shapes[s + n].geometry.type == ShapeType::chain_segment)
        ++n;
    return n;
}

} // namespace

void validate_scene(const Scene& scene, std::string_view origin_view) {
    Ctx ctx;
    ctx.origin = std::string(origin_view);
    check_as_library(ctx, "/dt", "dt", [&] { validate_time_step(scene.dt); }); // DCX_dt, _range
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

} // namespace tamias2d::io
