// The shape_control calls' promises (the user guide's "Changing shapes"): a refused value or a
// stale handle throws the named error and leaves state_hash() unchanged; a value equal to the
// current one changes no bit of the simulation; the results are the same on 1 to 4 workers.
// Library guarantees, not SRS physics: labelled "reliability" and "determinism".
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

/// A small pile: a floor, boxes and discs falling on it, one box on a revolute joint to the
/// floor (its anchor 1 m from the box's centre), sleeping as asked.
struct Pile {
    World w;
    ShapeId floor, box, disc, hinged, chain;
    BodyId hinged_body;
    explicit Pile(bool sleeping = true, int workers = 1)
        : w([&] {
              WorldDef d;
              d.enable_sleep = sleeping;
              d.workers = workers;
              return d;
          }()) {
        BodyDef gd;
        gd.type = BodyType::static_body;
        const BodyId ground = w.create_body(gd);
        floor = w.create_shape(ground, box_shape(20.0, 1.0));
        const std::vector<Vec2d> pts{{-8.0, 3.0}, {-6.0, 2.0}};
        chain = w.create_chain(ground, chain_shapes(pts, false))[0];
        for (int i = 0; i < 6; ++i) {
            BodyDef bd;
            bd.position = {-2.0 + 0.7 * i, 1.0 + 0.9 * i};
            const BodyId b = w.create_body(bd);
            const ShapeId s =
                w.create_shape(b, i % 2 == 0 ? box_shape(0.5, 0.5, Material{1.0, 0.2, 0.6})
                                             : circle_shape(0.3, Material{2.0, 0.1, 0.4}));
            (i == 0 ? box : disc) = s;
        }
        BodyDef hd;
        hd.position = {5.0, 2.0};
        hinged_body = w.create_body(hd);
        hinged = w.create_shape(hinged_body, box_shape(1.0, 1.0));
        RevoluteJointDef j;
        j.body_a = ground;
        j.body_b = hinged_body;
        j.anchor = {6.0, 2.0};
        w.create_joint(j);
    }
    void steps(int n) {
        for (int k = 0; k < n; ++k)
            w.step(dt);
    }
};

/// Calls `call` expecting a refusal of type E naming `field` (a ValidationError's field, any
/// non-empty one when `field` is empty; or text of the message); the hash must not change.
template <class E> void refused(World& w, const std::function<void()>& call, std::string field) {
    const std::uint64_t before = w.state_hash();
    bool thrown = false;
    try {
        call();
    } catch (const E& e) {
        thrown = true;
        if constexpr (std::is_same_v<E, ValidationError>)
            BOOST_TEST((field.empty() ? !e.field.empty() : e.field == field));
        else
            BOOST_TEST(std::string(e.what()).find(field) != std::string::npos);
    }
    BOOST_TEST(thrown);
    BOOST_TEST(w.state_hash() == before);
}

} // namespace

BOOST_AUTO_TEST_SUITE(shape_control_guarantees)

// Oracle: R4's promise (docs/user-guide.md, "Errors"): each value out of its data constraint is
// refused naming the field, a chain's segment is refused as WrongKind naming the shape, a stale
// handle as InvalidHandle, and the world's hash is unchanged after each.
BOOST_AUTO_TEST_CASE(bad_values_are_refused_and_change_nothing, *utf::label("R4")) {
    Pile p;
    p.steps(30);
    World& w = p.w;
    refused<ValidationError>(
        w, [&] { w.set_friction(p.box, -0.1); }, "material.friction");
    refused<ValidationError>(
        w, [&] { w.set_friction(p.box, not_a_number); }, "material.friction");
    refused<ValidationError>(
        w, [&] { w.set_restitution(p.box, 1.5); }, "material.restitution");
    refused<ValidationError>(
        w, [&] { w.set_density(p.box, 0.0); }, "material.density");
    refused<ValidationError>(
        w, [&] { w.set_density(p.box, not_a_number, false); }, "material.density");
    refused<ValidationError>(
        w,
        [&] {
            w.set_circle(p.disc, Circle{{0.0, 0.0}, -1.0});
        },
        "");
    refused<ValidationError>(
        w,
        [&] {
            w.set_circle(p.disc, Circle{{not_a_number, 0.0}, 1.0});
        },
        "");
    refused<ValidationError>(
        w,
        [&] {
            w.set_capsule(p.disc, Capsule{{0.0, 0.0}, {0.0, 0.0}, 0.5});
        },
        "");
    Polygon flat = box_shape(1.0, 1.0).geometry.polygon;
    flat.vertices[2] = flat.vertices[1]; // two vertices on one point: degenerate
    try {
        w.set_polygon(p.box, flat);
        BOOST_ERROR("a degenerate polygon was accepted");
    } catch (const ValidationError& e) {
        BOOST_TEST(!e.field.empty());
        BOOST_TEST(e.constraint == "DCX_shape");
    }
    refused<ValidationError>(
        w,
        [&] {
            w.set_segment(p.disc, Segment{{1.0, 1.0}, {1.0, 1.0}});
        },
        "");
    refused<WrongKind>(
        w,
        [&] {
            w.set_circle(p.chain, Circle{{0.0, 0.0}, 1.0});
        },
        "shape[" + std::to_string(p.chain.index) + "]");
    const ShapeId stale{p.box.index, p.box.generation + 7};
    refused<InvalidHandle>(
        w, [&] { w.set_friction(stale, 0.5); }, "ShapeId");
    refused<InvalidHandle>(
        w, [&] { w.set_sensor(stale, true); }, "ShapeId");
    refused<InvalidHandle>(
        w, [&] { (void)w.friction(stale); }, "ShapeId");
}

// Oracle: DCX_joint's lever rule, as create_joint applies it. Shrinking the hinged box to a
// disc of 1e-5 m would put the joint's anchor, 1 m away, about 1.4e5 radii of gyration from
// the centre of mass (beyond 1e5): refused naming the joint's anchor, with the geometry and the
// mass as they were (the hash unchanged).
BOOST_AUTO_TEST_CASE(a_change_beyond_a_joints_lever_is_refused, *utf::label("DCX_joint")) {
    Pile p;
    World& w = p.w;
    const double mass = w.mass(p.hinged_body);
    const std::uint64_t before = w.state_hash();
    try {
        w.set_circle(p.hinged, Circle{{0.0, 0.0}, 1e-5});
        BOOST_ERROR("accepted");
    } catch (const ValidationError& e) {
        BOOST_TEST(e.constraint == "DCX_joint");
        BOOST_TEST(e.field.find("anchor") != std::string::npos);
    }
    BOOST_TEST(w.state_hash() == before);
    BOOST_TEST(w.mass(p.hinged_body) == mass);
    BOOST_TEST((w.shape_geometry(p.hinged).type == ShapeType::polygon));
}

// Oracle: the promise that a value set to what it already is changes nothing. Two piles, one
// given every setter with its shape's current value part way (the sleeping bodies must not be
// woken), step alike: their hashes agree after every step.
BOOST_AUTO_TEST_CASE(setting_the_current_value_changes_no_bit, *utf::label("reliability")) {
    Pile a, b;
    a.steps(200); // long enough for some to sleep
    b.steps(200);
    World& w = b.w;
    for (const ShapeId s : {b.box, b.disc, b.floor, b.hinged}) {
        w.set_friction(s, w.friction(s));
        w.set_restitution(s, w.restitution(s));
        w.set_density(s, w.density(s), false);
        w.set_density(s, w.density(s), true);
        w.set_sensor(s, w.is_sensor(s));
        const Geometry g = w.shape_geometry(s);
        if (g.type == ShapeType::circle)
            w.set_circle(s, g.circle);
        else
            w.set_polygon(s, g.polygon);
    }
    BOOST_TEST(a.w.state_hash() == w.state_hash());
    for (int k = 0; k < 60; ++k) {
        a.w.step(dt);
        w.step(dt);
        BOOST_TEST_REQUIRE(a.w.state_hash() == w.state_hash());
    }
}

// Oracle: determinism (docs/design.md, "Determinism"): the same calls give the same hash on 1
// to 4 workers.
BOOST_AUTO_TEST_CASE(changes_give_equal_results_on_1_to_4_workers, *utf::label("determinism")) {
    std::vector<std::uint64_t> hashes;
    for (int workers = 1; workers <= 4; ++workers) {
        Pile p(true, workers);
        p.steps(20);
        p.w.set_friction(p.box, 0.05);
        p.w.set_restitution(p.disc, 0.8);
        p.w.set_density(p.box, 4.0);
        p.w.set_capsule(p.disc, Capsule{{-0.2, 0.0}, {0.2, 0.0}, 0.25});
        p.steps(20);
        p.w.set_sensor(p.box, true);
        p.w.set_polygon(p.hinged, box_shape(1.2, 0.8).geometry.polygon);
        p.steps(20);
        p.w.set_sensor(p.box, false);
        p.steps(60);
        hashes.push_back(p.w.state_hash());
    }
    for (std::size_t k = 1; k < hashes.size(); ++k)
        BOOST_TEST(hashes[k] == hashes[0]);
}

BOOST_AUTO_TEST_SUITE_END()
