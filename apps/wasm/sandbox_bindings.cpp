// The live sandbox's binding (docs/viewer.md, "Live sandbox"): the library's World and scene
// reader, compiled to WebAssembly by scripts/build_wasm.sh, driven from the page through plain
// C functions. One world at a time; bodies are numbered in scene order, dropped ones after.
// Every function that can fail returns -1 (or an empty result) and leaves the reason in
// tamias_error(); the world is then unchanged (the library's strong guarantee).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../cli/view_geometry.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/world.hpp"

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#define TAMIAS_EXPORT extern "C" EMSCRIPTEN_KEEPALIVE
#else
#define TAMIAS_EXPORT extern "C"
#endif

namespace {

using namespace tamias2d;
using nlohmann::json;

struct Sandbox {
    io::Scene scene;
    std::unique_ptr<World> world;
    std::vector<BodyId> ids;   ///< scene bodies, then dropped ones
    std::vector<double> out;   ///< states handed to the page
    JointId grab;              ///< the mouse's target joint, if any
    int steps = 0;             ///< steps taken since the scene was loaded
    std::string text;          ///< the last string returned to the page
    std::string error;         ///< why the last call failed
    double restitution = -1.0; ///< < 0: the scene's own materials
};

Sandbox& sandbox() {
    static Sandbox s;
    return s;
}

/// Runs `f`, turning an exception into -1 and its message into tamias_error().
template <class F> int guarded(F&& f) {
    Sandbox& s = sandbox();
    s.error.clear();
    try {
        return f(s);
    } catch (const std::exception& e) {
        s.error = e.what();
    } catch (...) {
        s.error = "unknown error";
    }
    return -1;
}

using tamias2d::view::point_json;
using tamias2d::view::to_body_frame;

/// A body as the player's drawing code takes it (apps/cli/player/player.js): name, type,
/// mass, inertia, local centre of mass and its shapes' geometry (in the body frame, as
/// `tamias2d view` writes them: view_geometry.hpp).
json body_json(const World& world, BodyId id, const std::vector<ShapeDef>& shapes) {
    json geoms = json::array();
    for (const ShapeDef& shape : shapes)
        geoms.push_back(tamias2d::view::geometry_json(shape.geometry));
    return {{"name", world.name(id)},
            {"type", std::string(to_string(world.type(id)))},
            {"m", world.mass(id)},
            {"I", world.inertia(id)},
            {"lc", point_json(world.local_center(id))},
            {"geoms", std::move(geoms)}};
}

/// The scene's joints, their anchors in each body's frame (as `tamias2d view` records them).
json joints_json(const Sandbox& s) {
    json joints = json::array();
    for (const io::SceneJoint& joint : s.scene.joints) {
        std::size_t a = s.ids.size(), b = s.ids.size();
        for (std::size_t i = 0; i < s.scene.bodies.size(); ++i) {
            if (s.scene.bodies[i].def.name == joint.body_a)
                a = i;
            if (s.scene.bodies[i].def.name == joint.body_b)
                b = i;
        }
        if (a == s.ids.size() || b == s.ids.size())
            continue;
        const World& w = *s.world;
        Vec2d la, lb;
        std::visit(
            [&](const auto& d) {
                using D = std::decay_t<decltype(d)>;
                if constexpr (std::is_same_v<D, DistanceJointDef>) {
                    la = to_body_frame(w, s.ids[a], d.anchor_a);
                    lb = to_body_frame(w, s.ids[b], d.anchor_b);
                } else if constexpr (std::is_same_v<D, MotorJointDef>) {
                    la = d.linear_offset;
                } else if constexpr (std::is_same_v<D, FilterJointDef>) {
                    // no anchor: drawn between the bodies' origins
                } else {
                    la = to_body_frame(w, s.ids[a], d.anchor);
                    lb = to_body_frame(w, s.ids[b], d.anchor);
                }
            },
            joint.def);
        joints.push_back({{"a", a}, {"b", b}, {"la", point_json(la)}, {"lb", point_json(lb)}});
    }
    return joints;
}

BodyId body(const Sandbox& s, int index) {
    if (!s.world || index < 0 || static_cast<std::size_t>(index) >= s.ids.size())
        throw std::runtime_error("no body " + std::to_string(index));
    return s.ids[static_cast<std::size_t>(index)];
}

Material drop_material(const Sandbox& s) {
    Material m{.density = 1.0, .restitution = 0.0, .friction = 0.6};
    if (s.restitution >= 0.0)
        m.restitution = s.restitution;
    return m;
}

int add_body(Sandbox& s, double x, double y, const ShapeDef& shape, const char* kind) {
    if (!s.world)
        throw std::runtime_error("no scene is loaded");
    BodyDef def;
    def.position = {x, y};
    def.name = std::string(kind) + " " + std::to_string(s.ids.size());
    World& w = *s.world;
    const BodyId id = w.create_body(def);
    try {
        w.create_shape(id, shape);
    } catch (...) {
        w.destroy_body(id);
        throw;
    }
    s.ids.push_back(id);
    s.text = body_json(w, id, {shape}).dump();
    return static_cast<int>(s.ids.size()) - 1;
}

} // namespace

/// Why the last call failed ("" when it did not).
TAMIAS_EXPORT const char* tamias_error() {
    return sandbox().error.c_str();
}

/// The string the last call that makes one made (tamias_load, tamias_add_*).
TAMIAS_EXPORT const char* tamias_text() {
    return sandbox().text.c_str();
}

/// Restitution for every shape of the scenes loaded next and of dropped bodies; < 0: the
/// scene's own materials (dropped bodies: 0).
TAMIAS_EXPORT void tamias_set_restitution(double restitution) {
    sandbox().restitution = restitution > 1.0 ? 1.0 : restitution;
}

/// Loads a scene (JSON text, docs/scene-format.md) in place of the current one. On success
/// tamias_text() is the scene for the page: description, dt, steps, gravity and the bodies
/// and joints as the player draws them; returns the number of bodies.
TAMIAS_EXPORT int tamias_load(const char* scene_json, const char* origin) {
    return guarded([&](Sandbox& s) {
        io::Scene scene = io::parse_scene(scene_json, origin);
        if (s.restitution >= 0.0)
            for (io::SceneBody& b : scene.bodies)
                for (ShapeDef& shape : b.shapes)
                    shape.material.restitution = s.restitution;
        auto world = std::make_unique<World>(scene.world);
        std::vector<BodyId> ids = io::build_world(scene, *world);
        s.scene = std::move(scene);
        s.world = std::move(world);
        s.ids = std::move(ids);
        s.grab = {};
        s.steps = 0;
        json bodies = json::array();
        for (std::size_t i = 0; i < s.ids.size(); ++i)
            bodies.push_back(body_json(*s.world, s.ids[i], s.scene.bodies[i].shapes));
        s.text = json{{"description", s.scene.description},
                      {"dt", s.scene.dt},
                      {"steps", s.scene.steps},
                      {"gravity", point_json(s.scene.world.gravity)},
                      {"bodies", std::move(bodies)},
                      {"joints", joints_json(s)}}
                     .dump(-1, ' ', false, json::error_handler_t::replace);
        return static_cast<int>(s.ids.size());
    });
}

/// Takes n steps of the scene's dt; returns the steps taken since the load.
TAMIAS_EXPORT int tamias_step(int n) {
    return guarded([&](Sandbox& s) {
        if (!s.world)
            throw std::runtime_error("no scene is loaded");
        for (int i = 0; i < n; ++i) {
            s.world->step(s.scene.dt);
            ++s.steps;
        }
        return s.steps;
    });
}

TAMIAS_EXPORT int tamias_body_count() {
    return static_cast<int>(sandbox().ids.size());
}

TAMIAS_EXPORT double tamias_time() {
    return sandbox().world ? sandbox().world->time() : 0.0;
}

/// Every body's state, 6 doubles a body: x, y (centre of mass, m), phi (rad, [0, 2 pi)),
/// vx, vy (m/s), omega (rad/s), exactly World::state's doubles. The pointer is valid until
/// the next call.
TAMIAS_EXPORT const double* tamias_states() {
    Sandbox& s = sandbox();
    s.out.resize(6 * s.ids.size());
    for (std::size_t i = 0; i < s.ids.size(); ++i) {
        const BodyState st = s.world->state(s.ids[i]);
        double* o = &s.out[6 * i];
        o[0] = st.position.x, o[1] = st.position.y, o[2] = st.orientation;
        o[3] = st.velocity.x, o[4] = st.velocity.y, o[5] = st.angular_velocity;
    }
    return s.out.data();
}

/// World::state_hash() as 16 hexadecimal digits ("" without a scene).
TAMIAS_EXPORT const char* tamias_state_hash() {
    Sandbox& s = sandbox();
    char buf[17] = "";
    if (s.world)
        std::snprintf(buf, sizeof buf, "%016llx",
                      static_cast<unsigned long long>(s.world->state_hash()));
    s.text = buf;
    return s.text.c_str();
}

TAMIAS_EXPORT void tamias_set_gravity(double gx, double gy) {
    guarded([&](Sandbox& s) {
        if (s.world)
            s.world->set_gravity({gx, gy});
        return 0;
    });
}

/// Drops a dynamic box (w x h m) or circle (radius r m) of density 1 at (x, y); returns its
/// index, and tamias_text() is the body as the player draws it.
TAMIAS_EXPORT int tamias_add_box(double x, double y, double w, double h) {
    return guarded(
        [&](Sandbox& s) { return add_body(s, x, y, box_shape(w, h, drop_material(s)), "box"); });
}

TAMIAS_EXPORT int tamias_add_circle(double x, double y, double r) {
    return guarded(
        [&](Sandbox& s) { return add_body(s, x, y, circle_shape(r, drop_material(s)), "circle"); });
}

/// Grabs a dynamic body at the world point (x, y) with a target joint (DD21) whose largest
/// force is `weights` times the body's weight under the current gravity (at least 1 N per kg).
TAMIAS_EXPORT int tamias_grab(int index, double x, double y, double weights) {
    return guarded([&](Sandbox& s) {
        World& w = *s.world;
        if (s.grab.index != null_index && w.is_valid(s.grab))
            w.destroy_joint(s.grab);
        s.grab = {};
        const BodyId id = body(s, index);
        const Vec2d g = w.gravity();
        TargetJointDef def;
        def.body = id;
        def.target = {x, y};
        def.max_force = weights * w.mass(id) * std::max(1.0, std::hypot(g.x, g.y));
        s.grab = w.create_joint(def);
        return 0;
    });
}

TAMIAS_EXPORT int tamias_drag(double x, double y) {
    return guarded([&](Sandbox& s) {
        if (s.grab.index != null_index && s.world->is_valid(s.grab))
            s.world->set_joint_target(s.grab, {x, y});
        return 0;
    });
}

TAMIAS_EXPORT void tamias_release() {
    guarded([&](Sandbox& s) {
        if (s.world && s.grab.index != null_index && s.world->is_valid(s.grab))
            s.world->destroy_joint(s.grab);
        s.grab = {};
        return 0;
    });
}
