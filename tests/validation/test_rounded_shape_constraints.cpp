// R4 for capsules, segments and chains (DCX_shape, DCX_finite, DCX_range): each defect is a
// ValidationError naming the field and the constraint, and the world is left exactly as it was.
#include <boost/test/unit_test.hpp>

#include <array>
#include <vector>

#include "tamias2d/geometry/shape_factory.hpp"
#include "validation_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::test;

namespace {

ShapeDef raw(const Geometry& g) {
    ShapeDef d;
    d.geometry = g;
    return d;
}

} // namespace

BOOST_AUTO_TEST_SUITE(rounded_shape_constraints)

// Oracle: DCX_shape's statement for the new kinds: a capsule's radius > 0 and its ends
// distinct; a segment's ends distinct; a chain of at least 2 points (3 for a loop) with no two
// consecutive points equal. Made by the factories or by hand, each is refused by name and the
// world is unchanged.
BOOST_AUTO_TEST_CASE(degenerate_kinds_are_refused, *utf::label("R4") * utf::label("DCX_shape")) {
    MovingWorld m;
    expect_validation_error(
        [] {
            (void)capsule_shape({0, 0}, {1, 0}, -0.5);
        },
        "capsule.radius", "DCX_shape");
    expect_validation_error(
        [] {
            (void)capsule_shape({0, 0}, {1, 0}, 0.0);
        },
        "capsule.radius", "DCX_shape");
    expect_validation_error(
        [] {
            (void)capsule_shape({1, 2}, {1, 2}, 0.5);
        },
        "capsule.length", "DCX_shape");
    expect_validation_error(
        [] {
            (void)segment_shape({1, 2}, {1, 2});
        },
        "segment.length", "DCX_shape");
    const std::array<Vec2d, 1> one = {Vec2d{0, 0}};
    expect_validation_error([&] { (void)chain_shapes(one, false); }, "chain.points.size",
                            "DCX_shape");
    const std::array<Vec2d, 2> two = {Vec2d{0, 0}, Vec2d{1, 0}};
    expect_validation_error([&] { (void)chain_shapes(two, true); }, "chain.points.size",
                            "DCX_shape");
    const std::array<Vec2d, 3> repeat = {Vec2d{0, 0}, Vec2d{1, 0}, Vec2d{1, 0}};
    expect_validation_error([&] { (void)chain_shapes(repeat, false); }, "chain.points[2].length",
                            "DCX_shape");

    // Hand-made geometry bypassing the factories: the world refuses it, unchanged.
    Geometry g;
    g.type = ShapeType::capsule;
    g.capsule = {{0, 0}, {1, 0}, -1.0};
    expect_rejected(
        m.world, [&] { m.world.create_shape(m.box, raw(g)); }, "capsule.radius", "DCX_shape");
    g.type = ShapeType::segment;
    g.segment = {{3, 3}, {3, 3}};
    expect_rejected(
        m.world, [&] { m.world.create_shape(m.box, raw(g)); }, "segment.length", "DCX_shape");
    g.type = ShapeType::chain_segment;
    g.chain_segment = {{-1, 0}, {0, 0}, {0, 0}, {1, 0}};
    expect_rejected(
        m.world, [&] { m.world.create_shape(m.box, raw(g)); }, "chain_segment.length", "DCX_shape");
}

// Oracle: DCX_finite and DCX_range for the new kinds: a NaN or infinite coordinate or radius,
// and a point beyond 1e12 m, are refused by name, the world unchanged.
BOOST_AUTO_TEST_CASE(out_of_range_values_are_refused,
                     *utf::label("R4") * utf::label("DCX_finite") * utf::label("DCX_range")) {
    MovingWorld m;
    for (const double bad : non_finite) {
        BOOST_TEST_CONTEXT("value = " << bad) {
            expect_validation_error(
                [&] {
                    (void)capsule_shape({0, 0}, {1, 0}, bad);
                },
                "capsule.radius", "DCX_finite");
            expect_validation_error(
                [&] {
                    (void)segment_shape({bad, 0}, {1, 0});
                },
                "segment.point1", "DCX_finite");
            const std::array<Vec2d, 3> pts = {Vec2d{0, 0}, Vec2d{1, bad}, Vec2d{2, 0}};
            expect_validation_error([&] { (void)chain_shapes(pts, false); }, "chain.points[1]",
                                    "DCX_finite");
        }
    }
    Geometry g;
    g.type = ShapeType::segment;
    g.segment = {{0, 0}, {2e12, 0}};
    expect_rejected(
        m.world, [&] { m.world.create_shape(m.box, raw(g)); }, "segment.point2", "DCX_range");
    g.type = ShapeType::capsule;
    g.capsule = {{0, 0}, {1, 0}, 1e-13};
    expect_rejected(
        m.world, [&] { m.world.create_shape(m.box, raw(g)); }, "capsule.radius", "DCX_range");
}

// Oracle: the all-or-none statement of World::create_chain: a chain whose middle definition
// is bad, or that holds a shape other than a chain segment, attaches nothing (the world's
// state hash is unchanged); a valid one attaches every segment, in order.
BOOST_AUTO_TEST_CASE(create_chain_is_all_or_none, *utf::label("R4")) {
    MovingWorld m;
    const std::array<Vec2d, 4> pts = {Vec2d{3, 0}, Vec2d{1, 0}, Vec2d{-1, 0}, Vec2d{-3, 0}};
    std::vector<ShapeDef> defs = chain_shapes(pts, false);
    defs[1].material.restitution = 2.0;
    expect_rejected(
        m.world, [&] { m.world.create_chain(m.ground, defs); }, "restitution", "DCI_CR");
    defs[1] = circle_shape(1.0);
    expect_rejected(
        m.world, [&] { m.world.create_chain(m.ground, defs); }, "chain[1].type", "DCX_shape");
    const std::vector<ShapeId> made = m.world.create_chain(m.ground, chain_shapes(pts, false));
    BOOST_TEST(made.size() == 3u);
    const std::vector<ShapeId> all = m.world.shapes(m.ground);
    BOOST_TEST_REQUIRE(all.size() == 4u);
    for (std::size_t i = 0; i < 3; ++i)
        BOOST_TEST((all[i + 1] == made[i]));
}

BOOST_AUTO_TEST_SUITE_END()
