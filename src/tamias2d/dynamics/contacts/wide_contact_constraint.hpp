// Four contact manifolds that share no dynamic body, one per lane, laid out for the wide
// solver: the same fields as ContactConstraint (contact_iteration.hpp is written against both).
// A lane without a manifold, and the second point of a one-point manifold, are all zeros and
// name the static body 0, so solving them changes nothing.
#pragma once

#include <cstddef>
#include <cstdint>

#include "tamias2d/dynamics/contacts/contact_constraint.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/math/wide.hpp"

namespace tamias2d {

struct alignas(wide_alignment) WideContactConstraintPoint {
    Wide normal_arm_a{}, normal_arm_b{}; ///< r x n at each body's anchor (DD8)
    Wide tangent_arm_a{}, tangent_arm_b{};
    Wide base_separation{};
    Wide normal_mass{};
    Wide tangent_mass{};
    Wide normal_impulse{};
    Wide tangent_impulse{};
    Wide max_normal_impulse{};
    Wide total_normal_impulse{};
    Wide total_tangent_impulse{};
};

struct alignas(wide_alignment) WideContactConstraint {
    std::uint32_t body_a[wide_lanes]{}, body_b[wide_lanes]{}; ///< solver body indices
    Vec2<Wide> normal{};
    Wide friction{};
    Wide k11{}, k12{}, k22{};
    Wide inv_k11{}, inv_k12{}, inv_k22{};
    WideMask use_block{};
    WideContactConstraintPoint points[2]{};
    // Where the results go (read once per step, by WideContactSolver::store).
    std::uint32_t contact[wide_lanes]{};          ///< the persistent contact of each lane
    std::uint32_t restitution_slot[wide_lanes]{}; ///< the restitution pass's copy, if it can bounce
    std::uint8_t count[wide_lanes]{};             ///< its points (0: empty lane)
};

/// The surface motion of four manifolds, one per lane, in an array of its own beside the packs
/// (WideContactSolver::set_surface_lane): only steps with surface motion fill and solve it.
struct alignas(wide_alignment) WideSurfaceMotion : SurfaceMotionOver<Wide> {};

/// What preparation needs of four manifolds, one per lane: filled lane by lane from the contacts,
/// then prepared into a pack four lanes at a time (WideContactSolver::prepare_pack). A point past
/// a lane's count, and an empty lane, are zeros (set_input_lane and clear_input_lane write every
/// field of a lane, so one input serves pack after pack).
struct alignas(wide_alignment) WideManifoldInput {
    Vec2<Wide> normal{};
    Wide friction{};
    Vec2<Wide> r_a[2]{}, r_b[2]{};                  ///< m, anchors relative to the centres of mass
    Wide separation[2]{};                           ///< m
    Wide normal_impulse[2]{}, tangent_impulse[2]{}; ///< N s, warm start
    std::uint32_t body_a[wide_lanes]{}, body_b[wide_lanes]{};
    std::uint32_t contact[wide_lanes]{};
    std::uint32_t restitution_slot[wide_lanes]{};
    std::uint8_t count[wide_lanes]{}; ///< 0: empty lane
};

/// The bodies of four lanes (gathered from SolverBody by transposing its rows, written back
/// after the solve).
struct alignas(wide_alignment) WideBody {
    Vec2<Wide> v{};
    Wide w{};
    Wide inv_m{};
    Wide inv_I{};
    Vec2<Wide> dp{};
    Wide dq{};
};

// Every pack member starts on a 32-byte boundary (the structures are built of whole packs).
static_assert(sizeof(WideContactConstraintPoint) % wide_alignment == 0);
static_assert(offsetof(WideContactConstraint, normal) % wide_alignment == 0);
static_assert(offsetof(WideContactConstraint, points) % wide_alignment == 0);

} // namespace tamias2d
