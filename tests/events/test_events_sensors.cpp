// Current sensor overlaps (World::sensor_overlaps) against the running set their begin and end
// events build and against the analytic overlap of discs crossing a box; the per-shape switch.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0, half_width = 1.0, radius = 0.25;

/// A static 2 m x 2 m sensor box at the origin and four discs (radius 0.25 m) crossing it
/// left to right at constant speeds, on rows 0.55 m apart, without gravity.
struct Gate {
    World world{WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false}};
    ShapeId sensor;
    std::vector<BodyId> discs;
    std::vector<ShapeId> disc_shapes;
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
            bd.position = {-3.0 - 0.37 * i, -0.825 + 0.55 * i};
            bd.linear_velocity = {speeds[i], 0.0};
            discs.push_back(world.create_body(bd));
            disc_shapes.push_back(world.create_shape(discs.back(), circle_shape(radius)));
        }
    }
    /// The running set: begin events add, end events remove (this sensor's only).
    void apply_events(std::set<std::uint32_t>& set) const {
        for (const SensorEvent& e : world.sensor_begin_events())
            if (e.sensor == sensor)
                BOOST_TEST(set.insert(e.visitor.index).second);
        for (const SensorEvent& e : world.sensor_end_events())
            if (e.sensor == sensor)
                BOOST_TEST(set.erase(e.visitor.index) == 1u);
    }
    std::set<std::uint32_t> overlaps() const {
        std::set<std::uint32_t> out;
        for (const ShapeId s : world.sensor_overlaps(sensor))
            out.insert(s.index);
        return out;
    }
};

} // namespace

BOOST_AUTO_TEST_SUITE(events_sensors)

// Oracle: geometry, closed form. A disc whose centre's height lies inside the box overlaps it
// exactly while |x| < half_width + r (its centre x after the step read back from the world);
// a margin of 1e-9 m leaves out the instants of tangency. And the events' running set equals
// the overlaps after every step.
BOOST_AUTO_TEST_CASE(sensor_overlaps_are_the_analytic_overlaps_and_the_events_set,
                     *utf::label("DD28")) {
    Gate gate;
    std::set<std::uint32_t> running;
    int overlapping_steps = 0;
    for (int s = 0; s < 260; ++s) { // the slowest disc leaves at about step 235
        gate.world.step(dt);
        gate.apply_events(running);
        const std::set<std::uint32_t> now = gate.overlaps();
        BOOST_TEST((running == now));
        const auto list = gate.world.sensor_overlaps(gate.sensor);
        BOOST_TEST(std::is_sorted(list.begin(), list.end(),
                                  [](ShapeId a, ShapeId b) { return a.index < b.index; }));
        for (std::size_t i = 0; i < gate.discs.size(); ++i) {
            const double x = gate.world.position(gate.discs[i]).x;
            const double reach = half_width + radius;
            if (std::abs(std::abs(x) - reach) < 1e-9)
                continue;
            const bool inside = std::abs(x) < reach;
            BOOST_TEST(now.count(gate.disc_shapes[i].index) == (inside ? 1u : 0u));
            overlapping_steps += inside ? 1 : 0;
        }
    }
    BOOST_TEST(overlapping_steps > 50);
    BOOST_TEST(running.empty()); // all have left
}

// Oracle: the switch's stated rule. A visitor switched off leaves the sensor's overlaps at the
// next step with an end event (the running set still equals the overlaps), and comes back with
// a begin event when switched on; a sensor switched off detects nothing, ending every overlap.
BOOST_AUTO_TEST_CASE(switching_sensor_events_keeps_the_set_and_the_events_equal) {
    Gate gate;
    std::set<std::uint32_t> running;
    const ShapeId slow = gate.disc_shapes[3]; // 1.37 m/s: inside from about step 126 to 235
    int steps = 0;
    auto step = [&] {
        gate.world.step(dt);
        ++steps;
        gate.apply_events(running);
        BOOST_TEST((running == gate.overlaps()));
    };
    while (gate.overlaps().count(slow.index) == 0 && steps < 200)
        step();
    BOOST_TEST_REQUIRE(gate.overlaps().count(slow.index) == 1u);
    gate.world.set_sensor_events_enabled(slow, false);
    BOOST_TEST(!gate.world.sensor_events_enabled(slow));
    step();
    BOOST_TEST(gate.overlaps().count(slow.index) == 0u);
    gate.world.set_sensor_events_enabled(slow, true);
    step();
    BOOST_TEST(gate.overlaps().count(slow.index) == 1u);
    gate.world.set_sensor_events_enabled(gate.sensor, false);
    step();
    BOOST_TEST(gate.overlaps().empty());
    step();
    BOOST_TEST(gate.world.sensor_begin_events().empty());
    gate.world.set_sensor_events_enabled(gate.sensor, true);
    step();
    BOOST_TEST(gate.overlaps().count(slow.index) == 1u);
}

// Oracle: the call's stated errors: a shape that is not a sensor is WrongKind naming it, a
// destroyed one InvalidHandle; neither changes the world.
BOOST_AUTO_TEST_CASE(sensor_overlaps_refuses_what_is_no_sensor) {
    Gate gate;
    const std::uint64_t before = gate.world.state_hash();
    BOOST_CHECK_THROW((void)gate.world.sensor_overlaps(gate.disc_shapes[0]), WrongKind);
    try {
        (void)gate.world.sensor_overlaps(gate.disc_shapes[0]);
    } catch (const WrongKind& e) {
        BOOST_TEST(e.call == "sensor_overlaps");
        BOOST_TEST(e.subject == "shape[" + std::to_string(gate.disc_shapes[0].index) + "]");
    }
    gate.world.destroy_shape(gate.disc_shapes[1]);
    const std::uint64_t after_destroy = gate.world.state_hash();
    BOOST_CHECK_THROW((void)gate.world.sensor_overlaps(gate.disc_shapes[1]), InvalidHandle);
    BOOST_TEST(gate.world.state_hash() == after_destroy);
    BOOST_TEST(before != after_destroy);
    BOOST_TEST(gate.world.sensor_overlaps(gate.sensor).empty()); // nothing stepped yet
}

BOOST_AUTO_TEST_SUITE_END()
