// The joint passes' streams (JointStreams, joint_streams.hpp) against their stated rule,
// re-implemented here as one filter per stream: the moving solver bodies 1 ... M cut into R runs
// (body k in run floor((k - 1) R / M)), the joints of run 0 in creation order, ..., of run R - 1,
// then the rest (between runs, or on the immovable body 0) in creation order. Which threads run
// the streams is tests/reliability's (equal hashes on every worker count).
#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "tamias2d/dynamics/joints/joint_streams.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

/// n joints between random solver bodies of 0 ... moving (about one side in ten immovable),
/// numbered in creation order.
memory::vector<SolvedJoint> random_joints(std::uint32_t seed, std::size_t n, std::uint32_t moving) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::uint32_t> body(1, moving), tenth(0, 9);
    memory::vector<SolvedJoint> out;
    for (std::uint32_t i = 0; i < n; ++i) {
        SolvedJoint s;
        s.joint = i;
        s.solver_a = tenth(rng) == 0 ? 0 : body(rng);
        s.solver_b = body(rng);
        // A joint often holds bodies created one after the other (a chain, a ragdoll).
        if (tenth(rng) < 6 && s.solver_a != 0)
            s.solver_b = s.solver_a < moving ? s.solver_a + 1 : s.solver_a - 1;
        out.push_back(s);
    }
    return out;
}

/// The rule: stream r < R holds the joints with both bodies moving and in run r; stream R the
/// rest; each in creation order.
std::vector<std::vector<std::uint32_t>> expected_streams(const memory::vector<SolvedJoint>& in,
                                                         std::uint32_t R, std::uint32_t moving) {
    std::vector<std::vector<std::uint32_t>> streams(R + 1);
    for (const SolvedJoint& s : in) {
        const auto run = [&](std::uint32_t k) { return std::uint64_t(k - 1) * R / moving; };
        const bool within =
            s.solver_a != 0 && s.solver_b != 0 && run(s.solver_a) == run(s.solver_b);
        streams[within ? run(s.solver_a) : R].push_back(s.joint);
    }
    return streams;
}

} // namespace

BOOST_AUTO_TEST_SUITE(joint_streams)

// Oracle: the rule above, stream by stream, and the property the threads rely on: no moving
// body is held by joints of two different runs, and no run's joint holds the immovable body 0.
BOOST_AUTO_TEST_CASE(the_split_follows_its_rule_and_the_runs_share_no_body,
                     *utf::label("internals")) {
    int split = 0;
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        const std::uint32_t moving = 40 + seed * 37;
        const std::size_t n = JointStreams::min_joints + seed * 23;
        for (std::uint32_t R = 2; R <= JointStreams::max_regions; R += 3) {
            BOOST_TEST_CONTEXT("seed " << seed << ", " << R << " regions") {
                const memory::vector<SolvedJoint> in = random_joints(seed, n, moving);
                memory::vector<SolvedJoint> joints = in;
                JointStreams streams;
                streams.split(joints, R, moving);
                BOOST_TEST_REQUIRE(streams.regions() == R);
                BOOST_TEST_REQUIRE(joints.size() == in.size());
                const auto expected = expected_streams(in, R, moving);
                std::set<std::uint32_t> seen_elsewhere;
                for (std::uint32_t r = 0; r <= R; ++r) {
                    const std::uint32_t end = r < R ? streams.begin(r + 1) : std::uint32_t(n);
                    std::vector<std::uint32_t> got;
                    std::set<std::uint32_t> bodies;
                    for (std::uint32_t k = streams.begin(r); k < end; ++k) {
                        got.push_back(joints[k].joint);
                        // The record keeps its own bodies.
                        BOOST_TEST(joints[k].solver_a == in[joints[k].joint].solver_a);
                        BOOST_TEST(joints[k].solver_b == in[joints[k].joint].solver_b);
                        bodies.insert(joints[k].solver_a);
                        bodies.insert(joints[k].solver_b);
                    }
                    BOOST_TEST(got == expected[r], boost::test_tools::per_element());
                    if (r == R)
                        continue;
                    BOOST_TEST(bodies.count(0) == 0u);
                    for (const std::uint32_t b : bodies)
                        BOOST_TEST(seen_elsewhere.count(b) == 0u);
                    seen_elsewhere.insert(bodies.begin(), bodies.end());
                }
                ++split;
            }
        }
    }
    BOOST_TEST(split == 20 * 3);
}

// Oracle: the stated floors: one region, fewer than min_joints joints, or fewer moving bodies
// than regions leave the creation order as it was.
BOOST_AUTO_TEST_CASE(one_region_or_few_joints_keep_the_creation_order, *utf::label("internals")) {
    const std::uint32_t moving = 500;
    for (const auto& [R, n, m] : {std::tuple{1u, std::size_t(1000), moving},
                                  std::tuple{4u, JointStreams::min_joints - 1, moving},
                                  std::tuple{4u, std::size_t(1000), 3u}}) {
        BOOST_TEST_CONTEXT(R << " regions, " << n << " joints, " << m << " moving") {
            const memory::vector<SolvedJoint> in = random_joints(7, n, m);
            memory::vector<SolvedJoint> joints = in;
            JointStreams streams;
            streams.split(joints, R, m);
            BOOST_TEST(streams.regions() == 0u);
            for (std::size_t k = 0; k < n; ++k)
                BOOST_TEST_REQUIRE(joints[k].joint == in[k].joint);
        }
    }
}

// Oracle: the same floors, met exactly: min_joints joints, or as many moving bodies as regions
// (a run of one body each), are cut by the rule of the first case.
BOOST_AUTO_TEST_CASE(the_floors_met_exactly_are_split, *utf::label("internals")) {
    for (const auto& [R, n, m] :
         {std::tuple{4u, JointStreams::min_joints, 500u}, std::tuple{4u, std::size_t(1000), 4u},
          std::tuple{JointStreams::max_regions, std::size_t(600), JointStreams::max_regions}}) {
        BOOST_TEST_CONTEXT(R << " regions, " << n << " joints, " << m << " moving") {
            const memory::vector<SolvedJoint> in = random_joints(11, n, m);
            memory::vector<SolvedJoint> joints = in;
            JointStreams streams;
            streams.split(joints, R, m);
            BOOST_TEST_REQUIRE(streams.regions() == R);
            const auto by_rule = expected_streams(in, R, m);
            std::vector<std::uint32_t> got, expected;
            for (const SolvedJoint& s : joints)
                got.push_back(s.joint);
            for (const auto& stream : by_rule)
                expected.insert(expected.end(), stream.begin(), stream.end());
            BOOST_TEST(got == expected, boost::test_tools::per_element());
            for (std::uint32_t r = 0; r < R; ++r)
                BOOST_TEST(streams.begin(r + 1) - streams.begin(r) == by_rule[r].size());
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
