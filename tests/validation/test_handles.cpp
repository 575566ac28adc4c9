// R4 (and ARCHITECTURE invariant 6): a handle to a destroyed body or shape, or one never issued,
// is an error (InvalidHandle), not a crash or a silent access to a recycled slot, and the
// rejected call leaves the world unchanged.
#include <boost/test/unit_test.hpp>

#include <functional>
#include <string>
#include <vector>

#include "support/body_changes.hpp"
#include "validation_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::test;

namespace {

/// Every World member that takes a BodyId, called with `id`.
std::vector<BodyCall> body_calls() {
    std::vector<BodyCall> calls = body_changes();
    std::vector<BodyCall> others = {
        {"state", [](World& w, BodyId id) { (void)w.state(id); }},
        {"position", [](World& w, BodyId id) { (void)w.position(id); }},
        {"origin", [](World& w, BodyId id) { (void)w.origin(id); }},
        {"orientation", [](World& w, BodyId id) { (void)w.orientation(id); }},
        {"velocity", [](World& w, BodyId id) { (void)w.velocity(id); }},
        {"angular_velocity", [](World& w, BodyId id) { (void)w.angular_velocity(id); }},
        {"mass", [](World& w, BodyId id) { (void)w.mass(id); }},
        {"inertia", [](World& w, BodyId id) { (void)w.inertia(id); }},
        {"local_center", [](World& w, BodyId id) { (void)w.local_center(id); }},
        {"type", [](World& w, BodyId id) { (void)w.type(id); }},
        {"name", [](World& w, BodyId id) { (void)w.name(id); }},
        {"shapes", [](World& w, BodyId id) { (void)w.shapes(id); }},
        {"is_awake", [](World& w, BodyId id) { (void)w.is_awake(id); }},
        {"set_awake", [](World& w, BodyId id) { w.set_awake(id, false); }},
        {"create_shape", [](World& w, BodyId id) { w.create_shape(id, circle_shape(0.5)); }},
        {"destroy_body", [](World& w, BodyId id) { w.destroy_body(id); }},
    };
    calls.insert(calls.end(), others.begin(), others.end());
    return calls;
}

void expect_invalid_handle(World& w, const std::function<void()>& call) {
    const Snapshot before = snapshot(w);
    BOOST_CHECK_THROW(call(), InvalidHandle);
    check_unchanged(before, w);
}

} // namespace

BOOST_AUTO_TEST_SUITE(handles)

// Oracle: the handle contract in handles.hpp (index, generation, world tag) and World's
// documentation: a destroyed body's handle, one with a wrong generation, one never issued, one
// of another world (naming a live slot of this one) and the null handle are all rejected by
// every call that takes a BodyId, and is_valid says false.
BOOST_AUTO_TEST_CASE(stale_and_unknown_body_handles_are_rejected, *utf::label("R4")) {
    MovingWorld m;
    BodyDef d;
    d.name = "doomed";
    const BodyId dead = m.world.create_body(d);
    m.world.create_shape(dead, circle_shape(0.5));
    m.world.destroy_body(dead);
    const BodyId reused = m.world.create_body(BodyDef{}); // may recycle dead's slot
    m.world.step(1.0 / 60.0);

    const World other;
    const std::uint32_t tag = m.world.tag();
    const std::vector<std::pair<std::string, BodyId>> bad = {
        {"destroyed", dead},
        {"wrong generation", BodyId{m.box.index, m.box.generation + 1, tag}},
        {"never issued", BodyId{12345, 1, tag}},
        {"another world's", BodyId{m.box.index, m.box.generation, other.tag()}},
        {"null", BodyId{}},
    };
    for (const auto& [what, id] : bad) {
        BOOST_TEST_CONTEXT(what << " handle " << id.index << ":" << id.generation) {
            BOOST_TEST(!m.world.is_valid(id));
            for (const auto& [call, f] : body_calls()) {
                BOOST_TEST_CONTEXT("World::" << call) {
                    expect_invalid_handle(m.world, [&, &f = f, &id = id] { f(m.world, id); });
                }
            }
        }
    }
    // The live handles still work, including the one that reused the slot.
    BOOST_TEST(m.world.is_valid(reused));
    BOOST_TEST(m.world.is_valid(m.box));
    BOOST_CHECK_NO_THROW(m.world.state(reused));
}

// Oracle: as above, for ShapeId: destroying a shape twice, a wrong generation, a never issued
// handle and one of another world are rejected by destroy_shape, and is_valid says false.
BOOST_AUTO_TEST_CASE(stale_and_unknown_shape_handles_are_rejected, *utf::label("R4")) {
    MovingWorld m;
    const ShapeId extra = m.world.create_shape(m.box, circle_shape(0.25));
    m.world.destroy_shape(extra);
    const ShapeId live = m.world.shapes(m.box).front();
    const std::vector<std::pair<std::string, ShapeId>> bad = {
        {"destroyed", extra},
        {"wrong generation", ShapeId{live.index, live.generation + 1, live.world}},
        {"never issued", ShapeId{9999, 1, live.world}},
        {"another world's", ShapeId{live.index, live.generation, live.world + 1}},
        {"null", ShapeId{}},
    };
    for (const auto& [what, id] : bad) {
        BOOST_TEST_CONTEXT(what) {
            BOOST_TEST(!m.world.is_valid(id));
            expect_invalid_handle(m.world, [&, id = id] { m.world.destroy_shape(id); });
        }
    }
    // Shapes of a destroyed body die with it.
    const std::vector<ShapeId> ball_shapes = m.world.shapes(m.ball);
    m.world.destroy_body(m.ball);
    for (const ShapeId s : ball_shapes) {
        BOOST_TEST(!m.world.is_valid(s));
        expect_invalid_handle(m.world, [&] { m.world.destroy_shape(s); });
    }
    BOOST_TEST(m.world.is_valid(live));
}

BOOST_AUTO_TEST_SUITE_END()
