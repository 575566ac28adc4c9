// The bytes of a snapshot: a game keeps snapshots as save files and sends them over the
// network, so the bytes a world writes are part of the format, not only what it reads back.
// Every example scene as built (before its first step), and after at most 120 steps: as
// written, with manifold reuse off (the contacts then keep no reuse basis) and thinned (every
// third body destroyed after the steps, so that free slots of bodies, shapes, joints and
// contacts are written), must write the payload recorded in golden_snapshots.txt: its length
// and its FNV-1a hash. The header is left out: it names the library's version.
//
// Oracle: the committed record, written by another build: a regression oracle, as the golden
// state hashes are. It fixes what the state hash leaves out (a contact's reuse basis with reuse
// off, which edge may bounce), and a pass proves the same bytes across builds. No SRS label.
//
// Regenerate after an intended change of the format or of the physics (and say why):
//   TAMIAS_GOLDEN_UPDATE=1 build/tests/snapshot/snapshot_tests --run_test=snapshot_bytes
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "snapshot_worlds.hpp"

namespace utf = boost::unit_test;
using namespace snapshot_test;

namespace {

constexpr std::size_t header_size = 32; // world_snapshot.cpp's layout

/// The steps before the snapshot: at most 120 (every scene's contacts and joints are at work by
/// then), and 5 for the large pyramid, whose boxes all touch from the first steps: a few seconds
/// under ASan.
int short_steps(const std::string& scene, int scene_steps) {
    return std::min(scene_steps, scene == "large_pyramid" ? 5 : 120);
}

/// FNV-1a, 64 bits: written here, independent of the library's own checksum (XXH64).
std::uint64_t fnv1a(const std::vector<std::byte>& bytes, std::size_t from) {
    std::uint64_t h = 0xcbf29ce484222325u;
    for (std::size_t k = from; k < bytes.size(); ++k)
        h = (h ^ std::uint64_t(bytes[k])) * 0x100000001b3u;
    return h;
}

using Key = std::pair<std::string, std::string>;      // scene and mode (below)
using Record = std::pair<std::size_t, std::uint64_t>; // payload bytes, FNV-1a
using Records = std::map<Key, Record>;

Records written_now() {
    Records out;
    for (const fs::path& path : example_scenes()) {
        const io::Scene scene = io::load_scene(path);
        for (const std::string mode : {"built", "reuse", "no_reuse", "thinned"}) {
            WorldDef def = scene.world;
            if (mode == "no_reuse")
                def.manifold_reuse_distance = 0.0;
            World world(def);
            io::build_world(scene, world);
            const int last = mode == "built" ? 0 : short_steps(path.stem().string(), scene.steps);
            for (int s = 0; s < last; ++s)
                world.step(scene.dt);
            if (mode == "thinned") {
                const std::vector<BodyId> bodies = world.bodies();
                for (std::size_t k = 0; k < bodies.size(); k += 3)
                    world.destroy_body(bodies[k]);
            }
            const std::vector<std::byte> bytes = world.snapshot();
            BOOST_TEST_REQUIRE(bytes.size() > header_size);
            out[{path.stem().string(), mode}] = {bytes.size() - header_size,
                                                 fnv1a(bytes, header_size)};
        }
    }
    return out;
}

std::string hex(std::uint64_t h) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

Records read_golden(const fs::path& file) {
    std::ifstream in(file);
    BOOST_TEST_REQUIRE(in.good(), "cannot read " << file);
    Records golden;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (line.empty() || line[0] == '#')
            continue;
        std::istringstream fields(line);
        std::string scene, mode, hash;
        std::size_t size = 0;
        fields >> scene >> mode >> size >> hash;
        BOOST_TEST_REQUIRE((!fields.fail() && hash.size() == 16),
                           file << ":" << number << ": expected `scene mode bytes hash16`");
        golden[{scene, mode}] = {size, std::stoull(hash, nullptr, 16)};
    }
    return golden;
}

void write_golden(const fs::path& file, const Records& records) {
    std::ofstream out(file);
    out << "# The payload (the bytes after the 32-byte header) of World::snapshot() of each\n"
           "# example scene as built, before its first step (built), and after at most 120\n"
           "# steps (the large pyramid: 5) as written (reuse), with manifold reuse off\n"
           "# (no_reuse) and with every third body destroyed after the steps (thinned): its\n"
           "# length and FNV-1a 64 hash. The oracle of\n"
           "# tests/snapshot/test_snapshot_bytes.cpp. Regenerate:\n"
           "#   TAMIAS_GOLDEN_UPDATE=1 build/tests/snapshot/snapshot_tests "
           "--run_test=snapshot_bytes\n"
           "# scene mode bytes hash\n";
    for (const auto& [key, record] : records)
        out << key.first << ' ' << key.second << ' ' << record.first << ' ' << hex(record.second)
            << '\n';
    BOOST_TEST_REQUIRE(out.good(), "cannot write " << file);
}

bool updating() {
    const char* u = std::getenv("TAMIAS_GOLDEN_UPDATE");
    return u && *u && std::string(u) != "0";
}

} // namespace

BOOST_AUTO_TEST_SUITE(snapshot_bytes)

BOOST_AUTO_TEST_CASE(every_example_scene_writes_the_recorded_bytes, *utf::label("determinism")) {
    const Records now = written_now();
    const fs::path file = TAMIAS_GOLDEN_SNAPSHOTS;
    if (updating()) {
        write_golden(file, now);
        BOOST_TEST_MESSAGE("wrote " << now.size() << " snapshot records to " << file);
        return;
    }
    const Records golden = read_golden(file);
    for (const auto& [key, record] : now) {
        const auto g = golden.find(key);
        if (g == golden.end())
            BOOST_ERROR(key.first << " " << key.second << ": no record in " << file
                                  << " (a new scene: regenerate the file)");
        else
            BOOST_TEST((g->second == record), key.first << " " << key.second << ": " << record.first
                                                        << " bytes, " << hex(record.second)
                                                        << "; recorded " << g->second.first
                                                        << " bytes, " << hex(g->second.second));
    }
    for (const auto& [key, record] : golden)
        BOOST_TEST(now.count(key) == 1u,
                   key.first << " " << key.second << ": recorded, but no such scene now");
}

BOOST_AUTO_TEST_SUITE_END()
