// World::shape_cast on seeded random shapes, 10 000 cases per pair of kinds (the cast shape: a
// circle, a polygon, a capsule or a segment; the world's: those or a chain edge). Oracle:
// query_oracle.hpp's gap between the cores less the radii (the vertex-edge closed form), which,
// for a convex shape translated past another, is a convex function of the fraction: its minimum
// (golden-section search) says whether they ever touch, and its first root where.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

#include "queries/query_oracle.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace query_oracle;

namespace {

constexpr int cases = 10000;

Vec2d random_point(std::mt19937_64& rng, double half) {
    std::uniform_real_distribution<double> u(-half, half);
    return {u(rng), u(rng)};
}

} // namespace

// Oracle: the property of DD29's conservative advancement as a query, judged by the gaps of
// query_oracle.hpp (an independent implementation of the gaps between shapes): the pose at the
// fraction found touches the shape hit (a gap in [0, cast_tolerance], never an overlap), no
// contact comes before it (the gap is positive and falling there, or its minimum before it is
// positive), and a cast reported clear never touches. A cast starting behind a chain edge passes it
// (DD31).
BOOST_AUTO_TEST_CASE(shape_cast_stops_touching_never_overlapping,
                     *utf::label("DD29") * utf::label("DD34")) {
    std::mt19937_64 rng(2901);
    const Kind cast_kinds[] = {Kind::circle, Kind::polygon, Kind::capsule, Kind::segment};
    for (const Kind kc : cast_kinds) {
        for (const Kind kw : all_kinds) {
            BOOST_TEST_CONTEXT("cast " << name(kc) << " at " << name(kw)) {
                World w;
                BodyDef fixed;
                fixed.type = BodyType::static_body;
                const BodyId body = w.create_body(fixed);
                int hits = 0, clear = 0, at_start = 0, behind = 0;
                double worst_gap = 0.0;
                for (int c = 0; c < cases; ++c) {
                    const Vec2d at = random_point(rng, 1.0);
                    const double angle = std::uniform_real_distribution<double>(0, 6.3)(rng);
                    const Geometry gw = random_geometry(kw, rng);
                    w.set_transform(body, at, angle);
                    ShapeDef def;
                    def.geometry = gw;
                    const ShapeId target = w.create_shape(body, def);
                    const Core cw = core_of(gw, at, angle);

                    const Geometry gc = random_geometry(kc, rng);
                    const Vec2d o = random_point(rng, 5.0);
                    const double turn = std::uniform_real_distribution<double>(0, 6.3)(rng);
                    const Vec2d aim = at + random_point(rng, 1.0);
                    const Vec2d d =
                        scaled(std::uniform_real_distribution<double>(0.5, 2.0)(rng), aim - o);
                    const Core cc = core_of(gc, o, turn);
                    const double tau = World::cast_tolerance(gc, d);
                    const auto g = [&](double t) { return gap(moved(cc, scaled(t, d)), cw); };
                    const auto hit = w.shape_cast(gc, o, turn, d);
                    const double eps = 1e-9 * (10.0 + norm(d));

                    BOOST_TEST_CONTEXT("case " << c) {
                        bool passes_behind = false;
                        if (kw == Kind::chain) {
                            const Vec2d a = cw.v[0], e = cw.v[1] - cw.v[0];
                            // The cast shape's centre: a polygon's area centroid, a circle's
                            // centre, a capsule's or segment's midpoint.
                            const Vec2d mean = centroid(cc);
                            const double side = cross(e, mean - a);
                            if (std::abs(side) <= 1e-9 * norm(e))
                                continue;
                            passes_behind = side > 0.0; // left of point1 -> point2: behind
                        }
                        if (passes_behind) {
                            ++behind;
                            BOOST_TEST(!hit);
                        } else if (hit) {
                            BOOST_TEST((hit->shape == target));
                            BOOST_TEST(hit->fraction >= 0.0);
                            BOOST_TEST(hit->fraction <= 1.0);
                            const double gt = g(hit->fraction);
                            if (hit->fraction == 0.0 && gt <= tau + eps) {
                                ++at_start; // overlapping or touching at the start
                            } else {
                                ++hits;
                                worst_gap = std::max(worst_gap, gt / tau);
                                BOOST_TEST(gt >= -eps);      // never overlapping
                                BOOST_TEST(gt <= tau + eps); // touching
                                // No earlier contact: falling at the fraction (convex: falling
                                // all the way to it), or a positive minimum before it.
                                const double h = 1e-7 * hit->fraction;
                                if (!(g(hit->fraction - h) > gt))
                                    BOOST_TEST(convex_min(g, 0.0, hit->fraction).second >= -eps);
                                // The point lies on the shape hit, the normal faces the cast.
                                BOOST_TEST(std::abs(signed_distance(cw, hit->point)) <= eps);
                                BOOST_TEST(std::abs(norm(hit->normal) - 1.0) <= 1e-9);
                                BOOST_TEST(dot(hit->normal, d) <= 1e-9 * norm(d));
                            }
                        } else {
                            ++clear;
                            BOOST_TEST(convex_min(g, 0.0, 1.0).second >= -eps);
                        }
                    }
                    w.destroy_shape(target);
                }
                BOOST_TEST_MESSAGE("cast " << name(kc) << " at " << name(kw) << ": " << hits
                                           << " hits (largest gap " << worst_gap << " tolerances), "
                                           << at_start << " at the start, " << clear << " clear, "
                                           << behind << " behind");
                BOOST_TEST(hits >= cases / 5);
                BOOST_TEST(clear >= cases / 50);
                if (kw == Kind::chain)
                    BOOST_TEST(behind >= cases / 20);
            }
        }
    }
}
