// The open findings F1-F3 (docs/verification.md, "Fuzzing"): non-finite states after accepted
// steps, all with joints. Until the library refuses such input or its joints hold, a fuzz input
// that reaches one of them ends at its first non-finite state instead of failing. One predicate
// per finding, the same thresholds as the seeded API driver (tests/fuzz/test_fuzz_api.cpp):
// delete a predicate, and its call in the targets, once its finding is fixed.
#pragma once

#include <cmath>
#include <vector>

#include "tamias2d/world.hpp"

namespace tamias2d::fuzz::known {

/// A joint as the targets record it at creation: its bodies and anchors (world frame).
struct JointRecord {
    BodyId a, b;
    std::vector<Vec2d> anchors;
};

/// Every joint made so far (destroyed ones kept: the finding is judged conservatively), and
/// whether one was far when made or when its anchor was set (anchors, rest length or bodies
/// 1e5 m apart).
struct Joints {
    std::vector<JointRecord> made;
    bool far_at_creation = false;
};

inline constexpr double far_lever = 1e5; // m

inline bool far_from_body(const World& w, BodyId b, Vec2d p) {
    if (!w.is_valid(b))
        return false;
    const Vec2d c = w.position(b);
    return std::hypot(p.x - c.x, p.y - c.y) >= far_lever;
}

/// Finding F1, far joint anchor: an anchor 1e5 m or more (within the supported 1e12 m) from
/// one of its bodies' centres of mass gives the body a NaN state at the next step. Judged
/// before the step (a failed step turns the positions it is judged by into NaN).
inline bool f1_far_joint_anchor(const World& w, const Joints& j) {
    if (j.far_at_creation)
        return true;
    for (const JointRecord& r : j.made)
        for (const Vec2d p : r.anchors)
            if (far_from_body(w, r.a, p) || far_from_body(w, r.b, p))
                return true;
    return false;
}

inline constexpr double tiny_gyration_squared = 1e-6; // m^2: sqrt(I / m) < 1 mm

/// Finding F2, tiny moment of inertia on a jointed body: a dynamic body whose radius of
/// gyration sqrt(I / m) is below 1 mm (an accepted inertia override, or made by its shapes)
/// makes the joint solver diverge to inf and NaN.
inline bool f2_tiny_inertia_on_jointed_body(const World& w, const Joints& j) {
    for (const JointRecord& r : j.made)
        for (const BodyId x : {r.a, r.b})
            if (w.is_valid(x) && w.mass(x) > 0.0 &&
                w.inertia(x) < tiny_gyration_squared * w.mass(x))
                return true;
    return false;
}

inline constexpr double huge_gravity = 1e6; // m s^-2
inline constexpr double huge_fall = 1e2;    // m, |g| dt^2

/// Finding F3, huge load per step on a joint: under gravity of 1e6 m s^-2 and more (supported
/// up to 1e12) or a step with |g| dt^2 >= 100 m a joint does not hold and can turn NaN.
inline bool f3_huge_load_on_joint(const World& w, const Joints& j, double dt) {
    const Vec2d g = w.gravity();
    const double a = std::hypot(g.x, g.y);
    return !j.made.empty() && (a >= huge_gravity || a * dt * dt >= huge_fall);
}

/// Which finding, if any, excuses a non-finite state after a step of `dt` (judged before it).
inline const char* excusing_finding(const World& w, const Joints& j, double dt) {
    if (f1_far_joint_anchor(w, j))
        return "F1";
    if (f2_tiny_inertia_on_jointed_body(w, j))
        return "F2";
    if (f3_huge_load_on_joint(w, j, dt))
        return "F3";
    return nullptr;
}

} // namespace tamias2d::fuzz::known
