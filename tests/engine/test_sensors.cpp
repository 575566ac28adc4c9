// Sensors (DD28, R7) in the world: begin and end overlap events against the analytic schedule
// of discs crossing a sensor at constant velocity, no force on anything, sensors blind to each
// other and to rays, end events on destruction, and a deterministic order.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0, half_width = 1.0, radius = 0.25;

struct Crossing {
    BodyId disc;
    ShapeId shape;
    double x0, speed;
};

/// A static sensor box 2 m x 2 m at the origin and discs of radius 0.25 m starting to its left
/// at different heights and speeds, in a world without gravity.
struct Gate {
    World world{WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false}};
    ShapeId sensor;
    std::vector<Crossing> discs;
    Gate() {
        BodyDef sd;
        sd.type = BodyType::static_body;
        const BodyId post = world.create_body(sd);
        ShapeDef s = box_shape(2.0 * half_width, 2.0 * half_width);
        s.is_sensor = true;
        sensor = world.create_shape(post, s);
        const double speeds[] = {3.1, 5.7, 9.3, 1.37};
        for (int i = 0; i < 4; ++i) {
            BodyDef bd;
            bd.position = {-3.0 - 0.37 * i, -0.825 + 0.55 * i}; // rows apart: no disc hits another
            bd.linear_velocity = {speeds[i], 0.0};
            const BodyId d = world.create_body(bd);
            discs.push_back(
                {d, world.create_shape(d, circle_shape(radius)), bd.position.x, speeds[i]});
        }
    }
};

/// The first step after which a disc's centre, x0 + v t, is beyond `edge` (strictly): the
/// analytic schedule of its overlap (the disc overlaps the box while |x| < half_width + r,
/// its centre's height being inside the box's).
int first_step_beyond(double x0, double v, double edge) {
    return int(std::floor((edge - x0) / (v * dt))) + 1;
}

} // namespace

BOOST_AUTO_TEST_SUITE(sensors)

// Oracle: the analytic schedule. Disc i overlaps the sensor from the first step its centre is
// past -(w + r) to the first step it is past w + r: one begin and one end event each, at exactly
// those steps, naming the sensor first; and the sensor exerts no force: every disc keeps its
// velocity to the bit.
BOOST_AUTO_TEST_CASE(events_follow_the_crossing_schedule, *utf::label("DD28") * utf::label("R7")) {
    Gate gate;
    std::vector<int> begin_step(gate.discs.size(), -1), end_step(gate.discs.size(), -1);
    for (int k = 1; k <= 400; ++k) {
        gate.world.step(dt);
        for (const auto& [events, steps] :
             {std::pair{gate.world.sensor_begin_events(), &begin_step},
              std::pair{gate.world.sensor_end_events(), &end_step}}) {
            for (const SensorEvent& e : events) {
                BOOST_TEST_REQUIRE((e.sensor == gate.sensor));
                for (std::size_t i = 0; i < gate.discs.size(); ++i) {
                    if (e.visitor == gate.discs[i].shape) {
                        BOOST_TEST_REQUIRE((*steps)[i] == -1); // once
                        (*steps)[i] = k;
                    }
                }
            }
        }
    }
    for (std::size_t i = 0; i < gate.discs.size(); ++i) {
        const Crossing& c = gate.discs[i];
        // The schedule is unambiguous: no crossing falls within 5 % of a step of a step's end.
        for (const double edge : {-(half_width + radius), half_width + radius}) {
            const double steps = (edge - c.x0) / (c.speed * dt);
            BOOST_TEST_REQUIRE(std::abs(steps - std::round(steps)) >= 0.05);
        }
        BOOST_TEST_CONTEXT("disc " << i) {
            BOOST_TEST(begin_step[i] == first_step_beyond(c.x0, c.speed, -(half_width + radius)));
            // Leaving: the first step after which the centre is at or past +(w + r).
            BOOST_TEST(end_step[i] == first_step_beyond(c.x0, c.speed, half_width + radius));
            BOOST_TEST(gate.world.velocity(c.disc).x == c.speed);
            BOOST_TEST(gate.world.velocity(c.disc).y == 0.0);
        }
    }
    BOOST_TEST(gate.world.contacts().empty()); // a sensor's pairs are not contacts
}

// Oracle: the stated rules. Two overlapping sensors report nothing; a ray through a sensor
// hits what lies behind it; destroying a disc inside the sensor ends its overlap at once, and
// destroying a sensor ends its own overlaps only.
BOOST_AUTO_TEST_CASE(sensors_are_blind_to_sensors_and_rays,
                     *utf::label("DD28") * utf::label("R7")) {
    World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false});
    ShapeDef sensor = box_shape(2.0, 2.0);
    sensor.is_sensor = true;
    const BodyId a = world.create_body(BodyDef{});
    const ShapeId sensor_a = world.create_shape(a, sensor);
    BodyDef bd;
    bd.position = {0.5, 0.0};
    const BodyId b = world.create_body(bd);
    const ShapeId sensor_b = world.create_shape(b, sensor);
    BodyDef wall_def;
    wall_def.type = BodyType::static_body;
    wall_def.position = {3.0, 0.0};
    const BodyId wall = world.create_body(wall_def);
    world.create_shape(wall, box_shape(1.0, 4.0));
    world.step(dt);
    BOOST_TEST(world.sensor_begin_events().empty());
    const auto hit = world.ray_cast({-3.0, 0.0}, {10.0, 0.0});
    BOOST_TEST_REQUIRE(hit.has_value());
    BOOST_TEST((hit->body == wall));
    // A solid disc inside sensor a: one begin event, then an end event when it is destroyed.
    BodyDef dd;
    dd.position = {-0.5, 0.0};
    const BodyId disc = world.create_body(dd);
    world.create_shape(disc, circle_shape(0.2));
    world.step(dt);
    BOOST_TEST(world.sensor_begin_events().size() == 2u); // inside both sensors
    world.destroy_body(disc);
    BOOST_TEST(world.sensor_end_events().size() == 2u);
    // Another disc inside both; destroying the second sensor ends its overlap alone, and the
    // first keeps reporting: no event while the disc stays, one when it leaves.
    const BodyId other = world.create_body(dd);
    const ShapeId other_shape = world.create_shape(other, circle_shape(0.2));
    world.step(dt);
    BOOST_TEST(world.sensor_begin_events().size() == 2u);
    world.destroy_shape(sensor_b);
    BOOST_TEST_REQUIRE(world.sensor_end_events().size() == 1u);
    BOOST_TEST((world.sensor_end_events()[0].sensor == sensor_b));
    world.step(dt);
    BOOST_TEST(world.sensor_begin_events().empty());
    BOOST_TEST(world.sensor_end_events().empty());
    world.set_transform(other, {-5.0, 0.0}, 0.0);
    world.step(dt);
    BOOST_TEST_REQUIRE(world.sensor_end_events().size() == 1u);
    BOOST_TEST((world.sensor_end_events()[0].sensor == sensor_a));
    BOOST_TEST((world.sensor_end_events()[0].visitor == other_shape));
}

// Oracle: determinism (the same inputs give the same events in the same order), the stated
// order being the pairs' storage order.
BOOST_AUTO_TEST_CASE(events_are_deterministic, *utf::label("DD28") * utf::label("R7")) {
    const auto record = [] {
        Gate gate;
        std::vector<std::uint32_t> log;
        for (int k = 0; k < 300; ++k) {
            gate.world.step(dt);
            for (const SensorEvent& e : gate.world.sensor_begin_events())
                log.push_back(e.visitor.index * 2);
            for (const SensorEvent& e : gate.world.sensor_end_events())
                log.push_back(e.visitor.index * 2 + 1);
        }
        return std::pair{log, gate.world.state_hash()};
    };
    BOOST_TEST((record() == record()));
}

// Oracle: DD28's statement, the boundary of an overlap: a sensor and a shape overlap when their
// signed distance is negative, so a shape touching the sensor along a face is no visitor. A
// 1 m box at rest with its left face exactly on the 2 m sensor box's right face (x = 1: both
// faces' places are exact doubles, so their separation is exactly 0) is not in
// sensor_overlaps; 1 mm further in it is, 1 mm further out it is not.
BOOST_AUTO_TEST_CASE(a_shape_touching_the_sensor_is_no_visitor, *utf::label("DD28")) {
    for (const double x : {half_width + 0.5, half_width + 0.5 - 1e-3, half_width + 0.5 + 1e-3}) {
        Gate gate;
        BodyDef bd;
        bd.position = {x, 0.0};
        const BodyId b = gate.world.create_body(bd);
        const ShapeId box = gate.world.create_shape(b, box_shape(1.0, 1.0));
        gate.world.step(dt);
        const std::vector<ShapeId> inside = gate.world.sensor_overlaps(gate.sensor);
        const bool seen = std::find(inside.begin(), inside.end(), box) != inside.end();
        BOOST_TEST(seen == (x < half_width + 0.5), "the box's centre at x = " << x);
    }
}

// Oracle: the analytic schedule, sensor and visitor swapped: a sensor disc on a moving body
// crossing a static box overlaps it from the first step its centre is past -(w + r) to the
// first step past w + r, and the box, being static, is seen like any other shape.
BOOST_AUTO_TEST_CASE(a_moving_sensor_sees_a_static_shape, *utf::label("DD28")) {
    World world{WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false}};
    BodyDef wd;
    wd.type = BodyType::static_body;
    const BodyId wall = world.create_body(wd);
    const ShapeId box = world.create_shape(wall, box_shape(2.0 * half_width, 2.0 * half_width));
    const double x0 = -3.13, speed = 4.3;
    BodyDef bd;
    bd.position = {x0, 0.2};
    bd.linear_velocity = {speed, 0.0};
    const BodyId probe = world.create_body(bd);
    ShapeDef s = circle_shape(radius);
    s.is_sensor = true;
    const ShapeId sensor = world.create_shape(probe, s);
    int begin = -1, end = -1;
    for (int k = 1; k <= 200; ++k) {
        world.step(dt);
        for (const SensorEvent& e : world.sensor_begin_events()) {
            BOOST_TEST_REQUIRE(((e.sensor == sensor) && (e.visitor == box) && begin == -1));
            begin = k;
        }
        for (const SensorEvent& e : world.sensor_end_events()) {
            BOOST_TEST_REQUIRE(((e.sensor == sensor) && (e.visitor == box) && end == -1));
            end = k;
        }
    }
    for (const double edge : {-(half_width + radius), half_width + radius}) {
        const double steps = (edge - x0) / (speed * dt); // unambiguous: not near a step's end
        BOOST_TEST_REQUIRE(std::abs(steps - std::round(steps)) >= 0.05);
    }
    BOOST_TEST(begin == first_step_beyond(x0, speed, -(half_width + radius)));
    BOOST_TEST(end == first_step_beyond(x0, speed, half_width + radius));
    BOOST_TEST(world.contacts().empty());
}

BOOST_AUTO_TEST_SUITE_END()
