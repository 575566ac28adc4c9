// Seeded fuzzing of the scene loader (R4): the example scenes' JSON text, mutated (byte flips,
// truncation, splices from other scenes, numbers replaced by extreme values or by deep
// nesting), through io::parse_scene, io::build_world and a few World::step calls.
//
// Oracle: the library's stated promises (docs/user-guide.md, "Errors"; scene.hpp): no crash and
// no sanitizer report; every rejection is an io::SceneError or a ValidationError with a
// non-empty message; a step that refuses leaves World::state_hash() unchanged; every state
// after an accepted step is finite; a loaded scene loads again from its written form, which
// steps alongside it to the same state_hash() after every step.
//
// TAMIAS_FUZZ_ITERATIONS=<n> runs more inputs (the default is printed); a failure prints its
// seed, replayed alone with TAMIAS_FUZZ_SEED=<seed> TAMIAS_FUZZ_ITERATIONS=1.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "support/cpu_time.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/memory.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
namespace fs = std::filesystem;
using namespace tamias2d;
using namespace tamias2d::fuzz;

namespace {

// A few seconds in Release and ~20 s under ASan/UBSan at -O1.
constexpr long default_iterations = 3000;
constexpr int steps_per_scene = 3;
// Building and stepping thousands of bodies takes far longer than parsing them (rain, the
// large pyramid, and mutants that ask for up to 10^5 bodies): larger scenes are parsed only.
constexpr std::size_t max_bodies_stepped = 500;

std::vector<std::string> example_texts() {
    std::vector<fs::path> paths;
    for (const auto& e : fs::directory_iterator(TAMIAS_EXAMPLE_SCENES))
        if (e.path().extension() == ".json")
            paths.push_back(e.path());
    std::sort(paths.begin(), paths.end());
    std::vector<std::string> texts;
    for (const auto& p : paths) {
        std::ifstream in(p, std::ios::binary);
        texts.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    return texts;
}

/// Number-like tokens: [start, end) of runs of [-+.0-9eE] that start with a digit or '-'.
std::vector<std::pair<std::size_t, std::size_t>> numbers_in(const std::string& t) {
    std::vector<std::pair<std::size_t, std::size_t>> spans;
    auto numeric = [](char c) {
        return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
    };
    for (std::size_t i = 0; i < t.size();) {
        if ((t[i] >= '0' && t[i] <= '9') || t[i] == '-') {
            std::size_t j = i;
            while (j < t.size() && numeric(t[j]))
                ++j;
            spans.emplace_back(i, j);
            i = j;
        } else {
            ++i;
        }
    }
    return spans;
}

const char* const extreme_numbers[] = {"1e308",
                                       "-1e308",
                                       "1e309",
                                       "-0",
                                       "-0.0",
                                       "NaN",
                                       "nan",
                                       "Infinity",
                                       "-Infinity",
                                       "inf",
                                       "1e99999",
                                       "-1e-99999",
                                       "4.9e-324",
                                       "2.2250738585072014e-308",
                                       "9223372036854775808.0",
                                       "9223372036854775807",
                                       "-9223372036854775809",
                                       "2147483648",
                                       "-2147483649",
                                       "1e12",
                                       "1.0000001e12",
                                       "1e-12",
                                       "9.9e-13",
                                       "1e24",
                                       "0",
                                       "-1",
                                       "1e-320",
                                       "0.5e",
                                       "1e+",
                                       "--1",
                                       "00012",
                                       "1.",
                                       ".5",
                                       "123456789012345678901234567890",
                                       "1e2147483648",
                                       "0x10"};

std::string nested(std::size_t depth, char open, char close) {
    return std::string(depth, open) + "0" + std::string(depth, close);
}

void mutate_once(std::string& t, const std::vector<std::string>& corpus, Rng& r) {
    switch (r.below(9)) {
    case 0: // flip a byte to anything, NUL and control characters included
        if (!t.empty())
            t[r.below(t.size())] = static_cast<char>(r.below(256));
        break;
    case 1: // flip one bit
        if (!t.empty())
            t[r.below(t.size())] ^= static_cast<char>(1u << r.below(8));
        break;
    case 2: // truncate
        t.resize(r.below(t.size() + 1));
        break;
    case 3: { // splice a piece of another scene in
        const std::string& other = corpus[r.below(corpus.size())];
        const std::size_t from = r.below(other.size());
        const std::size_t len = r.below(std::min<std::size_t>(other.size() - from, 200) + 1);
        t.insert(r.below(t.size() + 1), other, from, len);
        break;
    }
    case 4: { // erase a range
        const std::size_t at = r.below(t.size() + 1);
        t.erase(at, r.below(64));
        break;
    }
    case 5:
    case 6: { // replace a number by an extreme one
        const auto spans = numbers_in(t);
        if (spans.empty())
            break;
        const auto [a, b] = spans[r.below(spans.size())];
        t.replace(a, b - a, extreme_numbers[r.below(std::size(extreme_numbers))]);
        break;
    }
    case 7: { // replace a number by deep nesting, or leave the nesting unclosed
        const auto spans = numbers_in(t);
        if (spans.empty())
            break;
        const auto [a, b] = spans[r.below(spans.size())];
        static constexpr std::size_t depths[] = {2, 127, 128, 129, 1000, 100000};
        const std::size_t d = depths[r.below(std::size(depths))];
        std::string n = r.chance(50) ? nested(d, '[', ']') : std::string(d, '[');
        t.replace(a, b - a, n);
        break;
    }
    default: { // duplicate a range (repeated keys, repeated entries)
        if (t.empty())
            break;
        const std::size_t from = r.below(t.size());
        const std::size_t len = r.below(std::min<std::size_t>(t.size() - from, 120) + 1);
        const std::string piece = t.substr(from, len);
        t.insert(r.below(t.size() + 1), piece);
        break;
    }
    }
}

std::string excerpt(const std::string& t) {
    std::string e = t.substr(0, 300);
    for (char& c : e)
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n')
            c = '?';
    return e + (t.size() > 300 ? "..." : "");
}

/// Records a broken promise with the seed, and keeps the input beside the test for replay.
void fail(std::uint64_t seed, const std::string& text, const std::string& what) {
    const std::string file = "fuzz_scene_failure_" + std::to_string(seed) + ".json";
    std::ofstream(file, std::ios::binary) << text;
    BOOST_ERROR("seed " << seed << ": " << what << " (input written to " << file << "):\n"
                        << excerpt(text));
}

struct Tally {
    long rejected = 0, parsed = 0, stepped = 0, step_refused = 0, too_large = 0;
};

void run_one(std::uint64_t seed, const std::vector<std::string>& corpus, Tally& tally) {
    Rng r(seed);
    std::string text = corpus[r.below(corpus.size())];
    if (r.chance(50)) { // one number changed: most such mutants load, and then run
        const auto spans = numbers_in(text);
        const auto [a, b] = spans[r.below(spans.size())];
        text.replace(a, b - a, extreme_numbers[r.below(std::size(extreme_numbers))]);
    } else {
        const std::size_t mutations = 1 + r.below(4);
        for (std::size_t m = 0; m < mutations; ++m)
            mutate_once(text, corpus, r);
    }

    io::Scene scene;
    try {
        scene = io::parse_scene(text, "fuzz");
    } catch (const io::SceneError& e) {
        ++tally.rejected;
        if (std::string(e.what()).empty() || e.detail.empty())
            fail(seed, text, "SceneError with an empty message");
        return;
    } catch (const std::exception& e) {
        fail(seed, text, std::string("parse_scene threw a non-SceneError: ") + e.what());
        return;
    }
    ++tally.parsed;
    if (scene.bodies.size() > max_bodies_stepped) {
        ++tally.too_large;
        return;
    }

    World world(scene.world);
    try {
        io::build_world(scene, world);
    } catch (const std::exception& e) {
        // parse_scene validates the whole scene: what it accepts must build.
        fail(seed, text, std::string("a parsed scene failed to build: ") + e.what());
        return;
    }

    // The round trip promised in scene.hpp: the written form loads and builds the same world,
    // which then steps alongside it to the same hash after every step.
    std::optional<World> twin;
    try {
        const io::Scene again = io::parse_scene(io::scene_to_json(scene), "fuzz (written)");
        twin.emplace(again.world);
        io::build_world(again, *twin);
        if (twin->state_hash() != world.state_hash())
            fail(seed, text, "the written form builds a different world");
    } catch (const std::exception& e) {
        fail(seed, text, std::string("the written form does not load: ") + e.what());
        return;
    }

    for (int s = 0; s < steps_per_scene; ++s) {
        const std::uint64_t before = world.state_hash();
        const std::vector<double> states_before = body_states(world);
        try {
            world.step(scene.dt);
        } catch (const SolverDivergence& e) {
            // Its own promise (errors.hpp): bodies and clock as they were, contacts updated.
            ++tally.step_refused;
            if (body_states(world) != states_before)
                fail(seed, text, std::string("a diverged step changed the bodies: ") + e.what());
            return;
        } catch (const ValidationError& e) {
            // Refusing a state beyond the supported range is allowed; changing the world is not.
            ++tally.step_refused;
            if (e.field.empty() || std::string(e.what()).empty())
                fail(seed, text, "ValidationError with an empty field or message");
            if (world.state_hash() != before)
                fail(seed, text, std::string("a refused step changed the world: ") + e.what());
            return;
        } catch (const std::exception& e) {
            fail(seed, text, std::string("step threw a non-ValidationError: ") + e.what());
            return;
        }
        if (const std::string bad = non_finite_state(world); !bad.empty()) {
            fail(seed, text, "non-finite state after step " + std::to_string(s + 1) + ": " + bad);
            return;
        }
        try {
            twin->step(scene.dt);
        } catch (const std::exception& e) {
            fail(seed, text, std::string("the written form refused a step: ") + e.what());
            return;
        }
        if (twin->state_hash() != world.state_hash()) {
            fail(seed, text,
                 "the written form simulates differently from step " + std::to_string(s + 1));
            return;
        }
    }
    ++tally.stepped;
    // A ray through the scene's usual region: a NaN fraction was found after such runs.
    for (const Vec2d dir : {Vec2d{0.0, -100.0}, Vec2d{100.0, 1.0}}) {
        if (const std::string bad = bad_ray_cast(world, {-50.0, 50.0}, dir); !bad.empty())
            fail(seed, text, bad);
    }
}

} // namespace

BOOST_AUTO_TEST_SUITE(fuzz)

// Oracle: R4's promise as the user guide states it (this file's head): a scene outside the
// data constraints or the schema is refused with a named error; an accepted one steps to finite
// states and loads again from its written form.
BOOST_AUTO_TEST_CASE(mutated_scenes_keep_the_promises, *utf::label("R4")) {
    const std::vector<std::string> corpus = example_texts();
    BOOST_TEST_REQUIRE(!corpus.empty());
    const long n = iterations("TAMIAS_FUZZ_ITERATIONS", default_iterations);
    const std::uint64_t first = base_seed(20260000);
    BOOST_TEST_MESSAGE("scene fuzz: " << n << " inputs, seeds " << first << ".." << first + n - 1
                                      << " (TAMIAS_FUZZ_ITERATIONS, TAMIAS_FUZZ_SEED)");
    Tally tally;
    for (long i = 0; i < n; ++i) {
        const std::uint64_t seed = first + static_cast<std::uint64_t>(i);
        BOOST_TEST_CHECKPOINT("scene fuzz seed " << seed);
        run_one(seed, corpus, tally);
    }
    BOOST_TEST_MESSAGE("scene fuzz: " << tally.rejected << " rejected, " << tally.parsed
                                      << " accepted (" << tally.stepped << " stepped, "
                                      << tally.step_refused << " refused a step, "
                                      << tally.too_large << " too large to step)");
    // A driver whose mutations are all rejected tests only the parser's front door.
    BOOST_TEST(tally.stepped > n / 20);
}

namespace {
/// Parses, builds and steps once a scene text; returns the CPU seconds it took and the large
/// blocks it added (bytes).
std::pair<double, std::size_t> one_step_cost(const std::string& text) {
    const std::size_t before = large_array_stats().mapped_bytes;
    const double t0 = tamias2d::test::process_cpu_seconds();
    const io::Scene scene = io::parse_scene(text, "resource");
    World world(scene.world);
    io::build_world(scene, world);
    world.step(scene.dt);
    const double seconds = tamias2d::test::process_cpu_seconds() - t0;
    const std::size_t after = large_array_stats().mapped_bytes;
    return {seconds, after > before ? after - before : 0};
}
} // namespace

// Oracle: the resource bound an input under 1 MB must keep (docs/verification.md, "Resource
// oracle"): it validates and steps once within 10 s of CPU time (in an optimised build; a
// sanitizer build is held to sanitizer_slowdown times it) and 2 GiB of the library's large blocks.
// The families are the ones that broke it: a base-100 pyramid of boxes from 1e-12 m to 1e6 m,
// its speculative distance scaled with them (a fixed broad-phase margin made every pair of
// small boxes a pair even so), and many shapes on one body, static and dynamic (quadratic
// attach).
BOOST_AUTO_TEST_CASE(small_inputs_step_within_resource_bounds, *utf::label("reliability")) {
    std::vector<std::pair<std::string, std::string>> inputs;
    // The speculative distance scaled with the boxes as the default's 0.02 m is to 1 m boxes.
    const std::pair<const char*, const char*> sizes[] = {
        {"1e-12", "2e-14"}, {"1e-6", "2e-8"}, {"1", "0.02"}, {"1e6", "2e4"}};
    for (const auto& [box, speculative] : sizes)
        inputs.emplace_back(std::string("pyramid of ") + box + " m boxes",
                            std::string(R"({"version":1,"dt":"1/60","steps":1,"world":)") +
                                R"({"speculative_distance":)" + speculative + R"(},"bodies":[)" +
                                R"({"generator":"pyramid","base":100,"box":)" + box + "}]}");
    for (const char* type : {"static", "dynamic"}) {
        std::string shapes;
        for (int i = 0; i < 12000; ++i)
            shapes += std::string(i == 0 ? "" : ",") +
                      R"({"type":"circle","radius":0.4,"center":[)" + std::to_string(i % 100) +
                      "," + std::to_string(i / 100) + "]}";
        inputs.emplace_back(std::string("12000 circles on one ") + type + " body",
                            std::string(R"({"version":1,"dt":"1/60","steps":1,"world":)") +
                                R"({"gravity":[0,0]},"bodies":[{"name":"map","type":")" + type +
                                R"(","shapes":[)" + shapes + "]}]}");
    }
    for (const auto& [name, text] : inputs) {
        BOOST_TEST_CONTEXT(name) {
            BOOST_TEST_REQUIRE(text.size() < (std::size_t(1) << 20));
            const auto [seconds, bytes] = one_step_cost(text);
            BOOST_TEST_MESSAGE(name << " (" << text.size() << " bytes): " << seconds << " s, "
                                    << bytes << " bytes of large blocks");
            BOOST_TEST(seconds < 10.0 * tamias2d::test::sanitizer_slowdown);
            BOOST_TEST(bytes < (std::size_t(2) << 30));
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
