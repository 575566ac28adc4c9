// A step on several threads (WorldDef::workers, WorldDef::task_system) gives the bits of one
// thread: the parallel loops run blocks fixed by the scene, each writing only its own data, and
// what depends on order (events, wakes, destructions, the lists the write-back makes) is done in
// contact or body order after them, or from counts summed in block order (the solver bodies, the
// touching manifolds). The scenes are large enough (over 1024 moving bodies, over 2048 contacts,
// over 32 packs) for every parallel loop of the step to run in blocks. CI also
// runs this suite built with -fsanitize=thread (.ci/tsan_check.sh), where a data race fails it.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

#include "support/pyramid.hpp"
#include "support/reliability_support.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

// ThreadSanitizer runs the same code 5-15 times slower: fewer steps there.
constexpr int step_scale = reliability::memory_sanitizer_build ? 1 : 3;

/// A game's job system as a test double: each loop is cut into `pieces` ranges of items, which
/// `threads` std::threads run, each taking its ranges from the last to the first (reverse) or
/// every threads-th one (interleaved), with worker numbers 0 ... threads - 1. The loop runs
/// between enqueue and finish, which joins the threads.
struct ScramblingTasks {
    int threads = 3;
    int pieces = 7;
    bool reverse = true;
    std::vector<std::thread> running;
    std::atomic<int> loops{0};

    static void* enqueue(TaskCallback task, int count, void* task_context, void* user) {
        auto& self = *static_cast<ScramblingTasks*>(user);
        self.loops.fetch_add(1);
        const int pieces = std::min(self.pieces, count);
        auto piece_begin = [=](int p) { return int(std::int64_t(count) * p / pieces); };
        for (int t = 0; t < self.threads; ++t) {
            self.running.emplace_back([=, reverse = self.reverse, threads = self.threads] {
                for (int k = 0; k < pieces; ++k) {
                    const int p = reverse ? pieces - 1 - k : k;
                    if (p % threads != t)
                        continue;
                    task(piece_begin(p), piece_begin(p + 1), t, task_context);
                }
            });
        }
        return &self;
    }
    static void finish(void* handle, void* user) {
        BOOST_TEST_REQUIRE(handle == user);
        auto& self = *static_cast<ScramblingTasks*>(user);
        for (std::thread& t : self.running)
            t.join();
        self.running.clear();
    }
    TaskSystem system() { return {&ScramblingTasks::enqueue, &ScramblingTasks::finish, this}; }
};

/// How a scene's world is stepped.
struct Threading {
    int workers = 1;
    ScramblingTasks* tasks = nullptr; ///< the game's task system, or the World's own pool
};

using Build = std::function<void(World&)>;

/// The state hash after every step, with the begin and end events folded in (in order).
std::vector<std::uint64_t> run(WorldDef def, const Build& build, int steps, Threading t) {
    def.workers = t.workers;
    if (t.tasks)
        def.task_system = t.tasks->system();
    World world(def);
    build(world);
    std::vector<std::uint64_t> hashes;
    for (int i = 0; i < steps; ++i) {
        world.step(1.0 / 60.0);
        std::uint64_t h = world.state_hash();
        for (const ContactEvent& e : world.contact_begin_events())
            h = h * 1000003u + e.shape_a.index * 31u + e.shape_b.index;
        h = h * 7u + 1u;
        for (const ContactEvent& e : world.contact_end_events())
            h = h * 1000003u + e.shape_a.index * 31u + e.shape_b.index;
        hashes.push_back(h);
    }
    return hashes;
}

/// The scene stepped with 2, 3 and 4 workers of the World's pool and with the three scrambling
/// task systems must give the hashes of one worker, step by step.
void check_every_threading(const WorldDef& def, const Build& build, int steps) {
    const std::vector<std::uint64_t> one = run(def, build, steps, {});
    for (int workers = 2; workers <= 4; ++workers) {
        BOOST_TEST_CONTEXT("workers = " << workers) {
            BOOST_TEST(run(def, build, steps, {workers, nullptr}) == one,
                       boost::test_tools::per_element());
        }
    }
    for (const bool reverse : {true, false}) {
        ScramblingTasks tasks;
        tasks.reverse = reverse;
        BOOST_TEST_CONTEXT("task system, " << (reverse ? "reverse" : "interleaved")) {
            BOOST_TEST(run(def, build, steps, {tasks.threads, &tasks}) == one,
                       boost::test_tools::per_element());
            BOOST_TEST(tasks.loops.load() > steps); // it ran the step's loops
        }
    }
    // A system that runs the pieces one after another, the last first, on one thread, for a
    // world of three workers: a piece of a contact pass must never wait for one not started.
    ScramblingTasks one_at_a_time;
    one_at_a_time.threads = 1;
    BOOST_TEST_CONTEXT("task system, one piece at a time") {
        BOOST_TEST(run(def, build, steps, {3, &one_at_a_time}) == one,
                   boost::test_tools::per_element());
    }
}

const Material wood{1.0, 0.0, 0.6};

void ground(World& world, double width, double y = -0.5) {
    BodyDef g;
    g.type = BodyType::static_body;
    g.position = {0.0, y};
    world.create_shape(world.create_body(g), box_shape(width, 1.0, wood));
}

/// 1200 boxes of 0.5 m in 10 jittered rows falling into an open box, and a heavy block dropped
/// from high up that lands on the pile once much of it sleeps (wakes in the narrow phase).
void rain(World& world) {
    ground(world, 100.0);
    for (const double x : {-50.5, 50.5}) {
        BodyDef wall;
        wall.type = BodyType::static_body;
        wall.position = {x, 5.0};
        world.create_shape(world.create_body(wall), box_shape(1.0, 12.0, wood));
    }
    std::uint64_t state = 1;
    auto jitter = [&state] { // splitmix64, scaled to [-0.05, 0.05)
        state += 0x9e3779b97f4a7c15ull;
        std::uint64_t z = state;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        z ^= z >> 31;
        return (double(z >> 11) / 9007199254740992.0 - 0.5) * 0.1;
    };
    for (int row = 0; row < 10; ++row) {
        for (int col = 0; col < 120; ++col) {
            BodyDef d;
            d.position = {-49.0 + col * 0.82 + jitter(), 1.0 + row * 0.8 + jitter()};
            d.angle = 3.0 * jitter();
            world.create_shape(world.create_body(d), box_shape(0.5, 0.5, wood));
        }
    }
    BodyDef block;
    block.position = {3.0, 14.0}; // lands after about 1.3 s
    world.create_shape(world.create_body(block), box_shape(2.0, 1.0, Material{5.0, 0.0, 0.6}));
}

/// A falling box placed first (its contact with the box below it is among the first), then a
/// row of 200 touching boxes built asleep on the ground: when the falling box touches, the box
/// below wakes within the narrow phase, and its later contacts (with the ground and its
/// neighbours), kept so far, are updated in that same pass.
void sleeping_row(World& world) {
    ground(world, 300.0);
    BodyDef falling;
    falling.position = {0.3, 1.56}; // 0.06 m above the row: within the fat boxes' margin
    world.create_shape(world.create_body(falling), box_shape(1.0, 1.0, wood));
    for (int k = 0; k < 200; ++k) {
        BodyDef d;
        d.position = {k - 100.0, 0.5};
        d.awake = false;
        world.create_shape(world.create_body(d), box_shape(1.0, 1.0, wood));
    }
}

/// A pile of 1300 boxes in 13 rows, every third damped, every fourth bouncy (restitution 0.5),
/// every fifth pushed sideways by a force of its own, with static posts between them: the solver
/// bodies' decay factors and loads, and the bouncing manifolds' slots, from blocks.
void mixed_pile(World& world) {
    ground(world, 120.0);
    const Material bouncy{1.0, 0.5, 0.6};
    int k = 0;
    for (int row = 0; row < 13; ++row) {
        for (int col = 0; col < 100; ++col, ++k) {
            BodyDef d;
            d.position = {-50.0 + col * 1.01 + 0.3 * (row % 2), 0.5 + row * 1.02};
            if (k % 3 == 0) {
                d.linear_damping = 0.4;
                d.angular_damping = 0.7;
            }
            if (k % 5 == 0)
                d.force = {row % 2 == 0 ? 3.0 : -3.0, 0.0};
            if (k % 17 == 0)
                d.type = BodyType::static_body;
            world.create_shape(world.create_body(d),
                               box_shape(1.0, 1.0, k % 4 == 0 ? bouncy : wood));
        }
    }
}

/// 40 chains of 28 links hanging from static pins, swinging into each other and onto the
/// ground, with a revolute joint between neighbours.
void chains(World& world) {
    ground(world, 200.0, -30.0);
    for (int c = 0; c < 40; ++c) {
        BodyDef pin_def;
        pin_def.type = BodyType::static_body;
        pin_def.position = {-60.0 + 3.0 * c, 0.0};
        BodyId previous = world.create_body(pin_def);
        for (int k = 0; k < 28; ++k) {
            BodyDef link;
            link.position = {-60.0 + 3.0 * c + 0.5 + k, 0.0};
            const BodyId b = world.create_body(link);
            world.create_shape(b, box_shape(1.0, 0.25, wood));
            world.create_joint(RevoluteJointDef{
                .body_a = previous, .body_b = b, .anchor = {-60.0 + 3.0 * c + k, 0.0}});
            previous = b;
        }
    }
}

/// 30 hanging chains of 40 links, each link held by the next kind in turn (revolute with limit,
/// motor and spring; weld, soft; prismatic with limit, motor and spring; wheel with motor;
/// distance with spring and limits; motor joint), the first to a static pin, with a target
/// joint on every seventh link from the fourth: 1380 joints of every kind, 210 of them on an
/// immovable body.
void every_kind_chains(World& world) {
    ground(world, 200.0, -45.0);
    for (int c = 0; c < 30; ++c) {
        BodyDef pin_def;
        pin_def.type = BodyType::static_body;
        const double x0 = -60.0 + 4.0 * c;
        pin_def.position = {x0, 0.0};
        BodyId previous = world.create_body(pin_def);
        for (int k = 0; k < 40; ++k) {
            BodyDef link;
            link.position = {x0 + 0.5 + k, 0.0};
            const BodyId b = world.create_body(link);
            world.create_shape(b, box_shape(1.0, 0.25, wood));
            const Vec2d at{x0 + k, 0.0};
            switch ((c + k) % 6) {
            case 0:
                world.create_joint(RevoluteJointDef{.body_a = previous,
                                                    .body_b = b,
                                                    .anchor = at,
                                                    .enable_limit = true,
                                                    .lower_angle = -1.0,
                                                    .upper_angle = 1.0,
                                                    .enable_motor = true,
                                                    .motor_speed = 0.5,
                                                    .max_motor_torque = 2.0,
                                                    .enable_spring = true,
                                                    .hertz = 2.0,
                                                    .damping_ratio = 0.5});
                break;
            case 1:
                world.create_joint(WeldJointDef{.body_a = previous,
                                                .body_b = b,
                                                .anchor = at,
                                                .linear_hertz = 8.0,
                                                .angular_hertz = 4.0});
                break;
            case 2:
                world.create_joint(PrismaticJointDef{.body_a = previous,
                                                     .body_b = b,
                                                     .anchor = at,
                                                     .axis = {1.0, 0.2},
                                                     .enable_limit = true,
                                                     .lower_translation = -0.1,
                                                     .upper_translation = 0.2,
                                                     .enable_motor = true,
                                                     .motor_speed = 0.1,
                                                     .max_motor_force = 5.0,
                                                     .enable_spring = true,
                                                     .hertz = 3.0,
                                                     .damping_ratio = 0.3});
                break;
            case 3:
                world.create_joint(WheelJointDef{.body_a = previous,
                                                 .body_b = b,
                                                 .anchor = at,
                                                 .enable_motor = true,
                                                 .motor_speed = 1.0,
                                                 .max_motor_torque = 3.0});
                break;
            case 4:
                world.create_joint(DistanceJointDef{.body_a = previous,
                                                    .body_b = b,
                                                    .anchor_a = at,
                                                    .anchor_b = at + Vec2d{0.5, 0.0},
                                                    .hertz = 5.0,
                                                    .damping_ratio = 0.4,
                                                    .enable_limit = true,
                                                    .min_length = 0.3,
                                                    .max_length = 0.7});
                break;
            default:
                world.create_joint(MotorJointDef{.body_a = previous,
                                                 .body_b = b,
                                                 .linear_offset = {1.0, 0.0},
                                                 .max_force = 50.0,
                                                 .max_torque = 20.0});
                break;
            }
            if (k % 7 == 3)
                world.create_joint(
                    TargetJointDef{.body = b, .target = at + Vec2d{0.5, 0.0}, .max_force = 30.0});
            previous = b;
        }
    }
}

} // namespace

BOOST_AUTO_TEST_SUITE(parallel_step)

// Oracle: the same scene stepped by one worker, the serial step (state hashes and the order of
// the begin and end events, step by step). With contact regions, the regions' contact streams
// run on several threads at once (PackStreams), each pack after the packs it waits for.
BOOST_AUTO_TEST_CASE(pyramid_is_bitwise_identical_on_every_thread_count,
                     *utf::label("determinism")) {
    for (const int regions : {1, 2, 3}) {
        BOOST_TEST_CONTEXT("contact_regions = " << regions) {
            WorldDef def;
            def.gravity = {0.0, -10.0};
            def.contact_regions = regions;
            check_every_threading(
                def, [](World& w) { test::build_pyramid(w, 48); }, 10 * step_scale);
        }
    }
}

// Oracle: as above, with sleeping on: islands fall asleep, and the block dropped on the pile
// wakes bodies in the narrow phase, where the serial loop's wakes make later contacts due for
// update within the same pass.
BOOST_AUTO_TEST_CASE(sleeping_rain_is_bitwise_identical_on_every_thread_count,
                     *utf::label("determinism")) {
    for (const int regions : {1, 2}) {
        BOOST_TEST_CONTEXT("contact_regions = " << regions) {
            WorldDef def;
            def.gravity = {0.0, -10.0};
            def.enable_sleep = true;
            def.time_to_sleep = 0.1;
            def.contact_regions = regions;
            check_every_threading(def, rain, 60 * step_scale);
        }
    }
}

// Oracle: as above, with sleeping on, where the serial loop's order matters most: a wake in the
// narrow phase makes later contacts of the woken body due for update within the same pass.
BOOST_AUTO_TEST_CASE(wakes_within_the_narrow_phase_are_bitwise_identical_on_every_thread_count,
                     *utf::label("determinism")) {
    WorldDef def;
    def.gravity = {0.0, -10.0};
    def.enable_sleep = true;
    check_every_threading(def, sleeping_row, 20);
}

// Oracle: as above, with damped, bouncing and loaded bodies among static ones: the solver
// bodies and the touching manifolds are numbered from counts summed over blocks.
BOOST_AUTO_TEST_CASE(a_damped_bouncing_loaded_pile_is_bitwise_identical_on_every_thread_count,
                     *utf::label("determinism")) {
    for (const int regions : {1, 2}) {
        BOOST_TEST_CONTEXT("contact_regions = " << regions) {
            WorldDef def;
            def.gravity = {0.0, -10.0};
            def.contact_regions = regions;
            check_every_threading(def, mixed_pile, 10 * step_scale);
        }
    }
    World world(WorldDef{.gravity = {0.0, -10.0}});
    mixed_pile(world);
    world.step(1.0 / 60.0);
    BOOST_TEST(world.contacts().size() > 2048u); // enough touching manifolds for blocks
}

// Oracle: as above, with 1120 revolute joints: with contact regions, the joints are split too
// (JointStreams), and the runs' joints solved on several threads at once.
BOOST_AUTO_TEST_CASE(jointed_chains_are_bitwise_identical_on_every_thread_count,
                     *utf::label("determinism")) {
    for (const int regions : {1, 4}) {
        BOOST_TEST_CONTEXT("contact_regions = " << regions) {
            WorldDef def;
            def.gravity = {0.0, -10.0};
            def.contact_regions = regions;
            check_every_threading(def, chains, 10 * step_scale);
        }
    }
}

// Oracle: as above, with 1380 joints of every kind and every part (limits, motors, springs),
// 210 of them on an immovable body (30 static pins, 180 target joints), which the split leaves
// to the stream after the runs: each kind writes only its record and its two bodies.
BOOST_AUTO_TEST_CASE(joints_of_every_kind_are_bitwise_identical_on_every_thread_count,
                     *utf::label("determinism")) {
    for (const int regions : {1, 2, 3}) {
        BOOST_TEST_CONTEXT("contact_regions = " << regions) {
            WorldDef def;
            def.gravity = {0.0, -10.0};
            def.contact_regions = regions;
            check_every_threading(def, every_kind_chains, 10 * step_scale);
        }
    }
}

// Oracle: the pool's contract: destroying a World joins its threads and returns, however soon
// after they were started. (A thread that first read the bell after the destructor rang it
// slept through the ring, and the join waited forever: a hang this loop met within a few
// hundred worlds.)
BOOST_AUTO_TEST_CASE(a_pool_destroyed_as_soon_as_made_stops, *utf::label("reliability")) {
    for (int i = 0; i < 2000; ++i) {
        WorldDef def;
        def.workers = 2 + i % 3;
        World w(def);
        if (i % 2 == 1)
            w.step(1.0 / 60.0); // a step that runs no parallel loop (no bodies)
    }
    BOOST_TEST(true); // reaching here is the test; CTest's timeout catches a hang
}

// Oracle: the rules stated in world_def.hpp (workers in [1, 256]; both callbacks or neither).
BOOST_AUTO_TEST_CASE(bad_thread_settings_are_refused, *utf::label("reliability")) {
    WorldDef def;
    def.workers = 0;
    BOOST_CHECK_THROW(World{def}, ValidationError);
    def.workers = 257;
    BOOST_CHECK_THROW(World{def}, ValidationError);
    def.workers = 2;
    def.task_system.enqueue = &ScramblingTasks::enqueue;
    BOOST_CHECK_THROW(World{def}, ValidationError);
    def.task_system.finish = &ScramblingTasks::finish;
    BOOST_CHECK_NO_THROW(World{def});
}

BOOST_AUTO_TEST_SUITE_END()
