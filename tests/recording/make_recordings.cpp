// Writes the recordings the determinism tests replay on every platform
// (tests/determinism/recordings/): example scenes recorded for 55 steps with calls made mid-run
// (test_recordings.cpp also flips a bit of the impulse given before step 10, which every replay
// must then find at that step).
//
//   make_test_recordings <scenes directory> <output directory>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "tamias2d/io/scene.hpp"
#include "tamias2d/recorder.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;
namespace fs = std::filesystem;

namespace {

/// The step before which the impulse is applied, which the perturbed recording departs at.
constexpr int kick_step = 10;

/// The scene recorded for `steps` steps: an impulse on its last dynamic body before step 10, a
/// gravity change before 20, a new body before 30, a joint's motor speed (if a joint of the
/// scene has a motor) before 40 and an explosion before 50.
std::vector<std::byte> record(const fs::path& scene_file, int steps) {
    const io::Scene scene = io::load_scene(scene_file);
    World world(scene.world);
    const std::vector<BodyId> ids = io::build_world(scene, world);
    Recorder rec(world);
    BodyId kicked{};
    for (const BodyId id : ids)
        if (world.type(id) == BodyType::dynamic)
            kicked = id;
    for (int s = 1; s <= steps; ++s) {
        if (s == kick_step)
            rec.apply_impulse(kicked, {0.4, 0.8}, world.position(kicked));
        if (s == 20)
            rec.set_gravity({0.5, -9.5});
        if (s == 30) {
            BodyDef d;
            d.position = {0.0, 12.0};
            d.name = "dropped";
            rec.create_shape(rec.create_body(d), circle_shape(0.25));
        }
        if (s == 40)
            for (const BodyId id : ids)
                for (const JointId j : world.joints(id))
                    if (world.joint_kind(j) == JointKind::revolute ||
                        world.joint_kind(j) == JointKind::wheel) {
                        rec.set_joint_motor_speed(j, -2.0);
                        goto done;
                    }
    done:
        if (s == 50)
            rec.explode(ExplosionDef{.position = world.position(kicked),
                                     .radius = 2.0,
                                     .falloff = 1.0,
                                     .impulse_per_length = 0.5});
        rec.step(scene.dt);
    }
    return rec.bytes();
}

void write(const fs::path& file, const std::vector<std::byte>& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!out)
        throw std::runtime_error("cannot write " + file.string());
    std::cout << file.string() << ": " << bytes.size() << " bytes\n";
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: make_test_recordings <scenes directory> <output directory>\n";
        return 2;
    }
    const fs::path scenes = argv[1];
    const fs::path out = argv[2];
    fs::create_directories(out);
    for (const char* name : {"car", "machines", "ragdoll"})
        write(out / (std::string(name) + ".t2drec"),
              record(scenes / (name + std::string(".json")), 55));
    return 0;
}
