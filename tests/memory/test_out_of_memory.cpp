// std::bad_alloc during a step leaves a valid world. The guarantee (docs/user-guide.md,
// "Threads, exceptions and handles"): step() lets the bad_alloc through, and the world stays
// valid: every handle it had stays valid, every state is finite, every call works, it can be
// stepped again once memory is available, and destroying it frees everything. The step that
// failed may have been partly done (basic guarantee, not strong).
// Oracle: the library's own invariants as the public API shows them, checked after every
// failure point of a step (the Nth allocation, N = 0, 1, ... until a step completes), with
// the failure once or for good; the ASan/UBSan build runs the same sweep, where a dangling
// index or a leak left by the unwinding fails it.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <new>
#include <utility>
#include <vector>

#include "support/reliability_support.hpp"
#include "support/replaced_new.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

bool finite_world(const World& w) {
    for (const BodyId b : w.bodies()) {
        const BodyState s = w.state(b);
        if (!std::isfinite(s.position.x + s.position.y + s.velocity.x + s.velocity.y +
                           s.orientation + s.angular_velocity))
            return false;
    }
    return std::isfinite(w.kinetic_energy());
}

/// The busy world after `before` steps.
World busy_world_after(int before) {
    World w = reliability::busy_world();
    for (int s = 0; s < before; ++s)
        w.step(1.0 / 60.0);
    return w;
}

/// Steps `w` with its Nth allocation failing (once, or for good): whether the step threw
/// std::bad_alloc.
bool step_failing_at(World& w, long n, bool once) {
    bool threw = false;
    test::fail_allocation_after(n, once);
    try {
        w.step(1.0 / 60.0);
    } catch (const std::bad_alloc&) {
        threw = true;
    }
    test::stop_failing();
    return threw;
}

/// Fails the Nth allocation (N = 0, 1, ...) of the step after `before` steps, for every N
/// until the step needs fewer; after each failure the world must be valid (see above).
void sweep(int before, bool once) {
    int failures = 0, unchanged = 0;
    for (long n = 0;; ++n) {
        World w = busy_world_after(before);
        const std::vector<BodyId> bodies = w.bodies();
        const std::uint64_t hash = w.state_hash();
        if (!step_failing_at(w, n, once)) {
            BOOST_TEST_MESSAGE("step " << before + 1 << (once ? ", one failure: " : ": ")
                                       << failures << " failure points, " << unchanged
                                       << " left the world as before the step");
            break;
        }
        ++failures;
        unchanged += w.state_hash() == hash;
        BOOST_TEST_CONTEXT("step " << before + 1 << ", allocation " << n << (once ? " once" : "")) {
            BOOST_TEST_REQUIRE(w.bodies() == bodies);
            BOOST_TEST_REQUIRE(finite_world(w));
            (void)w.contacts();
            for (int s = 0; s < 60; ++s)
                w.step(1.0 / 60.0);
            BOOST_TEST_REQUIRE(finite_world(w));
            BOOST_TEST_REQUIRE(w.bodies() == bodies);
            for (const BodyId b : bodies)
                w.destroy_body(b);
            w.step(1.0 / 60.0);
            BOOST_TEST_REQUIRE(w.body_count() == 0u);
        }
    }
    BOOST_TEST(failures > 0);
}

/// The steps (0-based: how many steps come before) among the first 240 that allocate: the
/// first, when everything is sized, and those where the striker's impact makes new contacts and
/// the arrays grow. (A settled world allocates nothing: test_no_allocation.cpp.)
std::vector<int> allocating_steps() {
    std::vector<int> out;
    World w = reliability::busy_world();
    for (int s = 0; s < 240; ++s) {
        const long before = test::allocation_count();
        w.step(1.0 / 60.0);
        if (test::allocation_count() != before)
            out.push_back(s);
    }
    BOOST_TEST_MESSAGE("steps that allocate (0-based): " << out.size());
    return out;
}

/// The bits of every body's pose and velocities, in body order.
std::vector<std::uint64_t> motion_bits(const World& w) {
    std::vector<std::uint64_t> out;
    for (const BodyId b : w.bodies()) {
        const BodyState s = w.state(b);
        for (const double v : {s.position.x, s.position.y, s.velocity.x, s.velocity.y,
                               s.orientation, s.angular_velocity})
            out.push_back(std::bit_cast<std::uint64_t>(v));
    }
    return out;
}

/// The touching pairs of shapes (slot indices, the lower first), sorted.
std::vector<std::pair<std::uint32_t, std::uint32_t>> touching_pairs(const World& w) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    for (const ContactInfo& c : w.contacts())
        out.emplace_back(std::min(c.shape_a.index, c.shape_b.index),
                         std::max(c.shape_a.index, c.shape_b.index));
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

BOOST_AUTO_TEST_SUITE(out_of_memory)

// Oracle: the basic guarantee stated in docs/user-guide.md ("Memory exhaustion"), checked after
// a bad_alloc at each allocation of every allocating step, once or for good: the world keeps
// its bodies, every state and the kinetic energy are finite, it steps on 60 steps still finite,
// and destroying every body empties it. The ASan/UBSan build fails it on a dangling index or a
// leak.
BOOST_AUTO_TEST_CASE(bad_alloc_in_any_allocation_of_a_step_leaves_a_valid_world,
                     *utf::label("reliability")) {
    const std::vector<int> steps = allocating_steps();
    BOOST_TEST_REQUIRE(steps.size() >= 2u);
    for (const int before : steps) {
        sweep(before, false);
        sweep(before, true);
    }
}

// Oracle: the pairs the broad phase reports once (it forgets a shape's move when it reports its
// new pairs): a step that a bad_alloc stops while the new pairs are examined, before any body
// moved, must leave the pairs it did not reach for the next step, so that the next step finds
// every pair a world without the failure finds in that step. Checked at each allocation of
// every allocating step, failing once, where the bodies are left exactly as before the step:
// the next step's touching pairs are the twin world's. A snapshot taken then holds the pairs
// left (the snapshot's promise: a world read from it continues with the same bits).
BOOST_AUTO_TEST_CASE(a_step_stopped_by_bad_alloc_leaves_no_new_pair_unexamined,
                     *utf::label("reliability")) {
    int compared = 0;
    for (const int before : allocating_steps()) {
        const auto expected = touching_pairs(busy_world_after(before + 1));
        for (long n = 0;; ++n) {
            World w = busy_world_after(before);
            const std::vector<std::uint64_t> motion = motion_bits(w);
            if (!step_failing_at(w, n, true))
                break;
            if (motion_bits(w) != motion)
                continue; // stopped after the bodies moved: the step was partly done
            World restored = World::from_snapshot(w.snapshot());
            w.step(1.0 / 60.0);
            restored.step(1.0 / 60.0);
            ++compared;
            BOOST_TEST((touching_pairs(w) == expected),
                       "step " << before + 1 << ", allocation " << n);
            BOOST_TEST(restored.state_hash() == w.state_hash(),
                       "step " << before + 1 << ", allocation " << n << ", restored");
        }
    }
    BOOST_TEST_MESSAGE(compared << " failures before any body moved");
    BOOST_TEST(compared > 0);
}

// Oracle: the basic guarantee (above): every call works on the world a failed step left, also
// before it is stepped again. There, the contacts the failed step found may have no solver
// record yet (it stopped before its narrow phase), and shapes may wait for a refit or a move in
// the broad phase (it stopped while the bodies were written back). Each body is destroyed (in
// creation order, and in reverse) or made static right after each failure point of every
// allocating step: the emptied world steps to no contact, the static one to no contact and no
// motion, and writes a snapshot that is read back (the reader refuses a broad phase no world
// holds). The ASan/UBSan build (with the standard library's bounds checks) also fails it on a
// record read or written past the last.
BOOST_AUTO_TEST_CASE(bodies_destroyed_right_after_a_failed_step_leave_an_empty_world,
                     *utf::label("reliability")) {
    int failures = 0;
    for (const int before : allocating_steps()) {
        for (long n = 0;; ++n) {
            World w = busy_world_after(before), v = busy_world_after(before),
                  u = busy_world_after(before);
            if (!step_failing_at(w, n, true))
                break;
            BOOST_TEST_REQUIRE(step_failing_at(v, n, true));
            BOOST_TEST_REQUIRE(step_failing_at(u, n, true));
            ++failures;
            for (const BodyId b : u.bodies())
                u.set_body_type(b, BodyType::static_body);
            const std::vector<std::uint64_t> still = motion_bits(u);
            u.step(1.0 / 60.0);
            BOOST_TEST_REQUIRE(u.contacts().empty(), "step " << before + 1 << ", " << n);
            BOOST_TEST_REQUIRE((motion_bits(u) == still));
            BOOST_TEST_REQUIRE((World::from_snapshot(u.snapshot()).snapshot() == u.snapshot()));
            for (const BodyId b : w.bodies())
                w.destroy_body(b);
            std::vector<BodyId> reversed = v.bodies();
            std::reverse(reversed.begin(), reversed.end());
            for (const BodyId b : reversed)
                v.destroy_body(b);
            for (World* x : {&w, &v}) {
                x->step(1.0 / 60.0);
                BOOST_TEST_REQUIRE(x->body_count() == 0u);
                BOOST_TEST_REQUIRE(x->contacts().empty(), "step " << before + 1 << ", " << n);
            }
        }
    }
    BOOST_TEST(failures > 0);
}

BOOST_AUTO_TEST_SUITE_END()
