// libFuzzer target: the input bytes are a scene file. It is loaded as `tamias2d run` loads one
// (io::parse_scene, then io::build_world into a World of the scene's settings) and, when it loads
// and is small enough to step quickly, run for a few steps of its dt with two ray casts after.
//
// Oracle: the library's stated promises (include/tamias2d/io/scene.hpp, docs/user-guide.md,
// "Errors"): no crash and no sanitizer report; a rejected scene is an io::SceneError with a
// message and nothing else; what parse_scene accepts builds; its written form (scene_to_json)
// loads again, builds the same world and steps to the same state_hash after every step; a step that
// refuses is a ValidationError and leaves state_hash() unchanged; after every accepted step every
// body state, energy and momentum is finite. No finding is excused (docs/verification.md, "Findings
// (fixed)").
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "fuzz/libfuzzer/promise.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;
using namespace tamias2d::fuzz;

namespace {

// Bounds that keep one input fast: larger scenes (the large pyramid, generators asking for
// thousands of bodies) are parsed and validated only.
constexpr std::size_t max_bodies_stepped = 200;
constexpr int max_steps = 6;

io::Scene load(std::string_view text) {
    try {
        return io::parse_scene(text, "fuzz");
    } catch (const io::SceneError& e) {
        if (std::string(e.what()).empty() || e.detail.empty())
            broken_promise("SceneError with an empty message");
        throw;
    } catch (const std::exception& e) {
        broken_promise(std::string("parse_scene refused with a non-SceneError: ") + e.what());
    }
}

/// The world of the scene's written form, which must be the same world.
void build_twin(const io::Scene& scene, const World& world, std::optional<World>& twin) {
    try {
        const io::Scene again = io::parse_scene(io::scene_to_json(scene), "fuzz (written)");
        twin.emplace(again.world);
        io::build_world(again, *twin);
        if (twin->state_hash() != world.state_hash())
            broken_promise("the written form builds a different world");
    } catch (const std::exception& e) {
        broken_promise(std::string("the written form does not load: ") + e.what());
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    io::Scene scene;
    try {
        scene = load(text);
    } catch (const io::SceneError&) {
        return 0; // rejected, with a message
    }
    if (scene.bodies.size() > max_bodies_stepped)
        return 0;

    World world(scene.world);
    try {
        (void)io::build_world(scene, world);
    } catch (const std::exception& e) {
        broken_promise(std::string("a scene parse_scene accepted failed to build: ") + e.what());
    }
    std::optional<World> twin; // steps alongside, to the same hash after every step
    build_twin(scene, world, twin);

    for (int s = 0; s < max_steps; ++s) {
        const std::uint64_t before = world.state_hash();
        const std::vector<double> states_before = body_states(world);
        try {
            world.step(scene.dt);
        } catch (const SolverDivergence& e) {
            // Its own promise (errors.hpp): bodies and clock as they were, contacts updated.
            if (body_states(world) != states_before)
                broken_promise(std::string("a diverged step changed the bodies: ") + e.what());
            return 0;
        } catch (const ValidationError& e) {
            // Refusing a state beyond the supported range is allowed; changing the world is not.
            if (e.field.empty() || std::string(e.what()).empty())
                broken_promise("ValidationError with an empty field or message");
            if (world.state_hash() != before)
                broken_promise(std::string("a refused step changed the world: ") + e.what());
            return 0;
        } catch (const std::exception& e) {
            broken_promise(std::string("step refused with a non-ValidationError: ") + e.what());
        }
        if (const std::string bad = non_finite_state(world); !bad.empty())
            broken_promise("non-finite state after step " + std::to_string(s + 1) + ": " + bad);
        try {
            twin->step(scene.dt);
        } catch (const std::exception& e) {
            broken_promise(std::string("the written form refused a step: ") + e.what());
        }
        if (twin->state_hash() != world.state_hash())
            broken_promise("the written form simulates differently from step " +
                           std::to_string(s + 1));
    }
    for (const Vec2d dir : {Vec2d{0.0, -100.0}, Vec2d{100.0, 1.0}})
        if (const std::string bad = bad_ray_cast(world, {-50.0, 50.0}, dir); !bad.empty())
            broken_promise(bad);
    return 0;
}
