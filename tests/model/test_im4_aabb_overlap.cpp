// IM4 (collision detection of axis-aligned bounding boxes), checked by hand, against brute-force
// point sampling of the two boxes (T5's definition: some point lies in both) and against the
// SRS's own inequalities.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cstdint>

#include "tamias2d/model/im4_aabb_overlap.hpp"
#include "tamias2d/units/quantities.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d::units;
namespace im4 = tamias2d::model::im4;
using Box = im4::Aabb<double>;

namespace {
// Deterministic pseudo-random integers (64-bit LCG, Knuth's MMIX constants).
struct Lcg {
    std::uint64_t s;
    int below(int n) {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<int>((s >> 33) % static_cast<std::uint64_t>(n));
    }
};
// A random box with corners on the 1/4 grid in [-4, 4] and positive width and height.
Box random_box(Lcg& g) {
    const int x0 = g.below(32) - 16, y0 = g.below(32) - 16;
    const int w = 1 + g.below(std::min(16, 16 - x0)), h = 1 + g.below(std::min(16, 16 - y0));
    return {x0 / 4.0, y0 / 4.0, (x0 + w) / 4.0, (y0 + h) / 4.0};
}
bool strictly_inside(const Box& b, double x, double y) {
    return b.min_x < x && x < b.max_x && b.min_y < y && y < b.max_y;
}
} // namespace

BOOST_AUTO_TEST_SUITE(im4_aabb_overlap)

// Oracle: hand derivation for a = [0, 2]^2: b = [1, 3]^2 overlaps it; b = [2, 4] x [0, 2]
// only touches (shared edge, strict inequalities as in the SRS: no overlap); b = [3, 4] x
// [0, 2] is apart along x; [0.5, 1]^2 lies inside a; [0, 2] x [2.5, 3] is apart along y only.
BOOST_AUTO_TEST_CASE(hand_cases, *utf::label("IM4")) {
    const Box a{0, 0, 2, 2};
    BOOST_TEST(im4::overlaps(a, Box{1, 1, 3, 3}));
    BOOST_TEST(!im4::overlaps(a, Box{2, 0, 4, 2}));
    BOOST_TEST(!im4::overlaps(a, Box{3, 0, 4, 2}));
    BOOST_TEST(im4::overlaps(a, Box{0.5, 0.5, 1, 1}));
    BOOST_TEST(!im4::overlaps(a, Box{0, 2.5, 2, 3}));
    BOOST_TEST(im4::overlaps(a, a));
}

// Oracle: hand derivation of the centre-based reading of the SRS inputs: centre (1, 2), width
// 4, height 2 spans x in [-1, 3] and y in [1, 3]; the same with Boost.Units lengths.
BOOST_AUTO_TEST_CASE(from_centre_hand_value, *utf::label("IM4")) {
    const Box b = im4::from_centre(1.0, 2.0, 4.0, 2.0);
    BOOST_TEST(b.min_x == -1.0);
    BOOST_TEST(b.min_y == 1.0);
    BOOST_TEST(b.max_x == 3.0);
    BOOST_TEST(b.max_y == 3.0);
    const im4::Aabb<Length> q =
        im4::from_centre(1.0 * metre, 2.0 * metre, 4.0 * metre, 2.0 * metre);
    BOOST_TEST(q.min_x.value() == -1.0);
    BOOST_TEST(q.max_y.value() == 3.0);
}

// Oracle: brute-force point sampling (T5's definition). Boxes with corners on the 1/4 grid
// overlap (with positive area) exactly when some point (odd multiple of 1/16 in both
// coordinates) lies strictly inside both: any open overlap is at least 1/4 wide and contains
// lo + 1/16; touching or disjoint boxes contain no common interior point. 400 random pairs,
// 16384 sample points each; all values exact in binary. The Length-typed template must agree.
BOOST_AUTO_TEST_CASE(matches_point_sampling, *utf::label("IM4") * utf::label("T5")) {
    Lcg g{2024};
    int overlapping = 0;
    for (int pair = 0; pair < 400; ++pair) {
        const Box a = random_box(g), b = random_box(g);
        bool sampled = false;
        for (int i = -64; i < 64 && !sampled; ++i)
            for (int k = -64; k < 64 && !sampled; ++k) {
                const double x = (2 * i + 1) / 16.0, y = (2 * k + 1) / 16.0;
                sampled = strictly_inside(a, x, y) && strictly_inside(b, x, y);
            }
        BOOST_TEST(im4::overlaps(a, b) == sampled, "pair " << pair);
        BOOST_TEST(im4::overlaps(b, a) == sampled, "pair " << pair << " (swapped)");
        const im4::Aabb<Length> la{a.min_x * metre, a.min_y * metre, a.max_x * metre,
                                   a.max_y * metre};
        const im4::Aabb<Length> lb{b.min_x * metre, b.min_y * metre, b.max_x * metre,
                                   b.max_y * metre};
        BOOST_TEST(im4::overlaps(la, lb) == sampled);
        overlapping += sampled ? 1 : 0;
    }
    // Both outcomes must be exercised for the comparison to mean anything.
    BOOST_TEST(overlapping > 40);
    BOOST_TEST(overlapping < 360);
}

// Oracle: the SRS's IM4 inequalities, transcribed literally with (x, y) the lower-left corner:
// rect1.x1 < rect2.x2 + rect2.w2 and rect1.x1 + rect1.w1 > rect2.x2 and rect1.y1 < rect2.y2 +
// rect2.h2 and rect1.y1 + rect1.h1 > rect2.y2. With the corner at centre - size / 2 (IM4 says
// (x, y) is the centre of mass: erratum), they must agree with overlaps(from_centre(...)).
BOOST_AUTO_TEST_CASE(matches_srs_inequalities, *utf::label("IM4")) {
    Lcg g{77};
    for (int pair = 0; pair < 500; ++pair) {
        const double x1 = g.below(32) / 4.0, y1 = g.below(32) / 4.0, w1 = (1 + g.below(24)) / 4.0,
                     h1 = (1 + g.below(24)) / 4.0;
        const double x2 = g.below(32) / 4.0, y2 = g.below(32) / 4.0, w2 = (1 + g.below(24)) / 4.0,
                     h2 = (1 + g.below(24)) / 4.0;
        const double c1x = x1 - w1 / 2, c1y = y1 - h1 / 2, c2x = x2 - w2 / 2, c2y = y2 - h2 / 2;
        const bool srs = c1x < c2x + w2 && c1x + w1 > c2x && c1y < c2y + h2 && c1y + h1 > c2y;
        BOOST_TEST(im4::overlaps(im4::from_centre(x1, y1, w1, h1),
                                 im4::from_centre(x2, y2, w2, h2)) == srs,
                   "pair " << pair);
    }
}

BOOST_AUTO_TEST_SUITE_END()
