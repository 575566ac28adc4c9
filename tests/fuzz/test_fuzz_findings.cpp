// The scene mutants behind findings F1 and F2 (docs/verification.md, "Findings (fixed)"), kept as
// concrete cases: each example scene with one value changed as the scene fuzzer changed it. Each
// loaded and turned non-finite within two steps before DCX_joint's lever rule; now the loader
// refuses it, naming the joint's anchor and the rule.
//
// Oracle: DCX_joint (srs/data_constraints.yaml): every anchor on a dynamic body that turns lies
// within 1e5 radii of gyration sqrt(I / m) of its centre of mass; the unchanged scene loads.
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tamias2d/io/scene.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

std::string example(const std::string& name) {
    std::ifstream in(std::filesystem::path(TAMIAS_EXAMPLE_SCENES) / (name + ".json"),
                     std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The example with `from` (which must occur once) replaced by `to`.
std::string mutant(const std::string& name, const std::string& from, const std::string& to) {
    std::string text = example(name);
    const auto at = text.find(from);
    BOOST_TEST_REQUIRE(at != std::string::npos, name << " has no " << from);
    BOOST_TEST_REQUIRE(text.find(from, at + 1) == std::string::npos, name << ": " << from);
    return text.replace(at, from.size(), to);
}

} // namespace

BOOST_AUTO_TEST_SUITE(fuzz_findings)

// Oracle: DCX_joint's stated rule (srs/data_constraints.yaml): example scenes edited so that a
// joint's anchor lies far from its body or the body's radius of gyration is tiny are refused,
// the error naming the body whose anchor breaks the rule.
BOOST_AUTO_TEST_CASE(far_and_tiny_lever_scenes_are_refused,
                     *utf::label("R4") * utf::label("DCX_joint")) {
    struct Case {
        const char* scene;
        const char* from;
        const char* to;
        const char* body; // the body whose anchor the error names
    };
    const Case cases[] = {
        // F1: a link, a plank, a pendulum arm moved far from its pins.
        {"chain", R"("name": "link16", "position": [7.75, 0])",
         R"("name": "link16", "position": [1e12, 0])", "'link16'"},
        {"bridge", R"("name": "plank19", "position": [8.5, 0])",
         R"("name": "plank19", "position": [8.5, -2147483649])", "'plank19'"},
        {"double_pendulum", R"("position": [0.4330127018922193, 0.25])",
         R"("position": [0.433, -2147483649])", "'upper'"},
        // F2 from a shape: the ragdoll's head of radius 1e-12 m (scene seeds 50007199, 50013103).
        {"ragdoll", R"("radius": 0.25})", R"("radius": 1e-12})", "'head'"},
    };
    for (const Case& c : cases) {
        BOOST_TEST_CONTEXT(c.scene) {
            BOOST_CHECK_NO_THROW(io::parse_scene(example(c.scene), c.scene));
            try {
                (void)io::parse_scene(mutant(c.scene, c.from, c.to), c.scene);
                BOOST_ERROR("accepted");
            } catch (const io::SceneError& e) {
                BOOST_TEST(e.constraint == "DCX_joint", e.what());
                BOOST_TEST(e.field.find("anchor") != std::string::npos, e.what());
                BOOST_TEST(std::string(e.what()).find(c.body) != std::string::npos, e.what());
            }
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
