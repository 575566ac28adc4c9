// Closest points between two line segments. The polygon narrow phase uses it to tell a
// vertex-vertex approach (one speculative point along the vertex gap) from an edge region.
#pragma once

#include <algorithm>

#include "tamias2d/math/vec2d.hpp"

namespace tamias2d {

struct SegmentDistance {
    Vec2d closest1{};              ///< on segment 1
    Vec2d closest2{};              ///< on segment 2
    double fraction1 = 0.0;        ///< closest1 = p1 + fraction1 (q1 - p1), exactly 0 or 1 at ends
    double fraction2 = 0.0;        ///< likewise on segment 2
    double distance_squared = 0.0; ///< m^2
};

/// Closest points of segments p1-q1 and p2-q2 (either may be a point). Clamped fractions are
/// exactly 0 or 1, so callers can test for vertex regions with ==.
inline SegmentDistance segment_distance(Vec2d p1, Vec2d q1, Vec2d p2, Vec2d q2) {
    const Vec2d d1 = q1 - p1;
    const Vec2d d2 = q2 - p2;
    const Vec2d r = p1 - p2;
    const double a = dot(d1, d1);
    const double e = dot(d2, d2);
    const double f = dot(d2, r);
    double s = 0.0;
    double t = 0.0;
    if (a <= 0.0 && e <= 0.0) {
        // both points
    } else if (a <= 0.0) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = dot(d1, r);
        if (e <= 0.0) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = dot(d1, d2);
            const double denom = a * e - b * b;
            // Parallel segments: any s works; 0 is a deterministic choice.
            s = denom > 1e-14 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1.0) {
                t = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    SegmentDistance out;
    out.fraction1 = s;
    out.fraction2 = t;
    out.closest1 = s == 0.0 ? p1 : s == 1.0 ? q1 : p1 + s * d1;
    out.closest2 = t == 0.0 ? p2 : t == 1.0 ? q2 : p2 + t * d2;
    const Vec2d g = out.closest2 - out.closest1;
    out.distance_squared = dot(g, g);
    return out;
}

} // namespace tamias2d
