// The allocator hook (allocator.hpp) sees every allocation the library makes for a world. This
// executable replaces the global operator new and delete (counting_hook.cpp), so it is one of
// its own. Oracle for every case: two independent counters, the hook's own table of live
// blocks (each free matched with its allocation's size and alignment) and the replaced global
// operator new, which counts every C++ heap allocation of the process while the window is
// open; the scenario (scenario.cpp) allocates nothing itself inside it.
#include <boost/test/unit_test.hpp>

#include <stdexcept>
#include <string>

#include "embedding/counting_hook.hpp"
#include "embedding/scenario.hpp"
#include "tamias2d/allocator.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

namespace {

using namespace tamias2d;
using namespace tamias2d::test;
namespace utf = boost::unit_test;

/// The hook installed for one case, the default restored after it.
struct Hooked {
    Hooked() {
        set_allocator(counting_hook());
        reset_hook_counts();
    }
    ~Hooked() { reset_allocator(); }
    Hooked(const Hooked&) = delete;
    Hooked& operator=(const Hooked&) = delete;
};

struct Observed {
    ScenarioResult result;
    std::size_t news = 0, new_bytes = 0;
    HookCounts hook;
};

/// A job system of two workers that runs each loop's items in order on the calling thread,
/// alternating the worker numbers (a game's would hand them to its threads).
TaskSystem serial_jobs() {
    TaskSystem s;
    s.enqueue = [](TaskCallback task, int count, void* context, void*) -> void* {
        for (int i = 0; i < count; ++i)
            task(i, i + 1, i % 2, context);
        return nullptr;
    };
    s.finish = [](void*, void*) {};
    return s;
}

/// The scenario inside the window, with the counting hook set.
Observed observe(int workers, const TaskSystem& jobs = {}) {
    ScenarioInput in = scenario_input(workers);
    in.task_system = jobs;
    Observed o;
    {
        const Hooked hooked;
        open_window();
        o.result = run_scenario(in);
        close_window();
        o.news = window_news();
        o.new_bytes = window_new_bytes();
        o.hook = hook_counts();
    }
    return o;
}

void check_scenario(const ScenarioResult& r) {
    BOOST_TEST(r.chain_ids == 11u);
    BOOST_TEST(r.hash_count == 5u);
    BOOST_TEST(r.begin_events > 0u);
    BOOST_TEST(r.end_events > 0u);
    BOOST_TEST(r.sensor_begins > 0u);
    BOOST_TEST(r.hit_events > 0u);
    BOOST_TEST(r.move_events > 0u);
    BOOST_TEST(r.joint_events > 0u);
    BOOST_TEST(r.ray_hits > 0u);
    BOOST_TEST(r.aabb_hits > 0u);
    BOOST_TEST(r.point_hits > 0u);
    BOOST_TEST(r.overlap_hits > 0u);
    BOOST_TEST(r.cast_hits > 0u);
    BOOST_TEST(r.span_hits > 0u);
    BOOST_TEST(r.distance > 0.0);
    BOOST_TEST(r.crate_slept);
    BOOST_TEST(r.bullet_held);
    BOOST_TEST(r.restored_equal);
    BOOST_TEST(r.snapshot_size > 0u);
    BOOST_TEST(r.recorder_steps == 10u);
    BOOST_TEST(r.replayed_steps == 10u);
    BOOST_TEST(r.pre_solve_calls > 0u);
    BOOST_TEST(r.filter_calls > 0u);
}

void check_hook(const HookCounts& h) {
    BOOST_TEST(h.allocations > 0u);
    BOOST_TEST(h.frees == h.allocations);
    BOOST_TEST(h.live == 0u);
    BOOST_TEST(h.mismatched == 0u);
    BOOST_TEST(h.unknown == 0u);
    BOOST_TEST(h.misaligned == 0u);
    BOOST_TEST(h.table_full == 0u);
    BOOST_TEST(allocator_use().blocks == 0u);
}

} // namespace

BOOST_AUTO_TEST_SUITE(allocator_hook)

// Oracle: the allocator contract (allocator.hpp) on one worker, read by two counters apart from
// the library: the replaced global operator new sees only the by-value vectors the contract
// leaves to the caller (create_chain's handles, Recorder::bytes()), and the hook's own table
// matches every free with its block's size and alignment, none left live.
BOOST_AUTO_TEST_CASE(one_worker_allocates_only_through_the_hook, *utf::label("embedding")) {
    const Observed o = observe(1);
    check_scenario(o.result);
    BOOST_TEST(o.news == scenario_by_value_results);
    check_hook(o.hook);
    BOOST_TEST_MESSAGE("1 worker: " << o.hook.allocations << " hook allocations, " << o.hook.bytes
                                    << " bytes; " << o.news << " global operator new, "
                                    << o.new_bytes << " bytes");
}

// Oracle: the allocator contract (allocator.hpp) on two workers: outside the hook only the
// by-value vectors and each pool thread's std::thread state, one global operator new per pool
// thread (workers - 1) of each World; the scenario makes two Worlds (its own and the
// Replayer's), so two more. Read by the replaced operator new and the hook's own table.
BOOST_AUTO_TEST_CASE(two_workers_add_only_the_thread_start, *utf::label("embedding")) {
    const Observed o = observe(2);
    check_scenario(o.result);
    BOOST_TEST(o.news == scenario_by_value_results + 2u);
    check_hook(o.hook);
    BOOST_TEST_MESSAGE("2 workers: " << o.hook.allocations << " hook allocations, " << o.hook.bytes
                                     << " bytes; " << o.news << " global operator new, "
                                     << o.new_bytes << " bytes");
}

// Oracle: the allocator contract (allocator.hpp): on two workers lent by the game's job system
// (WorldDef::task_system) the World starts no thread, so the replaced global operator new sees
// only the by-value vectors, and the hook's own table matches every free with its allocation.
BOOST_AUTO_TEST_CASE(a_task_system_starts_no_thread, *utf::label("embedding")) {
    const Observed o = observe(2, serial_jobs());
    check_scenario(o.result);
    BOOST_TEST(o.news == scenario_by_value_results);
    check_hook(o.hook);
}

// Oracle: the same scenario run without the hook (determinism property: the same inputs give
// the same bits): its state hashes, bit for bit, on one worker and on two. Where the memory
// comes from must change nothing the world computes.
BOOST_AUTO_TEST_CASE(the_hook_changes_no_result, *utf::label("embedding")) {
    for (const int workers : {1, 2}) {
        ScenarioInput plain_in = scenario_input(workers);
        const ScenarioResult plain = run_scenario(plain_in);
        const Observed hooked = observe(workers);
        BOOST_TEST(plain.hash_count == hooked.result.hash_count);
        for (std::size_t k = 0; k < plain.hash_count; ++k)
            BOOST_TEST(plain.hashes[k] == hooked.result.hashes[k],
                       "workers " << workers << ", hash " << k);
    }
}

// Oracle: the stated rules of set_allocator and reset_allocator (allocator.hpp): refused with
// AllocatorInUse while a World holds any block (the count, read from allocator_use(), in the
// message), the current hook left as it was; accepted once none is held; a hook without one of
// its functions refused naming it ("allocator.free").
BOOST_AUTO_TEST_CASE(the_hook_is_refused_while_a_world_lives, *utf::label("embedding")) {
    {
        World world;
        world.create_body(BodyDef{});
        const std::size_t held = allocator_use().blocks;
        BOOST_TEST(held > 0u);
        try {
            set_allocator(counting_hook());
            BOOST_FAIL("set_allocator accepted while a world lives");
        } catch (const AllocatorInUse& e) {
            const std::string what = e.what();
            BOOST_TEST(what.find(std::to_string(held) + " blocks") != std::string::npos, what);
        }
        BOOST_TEST(current_allocator().allocate == nullptr);
        BOOST_CHECK_THROW(reset_allocator(), AllocatorInUse);
    }
    BOOST_TEST(allocator_use().blocks == 0u);
    Allocator half = counting_hook();
    half.free = nullptr;
    try {
        set_allocator(half);
        BOOST_FAIL("set_allocator accepted a hook without free");
    } catch (const std::invalid_argument& e) {
        BOOST_TEST(std::string(e.what()).find("allocator.free") != std::string::npos);
    }
    set_allocator(counting_hook());
    BOOST_TEST(current_allocator().allocate == counting_hook().allocate);
    {
        const World world;
        BOOST_CHECK_THROW(reset_allocator(), AllocatorInUse);
    }
    reset_allocator();
    BOOST_TEST(current_allocator().allocate == nullptr);
}

BOOST_AUTO_TEST_SUITE_END()
