// Determinism across builds: every example scene, loaded and stepped, must reach the
// World::state_hash() values committed in golden_hashes.txt, at the intermediate checkpoints
// and at its last step, on one worker (the scenes' own setting) and on four (the World's pool of
// threads; where the platform has no threads, WebAssembly without them, a task system that runs
// the pieces one after another on the calling thread). The same scenes solved in two contact
// regions (WorldDef::contact_regions; their joints in runs too where a scene has 256 or more)
// have records of their own, `<scene>:regions2`: the regions' cut and order are part of the
// bits.
//
// Oracle: the committed golden value, produced by another build (the file does not change
// with the build: Release -O3, the ASan/UBSan build at -O1 and the portable-lanes build all
// compare against the same file), so a pass proves the same bits across optimisation levels
// and the vector and portable packs, not only run-to-run repeatability.
//
// Regenerate after an intended change of the physics (and say why in the commit):
//   TAMIAS_GOLDEN_UPDATE=1 build/tests/determinism/determinism_tests
// which rewrites tests/determinism/golden_hashes.txt from this build.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tamias2d/io/scene.hpp"
#include "tamias2d/task_system.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
namespace fs = std::filesystem;
using namespace tamias2d;

namespace {

// The two largest scenes are cut short so that the ASan build stays within seconds: the
// large pyramid's 5050 boxes are all in contact from the first steps, and rain's first rows
// reach the container floor before step 100.
int steps_for(const std::string& scene, int scene_steps) {
    if (scene == "large_pyramid")
        return std::min(scene_steps, 30);
    if (scene == "rain")
        return std::min(scene_steps, 100);
    return scene_steps;
}

/// The checkpoints: steps 1 and 10 (a first difference shows early), every 100th, the last.
bool is_checkpoint(int step, int last) {
    return step == 1 || step == 10 || step % 100 == 0 || step == last;
}

using Key = std::pair<std::string, int>; // scene, step
using Hashes = std::map<Key, std::uint64_t>;

std::vector<fs::path> example_scenes() {
    std::vector<fs::path> scenes;
    for (const auto& e : fs::directory_iterator(TAMIAS_EXAMPLE_SCENES))
        if (e.path().extension() == ".json")
            scenes.push_back(e.path());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
/// No threads: each loop's pieces run at once, in order, on the calling thread (a task system
/// may run them so, task_system.hpp).
void* run_now(TaskCallback task, int items, void* task_context, void*) {
    task(0, items, 0, task_context);
    return nullptr;
}
void nothing_to_wait_for(void*, void*) {}
#endif

/// The scenes stepped with `workers` workers (0: each scene's own setting), in `regions`
/// contact regions (0: the scene's own setting; else the records' names say how many).
Hashes run_scenes(int workers, int regions = 0) {
    Hashes out;
    for (const fs::path& path : example_scenes()) {
        const std::string stem = path.stem().string();
        const std::string name = regions > 0 ? stem + ":regions" + std::to_string(regions) : stem;
        const io::Scene scene = io::load_scene(path);
        WorldDef def = scene.world;
        if (regions > 0)
            def.contact_regions = regions;
        if (workers > 0) {
            def.workers = workers;
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
            def.task_system = {run_now, nothing_to_wait_for, nullptr};
#endif
        }
        World world(def);
        io::build_world(scene, world);
        const int last = steps_for(stem, scene.steps);
        for (int s = 1; s <= last; ++s) {
            world.step(scene.dt);
            if (is_checkpoint(s, last))
                out[{name, s}] = world.state_hash();
        }
    }
    return out;
}

std::string hex(std::uint64_t h) {
    char buf[24];
    std::snprintf(buf, sizeof buf, "%016" PRIx64, h);
    return buf;
}

Hashes read_golden(const fs::path& file) {
    Hashes golden;
    std::ifstream in(file);
    BOOST_TEST_REQUIRE(in.good(), "cannot read " << file);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (line.empty() || line[0] == '#')
            continue;
        std::istringstream fields(line);
        std::string scene, hash;
        int step = 0;
        fields >> scene >> step >> hash;
        BOOST_TEST_REQUIRE((!fields.fail() && hash.size() == 16),
                           file << ":" << number << ": expected `scene step hash16`");
        golden[{scene, step}] = std::stoull(hash, nullptr, 16);
    }
    return golden;
}

void write_golden(const fs::path& file, const Hashes& hashes) {
    std::ofstream out(file);
    out << "# World::state_hash() of each example scene (examples/scenes/<scene>.json, its own "
           "dt)\n"
           "# after <step> steps: the oracle of tests/determinism/test_golden_hashes.cpp.\n"
           "# Regenerate: TAMIAS_GOLDEN_UPDATE=1 build/tests/determinism/determinism_tests\n"
           "# scene step hash\n";
    for (const auto& [key, hash] : hashes)
        out << key.first << ' ' << key.second << ' ' << hex(hash) << '\n';
    BOOST_TEST_REQUIRE(out.good(), "cannot write " << file);
}

bool updating() {
    const char* u = std::getenv("TAMIAS_GOLDEN_UPDATE");
    return u && *u && std::string(u) != "0";
}

/// Whether a record's scene name is that of a run in contact regions (`<scene>:regions<n>`).
bool in_regions(const Key& key) {
    return key.first.find(':') != std::string::npos;
}

/// Compares `actual` with the golden records of its kind (in regions or not).
void compare_with_golden(const Hashes& actual, const std::string& run, bool regions) {
    const fs::path file = TAMIAS_GOLDEN_HASHES;
    Hashes golden = read_golden(file);
    std::erase_if(golden, [&](const auto& record) { return in_regions(record.first) != regions; });
    // Each scene's first differing checkpoint only: later ones differ as a consequence.
    std::map<std::string, int> first_difference;
    for (const auto& [key, hash] : actual) {
        const auto g = golden.find(key);
        if (g == golden.end()) {
            BOOST_ERROR(key.first << " step " << key.second << ": no golden hash in " << file
                                  << " (new scene or checkpoint: regenerate the file)");
        } else if (g->second != hash && !first_difference.count(key.first)) {
            first_difference[key.first] = key.second;
            BOOST_ERROR(key.first << " step " << key.second << " (" << run << "): state_hash "
                                  << hex(hash) << ", golden " << hex(g->second)
                                  << ": this build does not give the golden bits");
        }
    }
    for (const auto& [key, hash] : golden)
        if (!actual.count(key))
            BOOST_ERROR(key.first << " step " << key.second << ": golden hash " << hex(hash)
                                  << " was not computed (scene or step removed?)");
    BOOST_TEST_MESSAGE(actual.size() << " checkpoints over " << example_scenes().size()
                                     << " scenes (" << run << ") compared with " << file);
}

} // namespace

BOOST_AUTO_TEST_SUITE(determinism)

// Oracle: the committed golden hashes (golden_hashes.txt), Tamias2D's own earlier output from
// another build: a regression oracle, so the test proves the same bits across builds, not any
// SRS item, and carries the `determinism` tag instead of an SRS label.
BOOST_AUTO_TEST_CASE(example_scenes_reach_the_golden_hashes, *utf::label("determinism")) {
    const Hashes actual = run_scenes(0);
    if (updating()) {
        Hashes all = actual;
        all.merge(run_scenes(0, 2));
        write_golden(TAMIAS_GOLDEN_HASHES, all);
        BOOST_TEST_MESSAGE("wrote " << all.size() << " golden hashes to " << TAMIAS_GOLDEN_HASHES);
        return;
    }
    compare_with_golden(actual, "one worker", false);
}

// Oracle: the same golden hashes: a step's results do not depend on the worker count
// (task_system.hpp), so four workers must give the one-worker bits that the file holds.
BOOST_AUTO_TEST_CASE(example_scenes_on_four_workers_reach_the_golden_hashes,
                     *utf::label("determinism")) {
    if (updating())
        return; // the file is written from one worker
    compare_with_golden(run_scenes(4), "four workers", false);
}

// Oracle: the committed golden hashes of the runs in two contact regions, Tamias2D's own
// earlier output (a regression oracle, as above): on one worker and on four, whose streams run
// the regions on several threads at once.
BOOST_AUTO_TEST_CASE(example_scenes_in_two_regions_reach_their_golden_hashes,
                     *utf::label("determinism")) {
    if (updating())
        return; // written with the others, from one worker
    compare_with_golden(run_scenes(0, 2), "two regions, one worker", true);
    compare_with_golden(run_scenes(4, 2), "two regions, four workers", true);
}

BOOST_AUTO_TEST_SUITE_END()
