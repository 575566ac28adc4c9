#include "tamias2d/dynamics/continuous.hpp"

#include <algorithm>
#include <cmath>

#include "tamias2d/collision/time_of_impact.hpp"
#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/bridge/continuous_motion.hpp"
#include "tamias2d/dynamics/contacts/contact_manager.hpp"
#include "tamias2d/dynamics/joints/joint_store.hpp"
#include "tamias2d/dynamics/shape_store.hpp"

namespace tamias2d {

namespace {

/// A collider's least distance from its centre to its boundary, m.
double inner_extent(const Collider& k) {
    if (k.type == ShapeType::circle || k.is_segment_kind())
        return k.radius; // a segment's (no area) is 0: its core is its midpoint
    double least = INFINITY;
    for (int i = 0; i < k.count; ++i)
        least = std::min(least, dot(k.normal(i), k.vertex(i) - k.center));
    return least;
}

/// The shape's core: the disc about its centroid of a quarter of its inner extent. A body whose
/// cores stay clear of a static shape all step kept its centroids on their side of it, and
/// its overlap at the end (if any) is shallow enough for the contact to push it back out.
Collider core_of(const Collider& k) {
    Collider core{};
    core.type = ShapeType::circle;
    core.center = k.center;
    core.radius = 0.25 * inner_extent(k);
    return core;
}

} // namespace

void ContinuousPass::run(BodyStore& store, ShapeStore& shape_store, const ContactManager& contacts,
                         const JointStore& joints, const WorldDef& def) {
    if (fast_.empty())
        return;
    // Bullets last, against the other bodies' final poses (their own sweeps done): the
    // moves so far go to the broad phase first, so its dynamic tree holds those poses.
    bool bullets = false;
    for (const FastBody& f : fast_) {
        if (store.settings[f.body].bullet)
            bullets = true;
        else
            sweep(f, false, store, shape_store, contacts, joints, def);
    }
    if (bullets) {
        shape_store.apply_moves();
        for (const FastBody& f : fast_)
            if (store.settings[f.body].bullet)
                sweep(f, true, store, shape_store, contacts, joints, def);
    }
    shape_store.apply_moves();
}

void ContinuousPass::sweep(const FastBody& f, bool bullet, BodyStore& store,
                           ShapeStore& shape_store, const ContactManager& contacts,
                           const JointStore& joints, const WorldDef& def) {
    auto& shapes = shape_store.shapes;
    const BroadPhase& broad = shape_store.broad_phase;
    // Stop a little short of touching, well inside the speculative distance, so that the next
    // step's narrow phase gives the pair a speculative point and the solver stops the body.
    const double target = std::max(def.linear_slop, 0.25 * def.speculative_distance);
    const double tolerance = 0.25 * target;
    Body& b = store.bodies[f.body];
    const Sweep sweep{b.local_center, f.c0, b.center, f.a0, b.angle};
    double reach_max = 0.0;
    for (std::uint32_t s = b.first_shape; s != null_index; s = shapes[s].next)
        reach_max = std::max(reach_max, reach(shapes[s].collider, b.local_center));
    // Every point of the body stays within reach_max of its centre, which moves along
    // the segment c0-c1.
    const double grow = reach_max + target + tolerance;
    const Aabb swept{
        std::min(sweep.c0.x, sweep.c1.x) - grow, std::min(sweep.c0.y, sweep.c1.y) - grow,
        std::max(sweep.c0.x, sweep.c1.x) + grow, std::max(sweep.c0.y, sweep.c1.y) + grow};
    nearby_.clear();
    const auto collect = [&](const DynamicTree& tree) {
        tree.query(swept, [&](int node) {
            nearby_.push_back(tree.user_data(node));
            return true;
        });
    };
    collect(broad.static_tree());
    if (bullet) {
        // Other dynamic bodies that are not bullets (two bullets meet at the step's poses).
        const std::size_t statics = nearby_.size();
        collect(broad.dynamic_tree());
        nearby_.erase(std::remove_if(nearby_.begin() + std::ptrdiff_t(statics), nearby_.end(),
                                     [&](std::uint32_t o) {
                                         const Body& other = store.bodies[shapes[o].body];
                                         return shapes[o].body == f.body ||
                                                other.type != BodyType::dynamic ||
                                                store.settings[shapes[o].body].bullet;
                                     }),
                      nearby_.end());
    }
    if (nearby_.empty())
        return;
    // Shape order, so that equal times of impact resolve the same way whatever the tree.
    std::sort(nearby_.begin(), nearby_.end());
    double t = 1.0;
    for (std::uint32_t s = b.first_shape; s != null_index; s = shapes[s].next) {
        if (shape_store.defs[s].is_sensor)
            continue;
        const Collider& shape = shapes[s].collider;
        const Collider core = core_of(shape);
        for (const std::uint32_t o : nearby_) {
            if (!contacts.should_collide(store, shape_store, joints, s, o))
                continue;
            const Shape& other = shapes[o];
            if (other.collider.type == ShapeType::chain_segment) {
                // One-sided (DD31): a body that starts behind a chain edge passes through it.
                const Collider& e = other.collider;
                const Vec2d start = transform_point(sweep.at(0.0), core.center);
                if (dot(rotate(other.body_xf.q, e.normal(0)),
                        start - transform_point(other.body_xf, e.vertex(0))) < 0.0)
                    continue;
            }
            // A core never enters a shape it starts outside of: one that starts within the
            // target may close half its gap (so a body that its contact turns about a corner
            // cannot swing its centroid through a thin shape).
            const double gap =
                shape_distance(core, sweep.at(0.0), other.collider, other.body_xf).distance;
            if (gap <= 0.0)
                continue; // already deep inside: the contact's alone
            const double core_target = std::min(target, 0.5 * gap);
            const ToiResult c = time_of_impact(core, sweep, other.collider, other.body_xf,
                                               core_target, 0.25 * core_target, t);
            if (c.state != ToiState::hit)
                continue; // the core stays clear
            // Stopped before touching if it started apart; else as its core touches.
            const ToiResult r =
                time_of_impact(shape, sweep, other.collider, other.body_xf, target, tolerance, c.t);
            const bool whole = r.state == ToiState::hit;
            const double hit = whole ? r.t : c.t;
            if (contacts.pre_solve && ContactManager::asks_pre_solve(shape_store, s, o)) {
                // The game's pre-solve rule decides, as for the pair's contact (a one-way
                // platform lets a fast body through): asked where the stop would put it.
                const ShapeDistance d = shape_distance(whole ? shape : core, sweep.at(hit),
                                                       other.collider, other.body_xf);
                if (!contacts.admits_impact(store, shape_store, s, o, d.normal,
                                            0.5 * (d.point_a + d.point_b), d.distance))
                    continue;
            }
            t = hit;
        }
    }
    if (t >= 1.0)
        return;
    // DD29: position, angle and velocities interpolated to the time of impact.
    b.center = bridge::center_at(f.c0, sweep.c1, t);
    b.angle = bridge::angle_at(f.a0, sweep.a1, t);
    b.v = bridge::velocity_at(f.v0, b.v, t);
    b.w = bridge::angular_velocity_at(f.w0, b.w, t);
    b.xf.q = Rot::from_angle(b.angle);
    b.xf.p = b.center - rotate(b.xf.q, b.local_center);
    for (std::uint32_t s = b.first_shape; s != null_index; s = shapes[s].next)
        shape_store.follow_body(shapes[s], b);
}

} // namespace tamias2d
