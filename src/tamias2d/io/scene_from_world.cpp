// io::scene_from_world: World::definitions as a Scene.
#include "tamias2d/io/scene_from_world.hpp"

#include <map>
#include <string>
#include <type_traits>
#include <variant>

#include "tamias2d/world.hpp"

namespace tamias2d::io {

Scene scene_from_world(const World& world) {
    const WorldDefinitions defs = world.definitions();
    Scene scene;
    scene.description =
        "written by io::scene_from_world at t = " + std::to_string(world.time()) + " s";
    scene.world = defs.world;
    // Names are unique in a scene file, and a joint names its bodies: a body whose name another
    // body has too, or that a joint names while it has none, is named "body<index>".
    std::map<std::string, int> uses;
    for (const BodyDefinition& b : defs.bodies)
        ++uses[b.def.name];
    std::map<std::uint32_t, std::string> name_of; // body index -> its name in the scene
    const auto fresh_name = [&](std::uint32_t index) {
        std::string fresh = "body" + std::to_string(index);
        while (uses.count(fresh))
            fresh += "_";
        uses[fresh] = 1;
        return fresh;
    };
    for (const BodyDefinition& b : defs.bodies) {
        const std::string& name = b.def.name;
        name_of[b.id.index] = !name.empty() && uses[name] > 1 ? fresh_name(b.id.index) : name;
    }
    const auto named = [&](BodyId id) -> const std::string& {
        std::string& name = name_of[id.index];
        if (name.empty())
            name = fresh_name(id.index);
        return name;
    };
    for (const JointDefinition& j : defs.joints) {
        std::visit(
            [&](const auto& d) {
                using D = std::decay_t<decltype(d)>;
                if constexpr (!std::is_same_v<D, TargetJointDef>) {
                    SceneJoint sj{d, named(d.body_a), named(d.body_b), ""};
                    std::visit(
                        [](auto& def) {
                            def.body_a = {};
                            def.body_b = {};
                        },
                        sj.def);
                    scene.joints.push_back(std::move(sj));
                }
            },
            j);
    }
    for (const BodyDefinition& b : defs.bodies) {
        SceneBody sb;
        sb.def = b.def;
        sb.def.name = name_of[b.id.index];
        sb.shapes = b.shapes;
        scene.bodies.push_back(std::move(sb));
    }
    return scene;
}

} // namespace tamias2d::io
