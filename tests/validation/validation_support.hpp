// Shared helpers of the R4 tests: a world in motion to mutate, a snapshot of its complete state,
// and expectations that a call is rejected with the right field and data-constraint label while
// leaving the world bit-for-bit unchanged (the strong guarantee, ARCHITECTURE invariant 5).
#pragma once

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d::test {

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();
inline constexpr double inf = std::numeric_limits<double>::infinity();
/// The non-finite values every real input must reject (DCX_finite).
inline constexpr double non_finite[] = {nan, inf, -inf};

/// A small world in motion: a static ground, a box resting on it, a falling ball and a spinning
/// plate, stepped 10 times so that time, velocities, contacts and impulses are all non-trivial.
struct MovingWorld {
    World world;
    BodyId ground, box, ball, plate;

    MovingWorld() : world(make_def()) {
        BodyDef g;
        g.type = BodyType::static_body;
        g.name = "ground";
        g.position = {0.0, -0.5};
        ground = world.create_body(g);
        world.create_shape(ground, box_shape(20.0, 1.0, Material{1.0, 0.0, 0.6}));

        BodyDef b;
        b.name = "box";
        b.position = {0.0, 0.5};
        box = world.create_body(b);
        world.create_shape(box, box_shape(1.0, 1.0, Material{1.0, 0.0, 0.6}));

        BodyDef c;
        c.name = "ball";
        c.position = {3.0, 2.0};
        c.linear_velocity = {-0.5, 0.0};
        ball = world.create_body(c);
        world.create_shape(ball, circle_shape(0.5, Material{2.0, 0.5, 0.2}));

        BodyDef p;
        p.name = "plate";
        p.position = {-4.0, 5.0};
        p.angular_velocity = 2.1;
        p.gravity_scale = 0.0;
        plate = world.create_body(p);
        world.create_shape(plate, box_shape(2.0, 0.5));

        for (int i = 0; i < 10; ++i)
            world.step(1.0 / 60.0);
    }

    static WorldDef make_def() {
        WorldDef d;
        d.gravity = {0.0, -10.0};
        return d;
    }
};

struct Snapshot {
    std::uint64_t hash;
    std::size_t bodies;
    double time;
};

inline Snapshot snapshot(const World& w) {
    return {w.state_hash(), w.body_count(), w.time()};
}

inline void check_unchanged(const Snapshot& before, const World& w) {
    const Snapshot after = snapshot(w);
    BOOST_TEST(after.hash == before.hash,
               "state_hash changed: the rejected call mutated the world");
    BOOST_TEST(after.bodies == before.bodies);
    BOOST_TEST(after.time == before.time);
}

inline bool same_value(double a, double b) {
    return (std::isnan(a) && std::isnan(b)) || a == b;
}

/// `call` must throw ValidationError whose field contains `field`, whose constraint is `label`,
/// and whose message names both. Returns the error (empty if none or another was thrown).
template <class F>
std::optional<ValidationError> expect_validation_error(F&& call, std::string_view field,
                                                       std::string_view label) {
    try {
        call();
    } catch (const ValidationError& e) {
        const std::string_view what = e.what();
        BOOST_TEST(e.field.find(field) != std::string::npos,
                   "field '" << e.field << "' should name '" << field << "'");
        BOOST_TEST(e.constraint == label, "constraint " << e.constraint << ", expected " << label);
        BOOST_TEST(what.find(e.field) != std::string_view::npos, "message: " << what);
        BOOST_TEST(what.find(label) != std::string_view::npos, "message: " << what);
        return e;
    } catch (const std::exception& e) {
        BOOST_ERROR("expected ValidationError(" << field << ", " << label
                                                << "), got another exception: " << e.what());
        return std::nullopt;
    }
    BOOST_ERROR("expected ValidationError(" << field << ", " << label << "), nothing thrown");
    return std::nullopt;
}

/// As expect_validation_error, and the world's complete state is unchanged afterwards.
template <class F>
std::optional<ValidationError> expect_rejected(World& w, F&& call, std::string_view field,
                                               std::string_view label) {
    const Snapshot before = snapshot(w);
    auto e = expect_validation_error(std::forward<F>(call), field, label);
    check_unchanged(before, w);
    return e;
}

/// Same, also checking the offending value is reported (NaN matches NaN).
template <class F>
void expect_rejected_value(World& w, F&& call, std::string_view field, std::string_view label,
                           double value) {
    const auto e = expect_rejected(w, std::forward<F>(call), field, label);
    if (e)
        BOOST_TEST(same_value(e->value, value),
                   "reported value " << e->value << ", expected " << value);
}

} // namespace tamias2d::test
