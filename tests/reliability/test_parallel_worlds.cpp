// Worlds in threads (docs/user-guide.md, "Threads, exceptions and handles"): distinct worlds
// may be built, stepped and destroyed in different threads at once, with no lock of the
// game's, and give the bits they give alone; a world may move to another thread between
// calls; large_array_stats and release_retained_memory may be called from any thread at any
// time. The only state worlds share is the pool of retained large blocks (memory.hpp), so the
// scenes are large enough (5050 boxes) that their arrays are large blocks, and each thread
// builds its world twice, taking the blocks the other released.
// Oracle: the same worlds stepped one after the other in the main thread. CI also runs this
// suite built with -fsanitize=thread (.ci/run), where a data race fails it.
#include <boost/test/unit_test.hpp>

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

#include "support/reliability_support.hpp"
#include "tamias2d/memory.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

struct Scene {
    int rows;
    int steps;
};
// ThreadSanitizer runs the same code 5-15 times slower: fewer steps there.
constexpr int step_scale = reliability::memory_sanitizer_build ? 1 : 4;
const Scene scenes[2] = {{100, 10 * step_scale}, {40, 30 * step_scale}};

/// The scene's state hash after every step, over two builds of the world.
std::vector<std::uint64_t> run(const Scene& s) {
    std::vector<std::uint64_t> hashes;
    for (int build = 0; build < 2; ++build) {
        World w = reliability::busy_world(s.rows);
        for (int i = 0; i < s.steps; ++i) {
            w.step(1.0 / 60.0);
            hashes.push_back(w.state_hash());
        }
    }
    return hashes;
}

} // namespace

BOOST_AUTO_TEST_SUITE(threads)

// Oracle: the same two scenes stepped one after the other in the main thread (the same inputs
// give the same bits): run at once in two threads, while a third empties the shared pool of
// large blocks, each gives the same state hash after every step. The ThreadSanitizer build
// (.ci/run) fails on a data race.
BOOST_AUTO_TEST_CASE(two_worlds_in_two_threads_give_the_bits_they_give_alone,
                     *utf::label("reliability")) {
    const std::vector<std::uint64_t> alone[2] = {run(scenes[0]), run(scenes[1])};
    std::vector<std::uint64_t> together[2];
    std::atomic<bool> done{false};
    // A third thread reads the shared counters and empties the pool while the worlds run.
    std::thread meddler([&] {
        while (!done.load()) {
            (void)large_array_stats();
            release_retained_memory();
            std::this_thread::yield();
        }
    });
    {
        std::thread a([&] { together[0] = run(scenes[0]); });
        std::thread b([&] { together[1] = run(scenes[1]); });
        a.join();
        b.join();
    }
    done = true;
    meddler.join();
    for (int k = 0; k < 2; ++k) {
        BOOST_TEST_REQUIRE(together[k].size() == alone[k].size());
        for (std::size_t i = 0; i < alone[k].size(); ++i)
            BOOST_TEST_REQUIRE(together[k][i] == alone[k][i], "scene " << k << " step " << i);
    }
}

// Oracle: a twin world given the same steps in this thread (the same inputs give the same
// bits): a world stepped 30 times here and 30 in another thread has the twin's state hash.
BOOST_AUTO_TEST_CASE(a_world_handed_to_another_thread_goes_on_as_before,
                     *utf::label("reliability")) {
    World here = reliability::busy_world(), twin = reliability::busy_world();
    for (int i = 0; i < 30; ++i) {
        here.step(1.0 / 60.0);
        twin.step(1.0 / 60.0);
    }
    std::thread there([&] { // one thread at a time: this one waits in join
        for (int i = 0; i < 30; ++i)
            here.step(1.0 / 60.0);
    });
    there.join();
    for (int i = 0; i < 30; ++i)
        twin.step(1.0 / 60.0);
    BOOST_TEST(here.state_hash() == twin.state_hash());
}

BOOST_AUTO_TEST_SUITE_END()
