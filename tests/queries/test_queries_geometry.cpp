// The geometric answers of the World's queries on seeded random shapes, 10 000 cases per shape
// kind or pair of kinds: a ray's entry into one shape (DD33, World::ray_cast(ShapeId, ...)), the
// distance and closest points of two shapes (DD34, World::distance) and of a shape and a point
// (DD34, World::closest_point). Oracle: query_oracle.hpp's independent geometry (signed
// distances from their definitions, the vertex-edge closed form of the distance between convex
// cores, Cramer's rule for a line crossing a segment), with the entry of a ray found by
// golden-section search and bisection on the signed distance along it, which is convex for a
// convex shape.
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

BodyDef fixed() {
    BodyDef d;
    d.type = BodyType::static_body;
    return d;
}

/// A world with one static body whose shape each case replaces.
struct OneShape {
    World world;
    BodyId body = world.create_body(fixed());
    ShapeId shape;
    Core core;

    void set(const Geometry& g, Vec2d origin, double angle) {
        if (world.is_valid(shape))
            world.destroy_shape(shape);
        world.set_transform(body, origin, angle);
        ShapeDef def;
        def.geometry = g;
        shape = world.create_shape(body, def);
        core = core_of(g, origin, angle);
    }
};

Vec2d random_point(std::mt19937_64& rng, double half) {
    std::uniform_real_distribution<double> u(-half, half);
    return {u(rng), u(rng)};
}

} // namespace

// Oracle: query_oracle.hpp, an independent implementation. The signed distance along the ray
// (solid shapes): no hit when the origin is inside,
// a miss when its minimum (golden-section search) is positive, else the entry is its first root
// (bisection). Segments and chain edges: Cramer's rule for the crossing, a chain edge hit from
// its right side only.
BOOST_AUTO_TEST_CASE(ray_entry_matches_the_signed_distance_oracle, *utf::label("DD33")) {
    std::mt19937_64 rng(3301);
    for (const Kind kind : all_kinds) {
        BOOST_TEST_CONTEXT("kind " << name(kind)) {
            OneShape w;
            int hits = 0, inside = 0, behind = 0, compared = 0;
            for (int c = 0; c < cases; ++c) {
                const Vec2d at = random_point(rng, 2.0);
                w.set(random_geometry(kind, rng), at,
                      std::uniform_real_distribution<double>(0, 6.3)(rng));
                const bool start_inside =
                    c % 10 == 0 && kind != Kind::segment && kind != Kind::chain;
                const Vec2d o = start_inside ? at + random_point(rng, 0.3) : random_point(rng, 6.0);
                const Vec2d aim = at + random_point(rng, 0.7);
                const double stretch = std::uniform_real_distribution<double>(0.6, 2.0)(rng);
                const Vec2d d = scaled(stretch, aim - o);
                const auto hit = w.world.ray_cast(w.shape, o, d);
                const double scale = 10.0 + norm(d);
                const double eps = 1e-9 * scale;
                BOOST_TEST_CONTEXT("case " << c) {
                    if (hit) {
                        BOOST_TEST((hit->shape == w.shape));
                        BOOST_TEST(hit->fraction >= 0.0);
                        BOOST_TEST(hit->fraction <= 1.0);
                        BOOST_TEST(norm(hit->point - (o + scaled(hit->fraction, d))) <= eps);
                        BOOST_TEST(std::abs(norm(hit->normal) - 1.0) <= 1e-12);
                        BOOST_TEST(dot(hit->normal, d) <= 0.0); // it faces the ray
                    }
                    if (!w.core.solid()) {
                        const Vec2d a = w.core.v[0], e = w.core.v[1] - w.core.v[0];
                        const double den = cross(d, e);
                        if (std::abs(den) <= 1e-9 * norm(d) * norm(e))
                            continue; // (nearly) parallel
                        const double t = cross(a - o, e) / den, u = cross(a - o, d) / den;
                        const auto near = [](double x) {
                            return std::abs(x) < 1e-9 || std::abs(x - 1.0) < 1e-9;
                        };
                        if (near(t) || near(u))
                            continue; // grazing an end
                        const bool crosses = t > 0 && t < 1 && u > 0 && u < 1;
                        const bool from_front = cross(e, o - a) < 0.0; // right of point1 -> point2
                        const bool expect = crosses && (kind == Kind::segment || from_front);
                        behind += crosses && !from_front;
                        BOOST_TEST(hit.has_value() == expect);
                        if (hit && expect) {
                            BOOST_TEST(std::abs(hit->fraction - t) <= 1e-9);
                            BOOST_TEST(std::abs(dot(hit->normal, e)) <= 1e-9 * norm(e));
                        }
                        hits += expect;
                        ++compared;
                        continue;
                    }
                    const auto f = [&](double s) {
                        return signed_distance(w.core, o + scaled(s, d));
                    };
                    const double f0 = f(0.0);
                    if (std::abs(f0) <= eps)
                        continue; // starts on the boundary
                    if (f0 < 0.0) {
                        ++inside;
                        ++compared;
                        BOOST_TEST(!hit); // the rule for a ray that starts inside
                        continue;
                    }
                    const auto [tm, fm] = convex_min(f, 0.0, 1.0);
                    if (fm > eps) {
                        BOOST_TEST(!hit);
                        ++compared;
                    } else if (fm < -1e-6) {
                        const double t = first_root(f, 0.0, tm);
                        BOOST_TEST_REQUIRE(hit.has_value());
                        BOOST_TEST(std::abs(hit->fraction - t) * norm(d) <= eps);
                        // The normal is outward: moving off the point along it by h gains h.
                        const double h = 1e-5;
                        BOOST_TEST(std::abs(f(hit->fraction)) <= eps);
                        BOOST_TEST(
                            std::abs(signed_distance(w.core, hit->point + scaled(h, hit->normal)) -
                                     h) <= 1e-3 * h);
                        ++hits;
                        ++compared;
                    } else if (hit) { // grazing: either answer, but a hit lies on the boundary
                        BOOST_TEST(std::abs(f(hit->fraction)) <= 1e-6);
                    }
                }
            }
            BOOST_TEST_MESSAGE(name(kind)
                               << ": " << compared << " compared, " << hits << " hits, " << inside
                               << " from inside, " << behind << " from behind");
            BOOST_TEST(compared >= cases * 9 / 10);
            BOOST_TEST(hits >= cases / 10);
            if (kind == Kind::chain)
                BOOST_TEST(behind >= cases / 20);
            if (w.core.r > 0.0 || kind == Kind::polygon)
                BOOST_TEST(inside >= cases / 20);
        }
    }
}

// Oracle: query_oracle.hpp, an independent implementation: its gap, the least vertex-edge distance
// between the cores (0 when they share a point) less both radii; the closest points must lie on the
// shapes' boundaries (signed distance 0) and be the distance apart.
BOOST_AUTO_TEST_CASE(shape_distance_matches_the_vertex_edge_oracle, *utf::label("DD34")) {
    std::mt19937_64 rng(3401);
    for (std::size_t i = 0; i < std::size(all_kinds); ++i) {
        for (std::size_t j = i; j < std::size(all_kinds); ++j) {
            const Kind ka = all_kinds[i], kb = all_kinds[j];
            BOOST_TEST_CONTEXT("pair " << name(ka) << "-" << name(kb)) {
                World w;
                const BodyId ba = w.create_body(fixed());
                const BodyId bb = w.create_body(fixed());
                int apart = 0, overlapping = 0;
                for (int c = 0; c < cases; ++c) {
                    const Geometry ga = random_geometry(ka, rng), gb = random_geometry(kb, rng);
                    const Vec2d pa = random_point(rng, 1.5), pb = random_point(rng, 1.5);
                    const double aa = std::uniform_real_distribution<double>(0, 6.3)(rng);
                    const double ab = std::uniform_real_distribution<double>(0, 6.3)(rng);
                    w.set_transform(ba, pa, aa);
                    w.set_transform(bb, pb, ab);
                    ShapeDef da, db;
                    da.geometry = ga;
                    db.geometry = gb;
                    const ShapeId sa = w.create_shape(ba, da), sb = w.create_shape(bb, db);
                    const Core ca = core_of(ga, pa, aa), cb = core_of(gb, pb, ab);
                    const ClosestPoints r = w.distance(sa, sb);
                    const double g = gap(ca, cb);
                    const double eps = 1e-9 * 10.0;
                    BOOST_TEST_CONTEXT("case " << c << " oracle gap " << g) {
                        if (g > eps) {
                            ++apart;
                            BOOST_TEST_REQUIRE(!r.overlapping);
                            BOOST_TEST(std::abs(r.distance - g) <= eps);
                            BOOST_TEST(std::abs(norm(r.point_b - r.point_a) - r.distance) <= eps);
                            BOOST_TEST(std::abs(signed_distance(ca, r.point_a)) <= eps);
                            BOOST_TEST(std::abs(signed_distance(cb, r.point_b)) <= eps);
                            if (r.distance > 1e-6)
                                BOOST_TEST(norm(r.normal - scaled(1.0 / r.distance,
                                                                  r.point_b - r.point_a)) <= 1e-6);
                        } else if (g < -eps) {
                            ++overlapping;
                            BOOST_TEST(r.overlapping);
                            BOOST_TEST(r.distance == 0.0);
                        } else { // they share a point, or touch, within rounding
                            ++overlapping;
                            BOOST_TEST(r.distance <= 2.0 * eps);
                        }
                    }
                    w.destroy_shape(sa);
                    w.destroy_shape(sb);
                }
                BOOST_TEST_MESSAGE(name(ka) << "-" << name(kb) << ": " << apart << " apart, "
                                            << overlapping << " sharing a point");
                BOOST_TEST(apart >= cases / 10);
                BOOST_TEST(overlapping >= cases / 20);
            }
        }
    }
}

// Oracle: query_oracle.hpp, an independent implementation: the signed distance from the point
// (its positive part is the distance; the closest
// point lies on the boundary, that far from the point).
BOOST_AUTO_TEST_CASE(closest_point_matches_the_signed_distance_oracle, *utf::label("DD34")) {
    std::mt19937_64 rng(3402);
    for (const Kind kind : all_kinds) {
        BOOST_TEST_CONTEXT("kind " << name(kind)) {
            OneShape w;
            int inside = 0;
            for (int c = 0; c < cases; ++c) {
                const Vec2d at = random_point(rng, 1.0);
                w.set(random_geometry(kind, rng), at,
                      std::uniform_real_distribution<double>(0, 6.3)(rng));
                const Vec2d p = at + random_point(rng, 2.5);
                const ClosestPoints r = w.world.closest_point(w.shape, p);
                const double g = signed_distance(w.core, p);
                const double eps = 1e-9 * 10.0;
                BOOST_TEST_CONTEXT("case " << c << " oracle " << g) {
                    BOOST_TEST((r.point_b == p));
                    if (g > eps) {
                        BOOST_TEST_REQUIRE(!r.overlapping);
                        BOOST_TEST(std::abs(r.distance - g) <= eps);
                        BOOST_TEST(std::abs(norm(r.point_a - p) - g) <= eps);
                        BOOST_TEST(std::abs(signed_distance(w.core, r.point_a)) <= eps);
                    } else if (g < -eps) {
                        ++inside;
                        BOOST_TEST(r.overlapping);
                    }
                }
            }
            if (w.core.solid())
                BOOST_TEST(inside >= cases / 100);
        }
    }
}
