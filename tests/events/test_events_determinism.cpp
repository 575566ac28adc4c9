// Every event list in a deterministic order, equal on 1 to 4 workers: a busy scene (a pyramid
// with rain, a sensor zone, a chain of jointed links) with every event kind on, its event
// lists hashed step by step.
#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <cstring>

#include "support/pyramid.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;

/// FNV-1a over the bytes of the events' fields (bit patterns of every double).
struct Fnv {
    std::uint64_t h = 1469598103934665603ull;
    void bytes(const void* p, std::size_t n) {
        const auto* c = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) {
            h ^= c[i];
            h *= 1099511628211ull;
        }
    }
    void operator()(std::uint64_t v) { bytes(&v, sizeof v); }
    void operator()(double v) { bytes(&v, sizeof v); }
    void operator()(Vec2d v) {
        (*this)(v.x);
        (*this)(v.y);
    }
    void operator()(BodyId b) { (*this)(std::uint64_t(b.index) << 32 | b.generation); }
    void operator()(ShapeId s) { (*this)(std::uint64_t(s.index) << 32 | s.generation); }
    void operator()(JointId j) { (*this)(std::uint64_t(j.index) << 32 | j.generation); }
};

struct Hashes {
    std::uint64_t events = 0, state = 0;
    std::size_t hits = 0, moves = 0, joints = 0, sensors = 0, contacts = 0;
};

/// The busy scene on `workers` threads with `regions` contact regions, 300 steps; rain falls
/// every fifth step for the first 200.
Hashes run(int workers, int regions) {
    World w(WorldDef{.gravity = {0.0, -10.0},
                     .contact_regions = regions,
                     .enable_sleep = true,
                     .workers = workers});
    test::build_pyramid(w, 16);
    BodyDef sd;
    sd.type = BodyType::static_body;
    sd.position = {0.0, 6.0};
    ShapeDef zone = box_shape(30.0, 4.0);
    zone.is_sensor = true;
    const ShapeId sensor = w.create_shape(w.create_body(sd), zone);
    // A chain of links from a static pin, with thresholds low enough to be crossed.
    sd.position = {-18.0, 14.0};
    BodyId previous = w.create_body(sd);
    for (int k = 0; k < 6; ++k) {
        BodyDef link;
        link.position = {-17.5 + k, 14.0};
        const BodyId b = w.create_body(link);
        w.create_shape(b, box_shape(1.0, 0.2));
        w.create_joint(RevoluteJointDef{.body_a = previous,
                                        .body_b = b,
                                        .anchor = {-18.0 + k, 14.0},
                                        .force_threshold = 1.0,
                                        .torque_threshold = 0.5});
        previous = b;
    }
    for (const BodyId b : w.bodies()) {
        w.set_move_events_enabled(b, true);
        for (const ShapeId s : w.shapes(b))
            w.set_hit_events_enabled(s, true);
    }
    w.set_hit_event_threshold(0.5);
    Fnv f;
    Hashes out;
    for (int s = 0; s < 300; ++s) {
        if (s < 200 && s % 5 == 0) {
            BodyDef drop;
            drop.position = {-12.0 + 1.37 * (s / 5 % 18), 22.0};
            drop.enable_move_events = true;
            const BodyId b = w.create_body(drop);
            ShapeDef disc = circle_shape(0.3, Material{1.0, 0.3, 0.4});
            disc.enable_hit_events = true;
            w.create_shape(b, disc);
        }
        if (s == 250) // a body with joints goes: body_destroyed events
            w.destroy_body(w.bodies()[w.bodies().size() - 1 - 40]);
        w.step(dt);
        for (const ContactHitEvent& e : w.contact_hit_events()) {
            f(e.shape_a), f(e.shape_b), f(e.body_a), f(e.body_b);
            f(e.point), f(e.normal), f(e.approach_speed);
        }
        for (const BodyMoveEvent& e : w.body_move_events()) {
            f(e.body), f(e.origin), f(e.angle), f(std::uint64_t(e.fell_asleep));
        }
        for (const JointEvent& e : w.joint_events()) {
            f(e.joint), f(std::uint64_t(e.kind)), f(e.body_a), f(e.body_b), f(e.force), f(e.torque);
        }
        for (const ContactEvent& e : w.contact_begin_events())
            f(e.shape_a), f(e.shape_b);
        for (const ContactEvent& e : w.contact_end_events())
            f(e.shape_b), f(e.shape_a);
        for (const ShapeId v : w.sensor_overlaps(sensor))
            f(v);
        out.hits += w.contact_hit_events().size();
        out.moves += w.body_move_events().size();
        out.joints += w.joint_events().size();
        out.sensors += w.sensor_overlaps(sensor).size();
        out.contacts += w.contact_begin_events().size();
    }
    out.events = f.h;
    out.state = w.state_hash();
    return out;
}

} // namespace

BOOST_AUTO_TEST_SUITE(events_determinism, *boost::unit_test::label("determinism"))

// Oracle: the one-worker run (WorldDef::workers' promise: the same bits on any number of
// threads). The hashes of every event list, step by step, and of the final state are equal on
// 2, 3 and 4 workers, for one contact region and for four; every kind of event occurs.
BOOST_AUTO_TEST_CASE(event_lists_are_equal_on_one_to_four_workers) {
    for (const int regions : {1, 4}) {
        const Hashes one = run(1, regions);
        BOOST_TEST_MESSAGE("regions " << regions << ": " << one.hits << " hits, " << one.moves
                                      << " moves, " << one.joints << " joint events, "
                                      << one.sensors << " sensor overlaps, " << one.contacts
                                      << " contact begins");
        BOOST_TEST(one.hits > 0u);
        BOOST_TEST(one.moves > 0u);
        BOOST_TEST(one.joints > 0u);
        BOOST_TEST(one.sensors > 0u);
        for (const int workers : {2, 3, 4}) {
            const Hashes many = run(workers, regions);
            BOOST_TEST(many.events == one.events, "workers " << workers << ", regions " << regions);
            BOOST_TEST(many.state == one.state, "workers " << workers << ", regions " << regions);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
